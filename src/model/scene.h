#pragma once
// The document's data: a scene of objects, each with a mesh, a parent and a motion track. Plain
// values that undo commands copy and swap; only the Document (document.h) changes them, through
// its undo stack.

#include "core/euler_angles.h"
#include "core/mass_properties.h"
#include "core/orientation_curves.h"
#include "core/pose.h"
#include "core/subdivision.h"
#include "model/shared_vector.h"

#include <Eigen/Core>
#include <QString>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace gyre::model {

// Stable identity of an object within a scene; 0 means "none" (for example, no parent).
using ObjectId = std::uint64_t;
inline constexpr ObjectId kNoObject = 0;

struct Keyframe {
    double time = 0.0;  // seconds
    Pose pose;          // the object's local transform, relative to its parent
    bool constrained = true;  // kept exactly by the angular-velocity fit unless freed
    // On a ballistic track, the free flight chosen for the span from this key to the next: its index by kinetic
    // energy (fit/ballistic_flight.h, taken modulo the span's count), or negative for the default, the flight
    // nearest the hermite motion. Kept on the key so that keys added, deleted or moved elsewhere leave each
    // span's choice with the span.
    int flightSolution = -1;
    // The three angles as the artist keyed them, radians, in the track's Euler convention, any size (720° is two
    // turns): present exactly when the track is in Euler rotation mode, and then
    // pose.orientation == quaternionFromEulerAngles(*eulerAngles, convention) to rounding (rotation_mode.h).
    std::optional<Eigen::Vector3d> eulerAngles = std::nullopt;
};

// How a track's keys hold their rotation, as Blender's rotation mode: quaternions (the orientation alone), or
// Euler angles in a convention (the angles as typed, which the euler interpolations follow, so that 0° then 360°
// is one turn). The convention also serves a quaternion track: its euler interpolations unwrap the
// quaternions into it, and the inspector and graph editor show its angles in it.
struct RotationMode {
    enum class Kind { Quaternion, Euler };
    Kind kind = Kind::Quaternion;
    EulerConvention convention;
    bool isEuler() const { return kind == Kind::Euler; }
    bool operator==(const RotationMode&) const = default;
};

// How a skinned mesh follows its joints (linear blend skinning, model/skinning.h): each position
// moves with up to four joints, weighted. The joints are objects of the same scene.
struct Skin {
    std::vector<ObjectId> joints;
    // One per joint: from the mesh's frame to the joint's frame in the bind pose, the pose in which
    // the mesh was modelled (Assimp's offset matrix, glTF's inverse bind matrix), in scene units.
    std::vector<Eigen::Matrix4f> inverseBinds;
    // One each per position: indices into `joints`, and their weights, each ≥ 0, summing to 1, or to
    // less where the rest of the position follows the mesh's own object (0 for a position no joint moves).
    std::vector<std::array<std::uint16_t, 4>> vertexJoints;
    std::vector<Eigen::Vector4f> vertexWeights;

    bool empty() const { return joints.empty(); }
};

// A triangle mesh in the object's local frame, for display.
struct Mesh {
    std::vector<Eigen::Vector3f> positions;
    std::vector<Eigen::Vector3f> normals;  // one per position, or empty
    std::vector<std::uint32_t> indices;    // three per triangle
    Skin skin;                             // empty: a rigid mesh
};

// One direction stroke the artist drew on the unit sphere: unit vectors, optionally timed. Without
// times the stroke is spread over the edit window by arc length.
struct DirectionStroke {
    std::vector<Eigen::Vector3d> points;
    std::vector<double> times;  // empty, or one per point, increasing
    bool operator==(const DirectionStroke&) const = default;
};

struct MagnitudePoint {
    double time = 0.0;
    double magnitude = 0.0;  // |ω| in rad/s
    bool operator==(const MagnitudePoint&) const = default;
};

// The sketch-editing state of a track (the sketch-editing paper's interface).
struct SketchState {
    std::vector<DirectionStroke> directionStrokes;
    std::vector<MagnitudePoint> magnitude;
    // A small curve drawn once, repeated `patternRepeat` times along the direction curve: x runs along
    // the stroke, y across it, in any unit; only its shape counts (fit::applyPattern, docs/fit.md).
    std::vector<Eigen::Vector2d> pattern;
    int patternRepeat = 0;
    std::optional<std::pair<double, double>> window;  // the edited span; the sketch's span if absent
    double alpha = 0.002;
    double beta = 1.0;
    double delta = 0.1;
    // The last applied fit: the Hermite control points of the orientation over the window. Empty when
    // no fit is applied; then the track's interpolation gives the orientation everywhere.
    std::vector<HermiteControlPoint> fittedCurve;
    // The keyframes the applied fit moved, as they were before any fit moved them (times strictly
    // increasing). Removing the fit puts each back on the key still at its time. Empty when no fit
    // is applied or it moved no key.
    std::vector<Keyframe> keysBeforeFit;
};

struct MotionTrack {
    SharedVector<Keyframe> keys;  // strictly increasing times; copies share them (shared_vector.h)
    InterpolationMethod interpolation = InterpolationMethod::Hermite; // euler or euler-cubic in Euler mode
    // The object's rotation mode: on its track, since every evaluation of the keys (motion, bake, export,
    // the worker) takes the track.
    RotationMode rotationMode;
    SubdivisionSettings subdivision;  // used when interpolation is Screw
    SketchState sketch;
};

struct SceneObject {
    ObjectId id = kNoObject;
    QString name;
    std::shared_ptr<const Mesh> mesh;  // null: the viewport draws a default shape, or plain axes for an empty
    ObjectId parent = kNoObject;
    MotionTrack track;
    // Drawn and pickable in the viewport (Blender's eye in the outliner). It hides the object alone, not
    // its children, and changes no motion: exports and fits still see it.
    bool visible = true;
    // The body's mass, centre of mass and inertia as the artist typed them; none: from the mesh
    // (model::objectMassProperties).
    std::optional<MassProperties> massOverride = std::nullopt;
    // Blender's Empty: an object that is only a frame (a pivot, a target), drawn as its three axes, never
    // a joint (app/viewport/skeleton.h). Its mesh is null.
    bool empty = false;
};

// The world axis a scene calls up, with its sign.
enum class UpDirection { PlusX, MinusX, PlusY, MinusY, PlusZ, MinusZ };

// What a ballistic track's centre of mass falls with: `acceleration` along −up.
struct Gravity {
    double acceleration = 9.81;           // m/s², ≥ 0
    UpDirection up = UpDirection::PlusZ;  // Gyre's world is Z-up
    bool operator==(const Gravity&) const = default;
};

struct Scene {
    std::vector<SceneObject> objects;  // parents come before their children
    double fps = 24.0;
    double startTime = 0.0;
    double endTime = 10.0;
    double currentTime = 0.0;
    Gravity gravity;
    ObjectId nextObjectId = 1;
};

} // namespace gyre::model
