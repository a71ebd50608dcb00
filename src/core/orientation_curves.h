#pragma once
// Orientation curves through timed keys: slerp, nlerp, Shoemake's squad, the Hermite quaternion
// spline of the sketch-editing paper, and linear interpolation of Euler angles (kept on purpose, to
// show why it misbehaves). Each gives its value, its time derivative and its world angular velocity
// ω = 2q′q⁻¹, all analytically.
//
// Keys are made sign-consistent on construction (each key flipped to the hemisphere of the one
// before), so every curve takes the short arc between consecutive keys. Outside the key span a curve
// holds the end orientation with zero derivative.

#include "core/euler_angles.h"
#include "core/name_table.h"

#include <Eigen/Geometry>

#include <cstddef>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

namespace gyre {

struct OrientationKey {
    double time = 0.0;
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
};

struct OrientationSample {
    Eigen::Quaterniond value;           // unit
    Eigen::Quaterniond derivative;      // dq/dt
    Eigen::Vector3d angularVelocity;    // world frame, rad/s
};

class OrientationCurve {
public:
    virtual ~OrientationCurve() = default;

    OrientationSample sample(double time) const;
    double startTime() const { return keys_.front().time; }
    double endTime() const { return keys_.back().time; }
    const std::vector<OrientationKey>& keys() const { return keys_; }

protected:
    // Throws std::invalid_argument unless there is at least one key and times strictly increase.
    explicit OrientationCurve(std::vector<OrientationKey> keys);
    // Copied and moved only as part of a concrete curve, never sliced through the base.
    OrientationCurve(const OrientationCurve&) = default;
    OrientationCurve(OrientationCurve&&) = default;
    OrientationCurve& operator=(const OrientationCurve&) = default;
    OrientationCurve& operator=(OrientationCurve&&) = default;

    // The sample inside segment `segment` (keys[segment] to keys[segment + 1]) at local parameter
    // u ∈ [0, 1]; `duration` is the segment's length in seconds.
    virtual OrientationSample sampleSegment(std::size_t segment, double u, double duration) const = 0;

    std::vector<OrientationKey> keys_;
};

class SlerpCurve final : public OrientationCurve {
public:
    explicit SlerpCurve(std::vector<OrientationKey> keys);

private:
    OrientationSample sampleSegment(std::size_t segment, double u, double duration) const override;
};

class NlerpCurve final : public OrientationCurve {
public:
    explicit NlerpCurve(std::vector<OrientationKey> keys);

private:
    OrientationSample sampleSegment(std::size_t segment, double u, double duration) const override;
};

// Shoemake's squad: squad(qᵢ, qᵢ₊₁, sᵢ, sᵢ₊₁, u) = slerp(slerp(qᵢ, qᵢ₊₁, u), slerp(sᵢ, sᵢ₊₁, u), 2u(1−u))
// with inner quadrangle points sᵢ = qᵢ·exp(−(log(qᵢ⁻¹qᵢ₊₁) + log(qᵢ⁻¹qᵢ₋₁))/4), and s = q at the ends.
// The keys, sign-aligned, and their sᵢ are points of the 4-sphere, and every slerp runs between them
// as they are, with no short-arc sign flip: so the curve is continuous for keys up to 180° apart.
class SquadCurve final : public OrientationCurve {
public:
    explicit SquadCurve(std::vector<OrientationKey> keys);

private:
    OrientationSample sampleSegment(std::size_t segment, double u, double duration) const override;
    std::vector<Eigen::Quaterniond> inner_;
};

// A control point of a Hermite quaternion spline: a quaternion and its time derivative, both as
// unconstrained 4-vectors.
struct HermiteControlPoint {
    double time = 0.0;
    Eigen::Quaterniond value = Eigen::Quaterniond::Identity();
    Eigen::Quaterniond derivative = Eigen::Quaterniond(0.0, 0.0, 0.0, 0.0);
};

// A cubic Hermite spline in R⁴ through quaternions with given derivatives (Ramamoorthi and Barr, as
// the sketch-editing paper uses it). The raw curve need not stay unit; sample() reports the
// normalised curve, whose angular velocity equals that of the raw one (see angularVelocity()).
class HermiteQuaternionSpline final : public OrientationCurve {
public:
    // Control points with strictly increasing times; values need not be sign-aligned.
    explicit HermiteQuaternionSpline(std::vector<HermiteControlPoint> points);

    // How the derivatives at the keys are estimated (one-sided at the first and last key):
    // - Geodesic: q′ᵢ = qᵢ·(log(qᵢ⁻¹qᵢ₊₁) − log(qᵢ⁻¹qᵢ₋₁))/(tᵢ₊₁ − tᵢ₋₁), the body angular velocity
    //   of the two arcs through qᵢ, averaged over their time, tangent to the unit sphere: a steady spin
    //   keyed at any spacing plays at its steady speed (within 0.1% for 90° between keys).
    // - Chord: the paper's InitCurve, q′ᵢ = (qᵢ₊₁ − qᵢ₋₁)/(tᵢ₊₁ − tᵢ₋₁). The chord is shorter than
    //   the arcs and not tangent, so the speed ripples between keys (8.2–9.4 rad/s through a steady
    //   9 rad/s spin keyed every 1/6 s).
    enum class KeyDerivatives { Geodesic, Chord };

    // The spline through the keys (the paper's InitCurve, with the derivatives `rule` gives).
    static HermiteQuaternionSpline throughKeys(std::vector<OrientationKey> keys,
                                               KeyDerivatives rule = KeyDerivatives::Geodesic);

    struct RawSample {
        Eigen::Quaterniond value;
        Eigen::Quaterniond derivative;
        Eigen::Quaterniond secondDerivative;
    };
    // The unnormalised cubic and its first two time derivatives; held constant outside the span.
    RawSample raw(double time) const;

    const std::vector<HermiteControlPoint>& controlPoints() const { return points_; }

private:
    static std::vector<OrientationKey> keysOf(const std::vector<HermiteControlPoint>& points);
    RawSample rawSegment(std::size_t segment, double u, double duration) const;
    OrientationSample sampleSegment(std::size_t segment, double u, double duration) const override;
    std::vector<HermiteControlPoint> points_;
};

// Interpolation of three-angle sequences, each angle on its own over time:
// - Linear: straight lines between the keys' angles.
// - Cubic: Hermite cubics with automatic slopes, Blender's "Auto Clamped" Bézier keys: at key i the
//   slope (pᵢ₊₁ − pᵢ₋₁)/(tᵢ₊₁ − tᵢ₋₁), zero at the first and last key and where pᵢ is a local extremum
//   (or equals a neighbour), and at most three times either neighbouring chord's slope (Fritsch and
//   Carlson), so the curve never leaves the range of the two keys it joins: no overshoot.
// Built from quaternions, the keys' angles are the Euler filter's (unwrappedEulerAngles); built from
// angles (an object in Euler rotation mode), they are the angles as given, so 0 then 2π is a full turn.
class EulerAngleCurve final : public OrientationCurve {
public:
    enum class Shape { Linear, Cubic };

    EulerAngleCurve(std::vector<OrientationKey> keys, const EulerConvention& convention, Shape shape = Shape::Linear);

    struct AngleKey {
        double time = 0.0;
        Eigen::Vector3d angles = Eigen::Vector3d::Zero(); // radians, in the convention, any size
    };
    // Throws std::invalid_argument unless there is at least one key and times strictly increase.
    static EulerAngleCurve throughAngles(std::vector<AngleKey> keys, const EulerConvention& convention, Shape shape);

    // The three angles at `time` (held outside the keys), radians.
    Eigen::Vector3d anglesAt(double time) const;
    // The slopes at the keys, rad/s: one per key for Cubic, none for Linear.
    const std::vector<Eigen::Vector3d>& keySlopes() const { return slopes_; }

private:
    EulerAngleCurve(std::vector<OrientationKey> keys, const EulerConvention& convention, Shape shape,
                    std::vector<Eigen::Vector3d> angles);
    OrientationSample sampleSegment(std::size_t segment, double u, double duration) const override;
    // The angles and their time derivatives inside a segment.
    std::pair<Eigen::Vector3d, Eigen::Vector3d> anglesInSegment(std::size_t segment, double u, double duration) const;
    EulerConvention convention_;
    Shape shape_;
    std::vector<Eigen::Vector3d> angles_;
    std::vector<Eigen::Vector3d> slopes_; // one per key for Cubic, empty for Linear
};

// Ballistic: every span a rigid body's free flight (core/torque_free.h, fit/ballistic_flight.h), which needs the
// body's inertia: like Screw, it is no orientation curve.
enum class InterpolationMethod { Slerp, Nlerp, Squad, Hermite, Euler, EulerCubic, Screw, Ballistic };

inline constexpr NameTable<InterpolationMethod, 8> kInterpolationMethodNames{{
    {InterpolationMethod::Slerp, "slerp"},
    {InterpolationMethod::Nlerp, "nlerp"},
    {InterpolationMethod::Squad, "squad"},
    {InterpolationMethod::Hermite, "hermite"},
    {InterpolationMethod::Euler, "euler"},
    {InterpolationMethod::EulerCubic, "euler-cubic"},
    {InterpolationMethod::Screw, "screw"},
    {InterpolationMethod::Ballistic, "ballistic"},
}};

std::optional<InterpolationMethod> parseInterpolationMethod(std::string_view name);
// Euler and EulerCubic: the methods that interpolate angles, not quaternions.
bool interpolatesAngles(InterpolationMethod method);
std::string_view interpolationMethodName(InterpolationMethod method);

// The orientation curve of a method; `Screw` (see polyscrew.h) and `Ballistic` are not orientation curves and
// throw std::invalid_argument. The convention is used by `Euler` and `EulerCubic` only.
std::unique_ptr<OrientationCurve> makeOrientationCurve(InterpolationMethod method, std::vector<OrientationKey> keys,
                                                       const EulerConvention& convention = {});

} // namespace gyre
