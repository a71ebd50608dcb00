#pragma once
// Scenes with their motion to glTF 2.0 (.gltf with its .bin, or .glb) by TinyGLTF (gltf_scene_writer.h),
// to Collada (.dae) through Assimp's exporter, to binary FBX 7.4 (.fbx) by Gyre's own writer
// (fbx_scene_writer.h), and to OBJ (.obj with its .mtl, Assimp's) for the meshes alone.
//
// Each object becomes a node under one root, with its parent kept, its mesh and its local transform
// at the scene's start time; a skinned mesh keeps its skin (glTF's skins, FBX's Skin deformer, Collada's
// skin controller, which Assimp's writer makes from the aiMesh's bones). The motion is baked: every object's track is sampled at the frames
// start + k/fps up to the scene's end and at each of its key times (model::bakeTrack), so every
// interpolation and every fit plays the same after import, where each sample is a key. glTF writes a
// hermite track's rotation as the track's own spline instead, a CUBICSPLINE sampler (rotationSplineOf
// in baked_scene.h), which plays the same between the samples too.
//
// FBX is written by Gyre because Assimp 5.2's binary FBX writer makes files that its own reader
// rejects (assimp issue #4686), and Blender 3.4 reads binary FBX only; Debian has no other library
// that writes FBX. Its file keeps the project's frame rate and exact time span. OBJ keeps no motion:
// the meshes are written posed at the start time, and the report says so.

#include "core/name_table.h"
#include "model/input_error.h"
#include "model/scene.h"

#include <QString>
#include <QStringList>

#include <cstddef>
#include <optional>

namespace gyre::io {

enum class SceneFormat { Gltf, Glb, Collada, Fbx, Obj };

// The names are the file extensions.
inline constexpr NameTable<SceneFormat, 5> kSceneFormatNames{{
    {SceneFormat::Gltf, "gltf"},
    {SceneFormat::Glb, "glb"},
    {SceneFormat::Collada, "dae"},
    {SceneFormat::Fbx, "fbx"},
    {SceneFormat::Obj, "obj"},
}};

// The format a path's extension names, ignoring case; nullopt for any other extension.
std::optional<SceneFormat> sceneFormatOfPath(const QString& path);

bool keepsMotion(SceneFormat format);

// The most samples an export bakes, over all objects: 2²⁴.
inline constexpr std::size_t kMaxExportSamples = std::size_t{1} << 24;

struct ExportReport {
    QStringList files;    // every file written: the .gltf's .bin and the .obj's .mtl come first
    QStringList warnings; // what the file could not keep
};

// Writes the scene to `path` in `format`, its motion baked at `fps` over [startTime, endTime]. Assimp,
// TinyGLTF and the FBX writer write into memory; each file is then written whole through an OutputTarget: a
// regular file through a temporary file in its folder, renamed (QSaveFile), so on an error a file
// already at that path keeps its contents; a FIFO or a device in place. Throws OutputError, naming the
// file, when fps is not finite and positive, the range is empty or gives more than kMaxExportSamples
// samples, a track cannot be evaluated, Assimp or TinyGLTF fails, an FBX file would pass 4 GiB, or a
// file cannot be written.
ExportReport exportScene(const model::Scene& scene, const QString& path, SceneFormat format, double fps);

} // namespace gyre::io
