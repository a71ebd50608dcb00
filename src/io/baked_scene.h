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
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gyre::io {

// A key of a glTF CUBICSPLINE sampler: the cubic's value and its time derivative on either side, equal
// but at a corner: where a fit's window meets the track's own spline, and at the first and last key,
// outside which the pose is held.
template <class Value>
struct SplineKeyOf {
    double time = 0.0;
    Value value;
    Value inDerivative;
    Value outDerivative;
};
using SplineKey = SplineKeyOf<Eigen::Quaterniond>;      // a rotation's raw cubic
using PositionSplineKey = SplineKeyOf<Eigen::Vector3d>; // a translation

struct BakedObject {
    std::string name;                      // UTF-8, unique within the file, not empty
    std::optional<std::size_t> parent;     // the index of an earlier object; none at the top level
    Pose startPose;                        // relative to the parent, at the scene's start time
    const model::Mesh* mesh = nullptr;     // null when the object has no triangles; indices checked
    bool empty = false;                    // SceneObject::empty: a frame alone, written as the format's Empty
    // For a skinned mesh (model::Skin), the index among the objects of each of its skin's joints; empty for
    // a rigid mesh, or a skin one of whose joints is no object of the scene (the mesh goes out rigid).
    std::vector<std::size_t> skinJoints;
    std::vector<model::TimedPose> samples; // the baked motion; empty when the object does not move
    // The orientation as the Hermite spline the track plays, cut at the samples' times
    // (rotationSplineOf), for glTF's CUBICSPLINE; empty when the track plays no such spline.
    std::vector<SplineKey> rotationSpline;
    // The positions as the cubic the track plays (positionSplineOf), for glTF's CUBICSPLINE; empty when
    // they are no such curve.
    std::vector<PositionSplineKey> positionSpline;
};

// A position a skin joint moves, and by how much.
struct JointInfluence {
    std::uint32_t vertex = 0;
    float weight = 0.0F; // > 0
};

// For each of a checked skin's joints (model/value_checks.h: every joint index in range), the positions
// it moves with a nonzero weight, in increasing order, found in one pass over the positions. Both
// writers write a joint's weights as such a list: Assimp's bone, FBX's Cluster.
std::vector<std::vector<JointInfluence>> jointInfluences(const model::Skin& skin);

struct BakedScene {
    std::vector<BakedObject> objects;
    model::BakeRange range; // the scene's start and end time and the frame rate of the bake
};

// The piecewise Hermite spline whose normalised curve is the track's orientation from its first key to
// its last, when there is one: a hermite track with two keys or more plays HermiteQuaternionSpline::
// throughKeys of its keys, and an applied fit's control points over the fit's span inside them. Where
// the fit meets the keys' spline, at a key the fit kept, the two raw cubics pass through the same
// rotation but may differ by a factor (the fit's values are not unit, or on the other hemisphere); the
// keys' spline on that side is multiplied by it, which leaves its normalised curve as it is, so the
// pieces join, with a corner (in- and out-derivative differ). The spline is cut at each of `times` in
// its span and at the fit's ends: a key at each with the raw cubic's value and derivatives there
// (HermiteQuaternionSpline::raw). A cubic cut at any point is the same cubic, so the pieces make the
// same curve; and a reader that ignores the tangents (Blender 3.4's glTF importer) still has the exact
// orientation, normalised, at every one of `times`. At the times before the first key and after the
// last the pose is held: keys of the end value with no slope, so the sampler spans every sample, as
// the clip does. Empty when the track plays no such spline: another interpolation, or a fit that
// reaches past the keys or meets their spline at another rotation.
// `times` increase and include the key times (the baked samples' times).
std::vector<SplineKey> rotationSplineOf(const model::MotionTrack& track, const std::vector<double>& times);

// The cubic the track's positions follow (model::cubicPositionCurve: squad and hermite tracks), cut at
// each of `times`, with its value and velocity there, held outside the keys as the rotation is; empty
// for other tracks, whose positions are linear between keys (the baked samples, which include the key
// times, are exact) or a screw's.
std::vector<PositionSplineKey> positionSplineOf(const model::MotionTrack& track, const std::vector<double>& times);

// Makes `baked`, the bake of `scene` (its objects in the scene's order), hold the times glTF asks of an
// animation sampler's input: float32 seconds, the first not below 0, strictly increasing.
// - A scene that starts before 0 s is moved later by its start, so that it starts at 0.
// - Two baked times a float32 step apart or less (keys 1e-9 s apart; frames at 30 fps near 1e6 s,
//   where the step is 1/16 s) round to the same float32, and Assimp's glTF reader, Gyre's own import,
//   turns float32 seconds into float32 milliseconds, which can join two seconds one step apart. Of each
//   run of an object's samples that read back as the same milliseconds, one is kept: the last at one of
//   the object's key times (the artist's pose), else the last of the run. Rounding is monotonic, so the
//   kept times strictly increase as float32 seconds and as Assimp's milliseconds.
// - The splines' times move with the samples; a spline two of whose times read back as the same
//   milliseconds is dropped, and the object's rotation or translation is written from its samples.
// Returns a warning for each of these that changed something.
QStringList prepareGltfTimes(BakedScene& baked, const model::Scene& scene);

} // namespace gyre::io
