#include "core/screw.h"

#include "core/fast_trig.h"
#include "core/quaternion_math.h"

#include <cmath>

namespace gyre {

namespace {

// Below this sin(r/2) the rotation is far below what any pose can resolve; the screw is then a pure
// translation. The bound keeps sin(t·a)/sin(a) and cot a in normal floating-point numbers.
constexpr double kNoRotation = 1e-100;

} // namespace

Screw::Screw(const Pose& from, const Pose& to, WithoutAngle)
    : fromOrientation_(from.orientation)
    , fromPosition_(from.position)
{
    // R = qb·qa⁻¹ on the short arc, c = pb − R·pa. The poses' quaternions are unit, so R's vector
    // part and scalar are sin a·S and cos a.
    const Eigen::Quaterniond relative = shortArc(to.orientation * from.orientation.conjugate());
    const Eigen::Vector3d c = to.position - relative * from.position;
    const double s = relative.vec().norm();
    if (s > kNoRotation) {
        axis_ = (1.0 / s) * relative.vec();
        sinHalfAngle_ = s;
        cosHalfAngle_ = relative.w();
    } else {
        const double length = c.norm();
        axis_ = length > 0.0 ? Eigen::Vector3d(c / length) : Eigen::Vector3d::UnitX();
    }
    slide_ = axis_.dot(c);
    perpendicular_ = c - slide_ * axis_;
    turnedOrientation_ = pureQuaternion(axis_) * fromOrientation_;
    if (sinHalfAngle_ > 0.0) {
        const double cotangent = cosHalfAngle_ / sinHalfAngle_;
        const Eigen::Vector3d positionAcross = from.position - axis_.dot(from.position) * axis_;
        const Eigen::Vector3d perpendicularTurned = axis_.cross(perpendicular_);
        sinSquaredTerm_ = perpendicular_ - 2.0 * positionAcross + cotangent * perpendicularTurned;
        sinCosTerm_ = 2.0 * axis_.cross(positionAcross) - perpendicularTurned + cotangent * perpendicular_;
    } else {
        sinSquaredTerm_.setZero(); // s = sin(ta) is 0 for every t
        sinCosTerm_.setZero();
    }
}

Screw::Screw(const Pose& from, const Pose& to)
    : Screw(from, to, WithoutAngle{})
{
    if (sinHalfAngle_ > 0.0)
        halfAngle_ = fastAngleOnUnitCircle(cosHalfAngle_, sinHalfAngle_);
}

Pose Screw::at(double t) const
{
    const SinCos turn = fastSinCos(t * halfAngle_);
    return pose(t, turn.sin, turn.cos, turn.sin * turn.sin, turn.sin * turn.cos);
}

Pose Screw::midpoint(const Pose& from, const Pose& to)
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

Pose Screw::pose(double t, double sinT, double cosT, double sinSquared, double sinCos) const
{
    return {linearCombination(cosT, fromOrientation_, sinT, turnedOrientation_),
            fromPosition_ + (t * slide_) * axis_ + sinSquared * sinSquaredTerm_ + sinCos * sinCosTerm_};
}

std::optional<Eigen::Vector3d> Screw::axisPoint() const
{
    if (sinHalfAngle_ == 0.0)
        return std::nullopt;
    // P = (c⊥ + cot(a)·S×c⊥)/2 solves (I − R)P = c⊥ with P ⊥ S.
    return 0.5 * (perpendicular_ + (cosHalfAngle_ / sinHalfAngle_) * axis_.cross(perpendicular_));
}

Pose screwInterpolate(const Pose& from, double t, const Pose& to)
{
    // The motion of Screw(from, to).at(t) for a single t, without the terms that only pay off over
    // many t: R_t = (cos ta, sin ta·S) applied to La, then c_t = (sin ta / sin a)·Rot(S, (t−1)a)·c⊥ + t·d·S.
    const Eigen::Quaterniond relative = shortArc(to.orientation * from.orientation.conjugate());
    const Eigen::Vector3d c = to.position - relative * from.position;
    const double s = relative.vec().norm();
    if (!(s > kNoRotation))
        return {from.orientation, from.position + t * c};
    const double w = relative.w();
    const SinCos turn = fastSinCos(t * fastAngleOnUnitCircle(w, s));
    const double inverseS = 1.0 / s;
    const Eigen::Vector3d axis = inverseS * relative.vec();
    const Eigen::Quaterniond rotation(turn.cos, turn.sin * axis.x(), turn.sin * axis.y(), turn.sin * axis.z());
    const double slide = axis.dot(c);
    const Eigen::Vector3d across = c - slide * axis;
    const double ratio = turn.sin * inverseS;
    const double sinBack = turn.sin * w - turn.cos * s;
    const double cosBack = turn.cos * w + turn.sin * s;
    return {rotation * from.orientation,
            rotation * from.position + ratio * (cosBack * across + sinBack * axis.cross(across)) + (t * slide) * axis};
}

} // namespace gyre
