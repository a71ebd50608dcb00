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

#include <array>
#include <cmath>
#include <cstddef>
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

namespace screw_detail {

// The operations below for T = double, and for T an Eigen array of lanes (ScrewBatch), where a
// choice is a select of whole lanes: every quotient a choice may discard is computed in every lane.
inline double filled(double value, double) { return value; }
template <class T>
T filled(double value, const T&) { return T::Constant(value); }
inline bool above(double a, double b) { return a > b; }
template <class T>
auto above(const T& a, double b) { return (a > b).eval(); }
inline bool all(bool mask) { return mask; }
template <class Mask>
bool all(const Mask& mask) { return mask.all(); }
inline double choose(bool mask, double a, double b) { return mask ? a : b; }
template <class Mask, class T>
T choose(const Mask& mask, const T& a, const T& b) { return mask.select(a, b); }
inline double signOf(double w) { return std::copysign(1.0, w); }
template <class T>
T signOf(const T& w) { return w.unaryExpr([](double v) { return std::copysign(1.0, v); }); }

// A screw's parameters from its two poses' coefficients, quaternions x, y, z, w as Eigen stores
// them: Screw and the lanes of ScrewBatch (screw_batch.h) run these same operations, so their results
// agree to the bit.
template <class T>
struct Terms {
    std::array<T, 4> turned; // (0, S)·qa
    std::array<T, 3> axis;
    std::array<T, 3> sinSquared; // V₁
    std::array<T, 3> sinCos;     // V₂
    T cosHalf;
    T sinHalf;
    T slide;
};

template <class T>
[[gnu::always_inline]] inline Terms<T> terms(const std::array<T, 4>& qa, const std::array<T, 3>& pa,
                                             const std::array<T, 4>& qb, const std::array<T, 3>& pb)
{
    using std::sqrt;
    // R = qb·qa⁻¹, in the order of Eigen's SSE quaternion product of qb and conj(qa).
    const T& ax = qb[0];
    const T& ay = qb[1];
    const T& az = qb[2];
    const T& aw = qb[3];
    const T bx = -qa[0];
    const T by = -qa[1];
    const T bz = -qa[2];
    const T& bw = qa[3];
    const std::array<T, 4> product{(aw * bx + ay * bz) - (az * by - ax * bw),
                                   (aw * by + ay * bw) + (az * bx - ax * bz),
                                   (aw * bz - ay * bx) + (az * bw + ax * by),
                                   (aw * bw - ay * by) - (az * bz + ax * bx)};
    // σ by its sign rather than by a branch, which the random sign would mispredict half the time.
    const T side = signOf(product[3]);
    std::array<T, 4> relative;
    std::array<T, 3> chord;
#pragma GCC unroll 4
    for (std::size_t c = 0; c < 4; ++c)
        relative[c] = side * product[c];
#pragma GCC unroll 4
    for (std::size_t c = 0; c < 3; ++c)
        chord[c] = pb[c] - pa[c];
    const T s = sqrt((relative[0] * relative[0] + relative[1] * relative[1]) + relative[2] * relative[2]);
    // Without rotation (s ≤ kNoRotation) 1/sin a and cot a stay 0, where s = sin(ta) = 0 for every t,
    // and the axis is the direction of travel, or x for identical poses: rare enough that a batch
    // takes that path, with its choices lane by lane, only for a block with such a screw.
    const auto rotates = above(s, Screw::kNoRotation);
    Terms<T> t;
    T inverseSin;
    if (all(rotates)) [[likely]] {
        inverseSin = 1.0 / s;
#pragma GCC unroll 4
        for (std::size_t c = 0; c < 3; ++c)
            t.axis[c] = inverseSin * relative[c];
        t.sinHalf = s;
        t.cosHalf = relative[3];
    } else {
        const T one = filled(1.0, s);
        const T zero = filled(0.0, s);
        inverseSin = choose(rotates, T(1.0 / choose(rotates, s, one)), zero);
        const T length = sqrt((chord[0] * chord[0] + chord[1] * chord[1]) + chord[2] * chord[2]);
        const auto travels = above(length, 0.0);
        const T safeLength = choose(travels, length, one);
#pragma GCC unroll 4
        for (std::size_t c = 0; c < 3; ++c) {
            const T travelling = chord[c] / safeLength;
            t.axis[c] = choose(rotates, T(inverseSin * relative[c]), choose(travels, travelling, c == 0 ? one : zero));
        }
        t.sinHalf = choose(rotates, s, zero);
        t.cosHalf = choose(rotates, relative[3], one);
    }
    const T cotangent = t.cosHalf * inverseSin; // 0 without rotation, as inverseSin is
    t.slide = (t.axis[0] * chord[0] + t.axis[1] * chord[1]) + t.axis[2] * chord[2];
    // S×Δ = S×Δ⊥
    const std::array<T, 3> chordTurned{t.axis[1] * chord[2] - t.axis[2] * chord[1],
                                       t.axis[2] * chord[0] - t.axis[0] * chord[2],
                                       t.axis[0] * chord[1] - t.axis[1] * chord[0]};
#pragma GCC unroll 4
    for (std::size_t c = 0; c < 3; ++c) {
        const T across = chord[c] - t.slide * t.axis[c];
        t.sinSquared[c] = across + cotangent * chordTurned[c];
        t.sinCos[c] = cotangent * across - chordTurned[c];
    }
    const T towardsTo = side * inverseSin;
    const T awayFrom = -cotangent;
#pragma GCC unroll 4
    for (std::size_t c = 0; c < 4; ++c)
        t.turned[c] = towardsTo * qb[c] + awayFrom * qa[c];
    return t;
}

// sin(ta), cos(ta), sin²(ta) and sin(ta)·cos(ta) at t = 1/2 by the half-angle formulas, with
// cos a ≥ 0 on the short arc: cos(a/2) = √((1 + cos a)/2), sin²(a/2) = sin²a / (2(1 + cos a)) (not
// (1 − cos a)/2, which cancels for small a), sin(a/2)·cos(a/2) = sin a / 2.
template <class T>
struct HalfTurn {
    T sin;
    T cos;
    T sinSquared;
    T sinCos;
};
template <class T>
[[gnu::always_inline]] inline HalfTurn<T> halfTurn(const T& cosA, const T& sinA)
{
    using std::sqrt;
    const T onePlusCos = 1.0 + cosA;
    const T cosT = sqrt(0.5 * onePlusCos);
    return {0.5 * sinA / cosT, cosT, 0.5 * sinA * sinA / onePlusCos, 0.5 * sinA};
}

} // namespace screw_detail

// Both constructors forced inline: GCC otherwise calls them out of line, and the caller then reads
// every member back from memory, a tenth of BM_Screw's time (36 ns against 32).
[[gnu::always_inline]] inline Screw::Screw(const Pose& from, const Pose& to, WithoutAngle)
    : fromOrientation_(from.orientation)
    , fromPosition_(from.position)
{
    const auto coefficients = [](const Eigen::Quaterniond& q) {
        return std::array<double, 4>{q.x(), q.y(), q.z(), q.w()};
    };
    const auto components = [](const Eigen::Vector3d& v) { return std::array<double, 3>{v.x(), v.y(), v.z()}; };
    const screw_detail::Terms<double> t = screw_detail::terms(coefficients(from.orientation), components(from.position),
                                                      coefficients(to.orientation), components(to.position));
    turnedOrientation_ = Eigen::Quaterniond(t.turned[3], t.turned[0], t.turned[1], t.turned[2]);
    axis_ = Eigen::Vector3d(t.axis[0], t.axis[1], t.axis[2]);
    sinSquaredTerm_ = Eigen::Vector3d(t.sinSquared[0], t.sinSquared[1], t.sinSquared[2]);
    sinCosTerm_ = Eigen::Vector3d(t.sinCos[0], t.sinCos[1], t.sinCos[2]);
    cosHalfAngle_ = t.cosHalf;
    sinHalfAngle_ = t.sinHalf;
    slide_ = t.slide;
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
    const Screw screw(from, to, WithoutAngle{});
    const screw_detail::HalfTurn<double> half = screw_detail::halfTurn(screw.cosHalfAngle_, screw.sinHalfAngle_);
    return screw.pose(0.5, half.sin, half.cos, half.sinSquared, half.sinCos);
}

inline Pose Screw::pose(double t, double sinT, double cosT, double sinSquared, double sinCos) const
{
    return {linearCombination(cosT, fromOrientation_, sinT, turnedOrientation_),
            fromPosition_ + (t * slide_) * axis_ + sinSquared * sinSquaredTerm_ + sinCos * sinCosTerm_};
}

// s(La, t, Lb): Screw(from, to).at(t).
Pose screwInterpolate(const Pose& from, double t, const Pose& to);

} // namespace gyre
