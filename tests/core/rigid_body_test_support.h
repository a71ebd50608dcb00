#pragma once
// Rigid-body quantities for the free-flight tests, written from their definitions: an inertia tensor with
// products (principal moments turned by a rotation), and the world angular momentum L = R·I·Rᵀ·ω.

#include <Eigen/Dense>
#include <Eigen/Geometry>

namespace gyre::test {

inline Eigen::Matrix3d rotatedInertia(const Eigen::Vector3d& moments, const Eigen::Quaterniond& axes)
{
    const Eigen::Matrix3d r = axes.toRotationMatrix();
    return r * moments.asDiagonal() * r.transpose();
}

inline Eigen::Vector3d momentumOf(const Eigen::Matrix3d& inertia, const Eigen::Quaterniond& q,
                                  const Eigen::Vector3d& omega)
{
    const Eigen::Matrix3d r = q.toRotationMatrix();
    return r * inertia * r.transpose() * omega;
}

} // namespace gyre::test
