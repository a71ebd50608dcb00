#pragma once
// The motion of a track as the project evaluates it: its pose at any time, and a bake at a frame rate.
//
// - slerp, nlerp, euler: that orientation curve through the keys, positions linear;
//   squad, hermite: that orientation curve, positions cubic (PositionCurve::Shape::Cubic).
//   Before the first key and after the last the end pose is held.
// - screw: ScrewBender's motion. The key poses are subdivided with track.subdivision and joined by
//   screws (a polyscrew); time maps to the polyscrew's parameter by the key times' C¹ time map
//   (KeyTimeMap: key i at parameter i, speed continuous across keys). An open track holds its end
//   poses outside the keys. A cyclic track repeats forever: its closing span, from the last key back
//   to the first, lasts the mean of the other spans, so the period is T = n·(tₙ₋₁ − t₀)/(n − 1) for
//   n keys.
// - ballistic: every span between two keys the free flight of the body (`body`: its inertia and centre of mass
//   in the object's frame) that meets both keys (fit/ballistic_flight.h), each span's solution its first
//   key's flightSolution (by kinetic energy) or the one nearest the hermite motion; the centre of mass on the
//   parabola under 9.81 m/s² along +Z (Gyre's up). Each span is solved when the motion is built.
// - A fit (track.sketch.fittedCurve non-empty) gives the orientation inside the span of its control
//   points, by the normalised HermiteQuaternionSpline through them; outside, and for positions, the
//   interpolation above. On a cyclic screw track the fit repeats with the cycle, as the motion does.
// A track without keys stays at the identity pose.

#include "core/euler_angles.h"
#include "core/mass_properties.h"
#include "core/orientation_curves.h"
#include "core/pose.h"
#include "core/position_curve.h"
#include "model/scene.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace gyre::model {

namespace detail {
class KeyedMotion;
}

class TrackMotion {
public:
    // Built once, evaluated at many times. Throws std::invalid_argument for key or control-point
    // times that do not strictly increase, a subdivision too large to hold, or a free flight that cannot be
    // solved. The convention is the one the euler interpolation uses, `body` the one the ballistic one flies
    // (by default a unit sphere's: objectMassProperties gives an object's).
    explicit TrackMotion(const MotionTrack& track, const EulerConvention& eulerConvention = {},
                         const MassProperties& body = {});
    ~TrackMotion();
    TrackMotion(TrackMotion&&) noexcept;
    TrackMotion& operator=(TrackMotion&&) noexcept;

    Pose at(double time) const;
    // The angular velocity ω = 2q′q⁻¹ of the orientation, in the parent's frame, rad/s, by a central
    // difference ω ≈ 2·log(q(t+h)·q(t−h)⁻¹)/(2h) with h = kAngularVelocityStep: every interpolation
    // method alike, screws included. Zero where the pose is held.
    Eigen::Vector3d angularVelocity(double time) const;

    // For a ballistic track of two keys or more, each span's chosen free flight and how many it offers (the
    // choice an index by kinetic energy); empty for every other track.
    struct FlightChoice {
        std::size_t chosen = 0;
        std::size_t count = 0;
    };
    const std::vector<FlightChoice>& flightChoices() const { return flightChoices_; }

private:
    std::unique_ptr<const detail::KeyedMotion> keyed_; // null for a track without keys
    std::optional<HermiteQuaternionSpline> fitted_;
    // A cyclic screw track's first key time t₀ and period T: time t plays as t₀ + ((t − t₀) mod T).
    std::optional<std::pair<double, double>> cycle_;
    std::vector<FlightChoice> flightChoices_;
};

// The step of TrackMotion::angularVelocity's central difference, seconds: small against any key
// spacing an artist makes, large enough that rounding stays below 1e-9 rad/s per rad/s.
inline constexpr double kAngularVelocityStep = 1e-5;

// A frame within this many seconds of a key gives way to the key: the key time is sampled, not a
// near-duplicate a rounding error away.
inline constexpr double kKeyMergeSeconds = 1e-9;

// Frames at start + k/fps up to end (both in seconds, fps > 0).
struct BakeRange {
    double start = 0.0;
    double end = 0.0;
    double fps = 24.0;
};

// How far from 1 the length of a baked orientation may be: a normalised quaternion is unit to a few
// ulps, so anything further came from a curve that lost its direction.
inline constexpr double kBakedUnitTolerance = 1e-9;

// `pose`, sampled at `time`, if its orientation is a unit quaternion within kBakedUnitTolerance and its
// position finite; else std::invalid_argument naming the time. Nothing non-unit is ever written.
Pose unitSample(const Pose& pose, double time);

// At least as many samples as bakeTimes gives for `keyCount` keys: the caller's check against a limit
// before anything is allocated. Infinite or NaN for a range that is not finite.
double bakeSampleBound(const BakeRange& range, std::size_t keyCount);

// The frames of the range merged with the key times inside it, increasing; a frame within
// kKeyMergeSeconds of a key gives way to it. Key times must increase. Throws std::invalid_argument
// unless fps is finite and positive and start ≤ end, both finite, or for more than kMaxFrames frames.
std::vector<double> bakeTimes(const std::vector<double>& keyTimes, const BakeRange& range);

struct TimedPose {
    double time = 0.0;
    Pose pose;
};

// The track's poses at bakeTimes(its key times, range). Throws std::invalid_argument for a pose that is
// not unitSample.
std::vector<TimedPose> bakeTrack(const MotionTrack& track, const BakeRange& range,
                                 const EulerConvention& eulerConvention = {}, const MassProperties& body = {});

std::vector<double> keyTimes(const MotionTrack& track);

// The body a ballistic track of `object` flies: its mass properties (objectMassProperties, object_mass.h: typed,
// its mesh's, or the default block's); the default MassProperties for a track of any other interpolation, which
// needs none.
MassProperties flightBodyOf(const SceneObject& object);

// The track's positions as TrackMotion plays them, when they are a cubic curve through the keys (squad
// and hermite tracks with two keys or more); none for the other interpolations.
std::optional<PositionCurve> cubicPositionCurve(const MotionTrack& track);

} // namespace gyre::model
