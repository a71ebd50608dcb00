#include "core/screw.h"

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
    return Screw(from, to).at(t);
}

} // namespace gyre
