#pragma once
// What a scene file says about its frame rate, its unit and its up axis (FileSettings), for
// importScene. Assimp 5.2 gives FBX's global settings as scene metadata ("FrameRate",
// "CustomFrameRate", "UnitScaleFactor", "UpAxis", "UpAxisSign") and BVH's frame time as ticks per
// second; it applies Collada's <unit> and <up_axis> to the root node without reporting them, so those
// are read from the file's <asset> (and the reader's up-axis turn is switched off: Gyre turns every
// format the same way).
//
// - Frame rate: FBX's time mode (CustomFrameRate for a custom one); BVH's frame time; else the
//   lowest common rate (24, 25, 30, 48, 50, 60, 72, 96, 100, 120, 240, then the NTSC 23.976, 29.97,
//   59.94) on whose frames every key of the chosen animations falls, within 1/200 of a frame
//   (Blender's glTF and Collada keys are at frame/fps); else 24.
// - Unit, in metres: FBX's UnitScaleFactor / 100 (FBX counts in centimetres); Collada's <unit meter>;
//   glTF's metre; 1 for formats without units.
//   An FBX file written by Assimp (Gyre's own FBX export among them) states 1 cm and 24 fps whatever it
//   holds, so its unit is taken as the metre and its rate from its keys.
// - Up axis: FBX's UpAxis and UpAxisSign; Collada's <up_axis>; Y for glTF (by its specification) and
//   the rest. X-up and downward axes are not converted (a warning says so).

#include "io/scene_import.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

struct aiAnimation;
struct aiScene;

namespace gyre::io {

// Which of Assimp's readers read the file, as far as the settings care.
enum class SceneSource { Fbx, Collada, Gltf, Bvh, Other };

SceneSource sourceOf(const QString& path, const aiScene& scene);

// What the file says; `animations` are the chosen ones, whose keys give the frame rate where the file
// states none. Warnings go to `warnings`.
FileSettings fileSettingsOf(const QString& path, SceneSource source, const aiScene& scene,
                            const std::vector<const aiAnimation*>& animations, QStringList& warnings);

// The unit of a Collada file (<asset><unit meter="…">), which Assimp has scaled the root node by;
// nothing when the file does not say, or is not readable as XML up to its <asset>.
std::optional<double> colladaMetresPerUnit(const QString& path);

} // namespace gyre::io
