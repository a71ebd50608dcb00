#pragma once
// A pose: an orientation and a position. It maps a point x of the object's local frame to
// orientation·x + position in the world.

#include <Eigen/Geometry>

namespace gyre {

struct Pose {
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
    Eigen::Vector3d position = Eigen::Vector3d::Zero();

    Eigen::Vector3d apply(const Eigen::Vector3d& localPoint) const { return orientation * localPoint + position; }

    Pose inverse() const
    {
        const Eigen::Quaterniond inverted = orientation.conjugate();
        return {inverted, -(inverted * position)};
    }

    // (a * b).apply(x) == a.apply(b.apply(x))
    friend Pose operator*(const Pose& a, const Pose& b)
    {
        return {a.orientation * b.orientation, a.orientation * b.position + a.position};
    }
};

} // namespace gyre
