#pragma once
// A scene as the exporters write it (scene_export.h): each object with a name unique in the file, its
// parent resolved to an earlier object, its local pose at the start time, its mesh checked, and its
// motion baked (model::bakeTrack). Both writers, Assimp's and Gyre's FBX writer, start from it.
// Its objects are the scene's, in the scene's order.

#include "core/pose.h"
#include "model/scene.h"
#include "model/track_evaluation.h"

#include <QStringList>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace gyre::io {

struct BakedObject {
    std::string name;                      // UTF-8, unique within the file, not empty
    std::optional<std::size_t> parent;     // the index of an earlier object; none at the top level
    Pose startPose;                        // relative to the parent, at the scene's start time
    const model::Mesh* mesh = nullptr;     // null when the object has no triangles; indices checked
    std::vector<model::TimedPose> samples; // the baked motion; empty when the object does not move
    // The orientation as the Hermite spline the track plays, cut at the samples' times
    // (rotationSplineOf), for glTF's CUBICSPLINE; empty when the track plays no such spline.
    std::vector<HermiteControlPoint> rotationSpline;
};

struct BakedScene {
    std::vector<BakedObject> objects;
    model::BakeRange range; // the scene's start and end time and the frame rate of the bake
};

// The Hermite spline whose normalised curve is the track's orientation at every time, when there is one
// (a hermite track with two keys or more, without a fit: HermiteQuaternionSpline::throughKeys of its
// keys; or with a fit that spans exactly its keys: the fit's control points), cut at each of `times`
// inside its span: a control point at each such time with the raw cubic's value and derivative there
// (HermiteQuaternionSpline::raw). A cubic cut at any point is the same cubic, so the pieces make the
// same curve; and a reader that ignores the tangents (Blender 3.4's glTF importer) still has the exact
// orientation, normalised, at every one of `times`. Empty when the track plays no such spline.
// `times` increase and include the key times (the baked samples' times).
std::vector<HermiteControlPoint> rotationSplineOf(const model::MotionTrack& track, const std::vector<double>& times);

// Makes `baked`, the bake of `scene` (its objects in the scene's order), hold the times glTF asks of an
// animation sampler's input: float32 seconds, the first not below 0, strictly increasing.
// - A scene that starts before 0 s is moved later by its start, so that it starts at 0.
// - Two baked times a float32 step apart or less (keys 1e-9 s apart; frames at 30 fps near 1e6 s,
//   where the step is 1/16 s) round to the same float32, and Assimp's glTF reader, Gyre's own import,
//   turns float32 seconds into float32 milliseconds, which can join two seconds one step apart. Of each
//   run of an object's samples that read back as the same milliseconds, one is kept: the last at one of
//   the object's key times (the artist's pose), else the last of the run. Rounding is monotonic, so the
//   kept times strictly increase as float32 seconds and as Assimp's milliseconds.
// - The rotation spline's times move with the samples; a spline two of whose times read back as the
//   same milliseconds is dropped, and the object's rotation is written from its samples.
// Returns a warning for each of these that changed something.
QStringList prepareGltfTimes(BakedScene& baked, const model::Scene& scene);

} // namespace gyre::io
