#pragma once
// What the document allows in its values, checked in one place for the undo commands (which refuse a
// bad change before it is pushed) and the project file reader (which names the field). Each check
// throws std::invalid_argument with a message that reads after the name of the value, as in
// "objects[2].keyframes[5].time: 1.5 does not come after 2".

#include "model/scene.h"

#include <Eigen/Geometry>

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace gyre::model {

// A unit quaternion or vector whose length is off by no more than this is normalised; beyond it the
// value is refused. Text written with 4 to 17 digits drifts by far less.
inline constexpr double kUnitLengthTolerance = 1e-3;

// The most subdivision levels a track may ask for: 2^16 poses per control pose.
inline constexpr int kMaxSubdivisionLevels = 16;
// The highest frame rate a scene may have.
inline constexpr double kMaxFps = 1000.0;

// `value` if it is finite.
double finiteNumber(double value);
// `value` if it is finite and ≥ 0, or > 0.
double nonNegativeNumber(double value);
double positiveNumber(double value);

// The finite vector; the unit vector or quaternion within kUnitLengthTolerance of length 1, normalised.
Eigen::Vector3d finiteVector(const Eigen::Vector3d& value);
Eigen::Vector2d finiteVector(const Eigen::Vector2d& value);
Eigen::Vector3d unitVector(const Eigen::Vector3d& value);
Eigen::Quaterniond unitQuaternion(const Eigen::Quaterniond& value);
// Any finite 4-vector, such as a Hermite control point's value or derivative.
Eigen::Quaterniond finiteQuaternion(const Eigen::Quaterniond& value);

// `time` (finite) if it comes strictly after `previous`.
double timeAfter(double time, double previous);

// Checks whole values, normalising unit quaternions and vectors in place.
void checkKeyframe(Keyframe& key);
void checkKeyframes(std::vector<Keyframe>& keys);
void checkStroke(DirectionStroke& stroke);
void checkMagnitudeCurve(const std::vector<MagnitudePoint>& points);
void checkPattern(const std::vector<Eigen::Vector2d>& pattern, int repeat);
void checkWindow(const std::optional<std::pair<double, double>>& window);
void checkFittedCurve(const std::vector<HermiteControlPoint>& curve);
void checkSketch(SketchState& sketch);
void checkSubdivision(const SubdivisionSettings& settings);
void checkTrack(MotionTrack& track);
// `fps` if it is in (0, kMaxFps].
double frameRate(double fps);
void checkTimeRange(double fps, double startTime, double endTime);
// Finite positions and normals, one normal per position or none, and whole triangles of indices
// that name positions.
void checkMesh(const Mesh& mesh);

} // namespace gyre::model
