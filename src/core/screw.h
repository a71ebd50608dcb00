#pragma once
// The screw motion between two poses, s(La, t, Lb) of ScrewBender: a rotation by t·angle about an
// axis of direction S through a point P, combined with a slide t·d along S, applied to La. It is the
// SE(3) geodesic La·exp(t·log(La⁻¹Lb)) with the rotation angle in [0, π] (the short arc).
//
// The parameters are computed once in the constructor; at(t) is cheap and valid for any t, so t
// outside [0, 1] extrapolates along the same screw.

#include "core/fast_trig.h"
#include "core/pose.h"
#include "core/quaternion_math.h"

#include <Eigen/Geometry>

#include <cmath>
#include <optional>

namespace gyre {

class Screw {
public:
    Screw(const Pose& from, const Pose& to);

    // The pose a fraction t of the way along the screw: at(0) = from, at(1) = to.
    Pose at(double t) const;

    // s(from, 1/2, to), equal to Screw(from, to).at(0.5) but without trigonometry: the half-angle
    // formulas give cos(a/2) = √((1 + cos a)/2) and sin(a/2) = sin a / (2 cos(a/2)). Subdivision
    // spends most of its screws on midpoints.
    static Pose midpoint(const Pose& from, const Pose& to);

    // Unit direction S of the axis. For a pure translation, the direction of travel; for identical
    // poses, x.
    Eigen::Vector3d axisDirection() const { return axis_; }
    // Rotation angle r ∈ [0, π] about S, right-handed.
    double angle() const { return 2.0 * halfAngle_; }
    // Signed translation d along S.
    double slide() const { return slide_; }
    // The point of the axis nearest the world origin; none when the motion has no rotation.
    std::optional<Eigen::Vector3d> axisPoint() const;

    // Below this sin(r/2) the rotation is far below what any pose can resolve; the screw is then a
    // pure translation. The bound keeps sin(t·a)/sin(a) and cot a in normal floating-point numbers.
    static constexpr double kNoRotation = 1e-100;

private:
    struct WithoutAngle {};
    // Everything but the angle itself, which only at() needs.
    Screw(const Pose& from, const Pose& to, WithoutAngle);
    // The pose at the t with sin(ta) = sinT, cos(ta) = cosT, sin²(ta) = sinSquared and
    // sin(ta)·cos(ta) = sinCos.
    Pose pose(double t, double sinT, double cosT, double sinSquared, double sinCos) const;

    // With R = qb·qa⁻¹ = (cos a, sin a·S), taken on the short arc by its sign σ, and the chord
    // Δ = pb − pa = d·S + Δ⊥, the screw at time t turns La by R_t = (cos ta, sin ta·S) about the axis
    // and slides it by t·d along it. With s = sin ta, k = cos ta and the angle-sum formulas,
    // everything is linear in s, k, s², s·k and t:
    //   orientation(t) = k·qa + s·(0, S)·qa,   (0, S)·qa = (σqb − cos a·qa) / sin a
    //   position(t)    = pa + t·d·S + s²·V₁ + s·k·V₂
    //   V₁ = Δ⊥ + cot a·S×Δ,   V₂ = cot a·Δ⊥ − S×Δ
    // Across S the chord Δ⊥ joins two points of a circle about the axis point P = pa⊥ + V₁/2, and
    // position(t) turns pa's part across S about P by 2ta; at t = 1, s² + k² = 1 leaves pa + Δ. No
    // term needs pa turned by R, and as the poses' quaternions are unit, R·qa = σqb gives (0, S)·qa
    // without a quaternion product. As a → 0, cot a and 1/sin a grow like 1/a while s and s·k shrink
    // like a and s² like a², so every product stays bounded, and so do their rounding errors.
    Eigen::Quaterniond fromOrientation_;   // qa
    Eigen::Quaterniond turnedOrientation_; // (0, S)·qa
    Eigen::Vector3d fromPosition_;         // pa
    Eigen::Vector3d axis_;                 // S
    Eigen::Vector3d sinSquaredTerm_;       // V₁
    Eigen::Vector3d sinCosTerm_;           // V₂
    double halfAngle_ = 0.0;               // a = r/2
    double cosHalfAngle_ = 1.0;
    double sinHalfAngle_ = 0.0;
    double slide_ = 0.0;                   // d
};

// Defined here, so that the subdivision's loop inlines them.

// Both constructors forced inline: GCC otherwise calls them out of line, and the caller then reads
// every member back from memory, a tenth of BM_Screw's time (36 ns against 32).
[[gnu::always_inline]] inline Screw::Screw(const Pose& from, const Pose& to, WithoutAngle)
    : fromOrientation_(from.orientation)
    , fromPosition_(from.position)
{
    // σ by its sign rather than by a branch, which the random sign would mispredict half the time.
    const Eigen::Quaterniond product = to.orientation * from.orientation.conjugate();
    const double side = std::copysign(1.0, product.w());
    const Eigen::Quaterniond relative = scaled(product, side);
    const Eigen::Vector3d chord = to.position - from.position;
    const double s = relative.vec().norm();
    // 1/sin a and cot a stay 0 without rotation, where s = sin(ta) = 0 for every t.
    double inverseSin = 0.0;
    double cotangent = 0.0;
    if (s > kNoRotation) [[likely]] {
        inverseSin = 1.0 / s;
        axis_ = inverseSin * relative.vec();
        sinHalfAngle_ = s;
        cosHalfAngle_ = relative.w();
        cotangent = cosHalfAngle_ * inverseSin;
    } else {
        const double length = chord.norm();
        axis_ = length > 0.0 ? Eigen::Vector3d(chord / length) : Eigen::Vector3d::UnitX();
    }
    slide_ = axis_.dot(chord);
    const Eigen::Vector3d chordAcross = chord - slide_ * axis_;
    const Eigen::Vector3d chordTurned = axis_.cross(chord); // S×Δ = S×Δ⊥
    sinSquaredTerm_ = chordAcross + cotangent * chordTurned;
    sinCosTerm_ = cotangent * chordAcross - chordTurned;
    turnedOrientation_ = linearCombination(side * inverseSin, to.orientation, -cotangent, fromOrientation_);
}

[[gnu::always_inline]] inline Screw::Screw(const Pose& from, const Pose& to)
    : Screw(from, to, WithoutAngle{})
{
    if (sinHalfAngle_ > 0.0)
        halfAngle_ = fastAngleOnUnitCircle(cosHalfAngle_, sinHalfAngle_);
}

inline Pose Screw::at(double t) const
{
    const SinCos turn = fastSinCos(t * halfAngle_);
    return pose(t, turn.sin, turn.cos, turn.sin * turn.sin, turn.sin * turn.cos);
}

inline Pose Screw::midpoint(const Pose& from, const Pose& to)
{
    // Half-angle formulas, with cos a ≥ 0 on the short arc: cos(a/2) = √((1 + cos a)/2),
    // sin²(a/2) = sin²a / (2(1 + cos a)) (not (1 − cos a)/2, which cancels for small a),
    // sin(a/2)·cos(a/2) = sin a / 2.
    const Screw screw(from, to, WithoutAngle{});
    const double sinA = screw.sinHalfAngle_;
    const double onePlusCos = 1.0 + screw.cosHalfAngle_;
    const double cosT = std::sqrt(0.5 * onePlusCos);
    return screw.pose(0.5, 0.5 * sinA / cosT, cosT, 0.5 * sinA * sinA / onePlusCos, 0.5 * sinA);
}

inline Pose Screw::pose(double t, double sinT, double cosT, double sinSquared, double sinCos) const
{
    return {linearCombination(cosT, fromOrientation_, sinT, turnedOrientation_),
            fromPosition_ + (t * slide_) * axis_ + sinSquared * sinSquaredTerm_ + sinCos * sinCosTerm_};
}

// s(La, t, Lb): Screw(from, to).at(t).
Pose screwInterpolate(const Pose& from, double t, const Pose& to);

} // namespace gyre
