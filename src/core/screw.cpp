#include "core/screw.h"

namespace gyre {

std::optional<Eigen::Vector3d> Screw::axisPoint() const
{
    if (sinHalfAngle_ == 0.0)
        return std::nullopt;
    // P = pa⊥ + V₁/2 = (pa⊥ + pb⊥)/2 + (cot a)/2·S×Δ: the chord's midpoint, moved across the chord
    // to the centre of the circle on which the chord spans an arc of 2a. P ⊥ S.
    return fromPosition_ - axis_.dot(fromPosition_) * axis_ + 0.5 * sinSquaredTerm_;
}

Pose screwInterpolate(const Pose& from, double t, const Pose& to)
{
    return Screw(from, to).at(t);
}

} // namespace gyre
