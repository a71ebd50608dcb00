#include "core/screw.h"

#include "core/fast_trig.h"
#include "core/quaternion_math.h"

#include <cmath>

namespace gyre {

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
    if (!(s > Screw::kNoRotation))
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
