#pragma once
// Rigid-body quantities for the free-flight tests, written from their definitions: an inertia tensor with
// products (principal moments turned by a rotation), the world angular momentum L = R·I·Rᵀ·ω, and ω from the
// orientations alone, so that a conservation check reads what the motion does, not the ω it reports.

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

// The world angular velocity at t by a central difference of the orientation, ω ≈ θ·n/(2h) for the turn θ about
// n from q(t−h) to q(t+h). Truncation h²/6·|ω̈| and rounding 1e-16/h: about 1e-10 rad/s for |ω| ≲ 15 rad/s.
template <class OrientationAt>
Eigen::Vector3d differencedAngularVelocity(const OrientationAt& orientationAt, double t, double h = 1e-6)
{
    const Eigen::AngleAxisd turn(orientationAt(t + h) * orientationAt(t - h).conjugate());
    return turn.angle() * turn.axis() / (2.0 * h);
}

} // namespace gyre::test
