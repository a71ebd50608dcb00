#pragma once
// A ray in the world: the points origin + t·direction for t ≥ 0, direction of unit length.

#include <Eigen/Core>

namespace gyre::app {

struct Ray {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    Eigen::Vector3d direction = Eigen::Vector3d::UnitX();

    Eigen::Vector3d at(double t) const { return origin + t * direction; }
};

} // namespace gyre::app
