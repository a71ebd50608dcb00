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

// Budgets, so that no value the document holds asks for unbounded time or memory.
//
// Every time in the document (keys, strokes, magnitude points, the window, fitted control points, the
// scene's range) lies within ±kMaxTimeSeconds: eleven and a half days, far beyond any animation, and
// small enough that a duration times kMaxFps stays an exact integer in a double.
inline constexpr double kMaxTimeSeconds = 1e6;
// The largest coordinate of a key's position, in scene units: a billion metres, or ten thousand
// kilometres in centimetres. Position curves multiply coordinates by one another and by powers of time
// (the cubic's terms, the screw's chord), so a bound far below the overflow keeps every term finite;
// a double still resolves 10⁻⁷ of a unit there.
inline constexpr double kMaxPositionCoordinate = 1e9;
// The most frames a scene's range may hold at its frame rate, (end − start)·fps: the rows a pose file
// may hold (2^24, 4.7 hours at kMaxFps), each frame one sample of every object when baked.
inline constexpr double kMaxFrames = 16777216.0;
// The most poses a screw track may subdivide into, n·2^L for n keys at L levels (cyclic or open): 2^20.
// Measured, a subdivided pose costs about 255 bytes while a track is subdivided and evaluated (the
// pose, the subdivider's working buffers, the polyscrew's screw per span): 1,000 keys at 12 levels,
// 4,096,000 poses, bake with a peak of 1.04 GB in 52 s. The budget keeps one track near 270 MB.
inline constexpr std::size_t kMaxSubdividedPoses = std::size_t{1} << 20;
// The most keys a ballistic track holds. Each span is a free flight solved when its keys first meet, about 4 ms
// of CPU in a release build (gyre-bench's BM_FlightSolve; spans already solved are remembered): 64 keys are
// about a quarter of a second of solving when a project opens, and a thrown object is keyed at its launch, its
// landing and a few bounces.
inline constexpr std::size_t kMaxBallisticKeys = 64;
// The shortest a fitted control point's value may be. The fit starts from unit keys and keeps its
// values near length 1; the curve is normalised when evaluated, so a value near zero has no direction
// and its neighbourhood turns arbitrarily fast (the normalised curve's angular velocity grows as
// 1/|q|²). Zero, denormal and such near-zero values are refused.
inline constexpr double kMinControlValueNorm = 1e-3;
// The largest a fitted control point's derivative q′ may be, per second. For a unit curve |q′| = |ω|/2,
// so this allows 2·10^6 rad/s (over 300,000 turns a second, far beyond what kMaxFps can show), and keeps
// every term of the cubic, value + q′·Δt with Δt ≤ 2·kMaxTimeSeconds, below 10^13: no overflow, and
// the length stays far from zero and infinity, so evaluation stays unit.
inline constexpr double kMaxControlDerivativeNorm = 1e6;

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

// `position` if each coordinate is finite and within ±kMaxPositionCoordinate.
Eigen::Vector3d positionValue(const Eigen::Vector3d& position);
// `time` if it is finite and within ±kMaxTimeSeconds.
double timeValue(double time);
// `time` (a timeValue) if it comes strictly after `previous`.
double timeAfter(double time, double previous);
// A fitted control point's value (length ≥ kMinControlValueNorm) and derivative (length ≤
// kMaxControlDerivativeNorm).
Eigen::Quaterniond controlValue(const Eigen::Quaterniond& value);
Eigen::Quaterniond controlDerivative(const Eigen::Quaterniond& derivative);

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
// The poses a screw track would subdivide into, `keyCount`·2^levels, within kMaxSubdividedPoses; the keys of a
// ballistic track within kMaxBallisticKeys; a track of another interpolation passes.
void checkPoseBudget(std::size_t keyCount, InterpolationMethod interpolation, const SubdivisionSettings& settings);
void checkTrack(MotionTrack& track);
// `fps` if it is in (0, kMaxFps].
double frameRate(double fps);
// A frame rate, start and end times (timeValues, start before end), and at most kMaxFrames frames.
void checkTimeRange(double fps, double startTime, double endTime);
// The most joints a skin may have: the joint matrices a vertex shader holds in one 16 KiB uniform
// block, the size every OpenGL 3.3 driver gives (256 4×4 float matrices). A 31-joint capture uses 31,
// characters with fingers about 70.
inline constexpr std::size_t kMaxSkinJoints = 256;

// Finite positions and normals, one normal per position or none, and whole triangles of indices
// that name positions; a skin that is empty or checkSkin's.
void checkMesh(const Mesh& mesh);
// At most kMaxSkinJoints distinct nonzero joints, a finite inverse bind each whose last row is
// (0, 0, 0, 1), and for each of `positions` four joint indices below the joint count and four
// finite weights ≥ 0 whose sum is at most 1 (within kSkinWeightTolerance).
inline constexpr float kSkinWeightTolerance = 1e-3F;
void checkSkin(const Skin& skin, std::size_t positions);

} // namespace gyre::model
