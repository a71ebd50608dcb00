#pragma once
// Quaternion algebra that Eigen does not provide: the exponential and logarithm of unit quaternions,
// their differentials, short-arc slerp and nlerp, and angular velocity.
//
// Conventions (docs/conventions.md): Hamilton quaternions rotating actively, q and -q the same rotation.
// Quaternion-valued quantities that need not be unit (derivatives, unnormalised spline values) are
// Eigen::Quaterniond too; sums and scalings go through coeffs().

#include <Eigen/Geometry>

namespace gyre {

// exp(v) of the pure quaternion (0, v): (cos|v|, sin|v|/|v| · v). A unit quaternion whose rotation
// angle is 2|v| about v/|v|.
Eigen::Quaterniond quatExp(const Eigen::Vector3d& v);

// The principal logarithm of a unit quaternion, short arc: v with |v| ∈ [0, π/2] and
// quatExp(v) = ±q. The rotation vector of q is 2·quatLog(q).
Eigen::Vector3d quatLog(const Eigen::Quaterniond& q);

// The logarithm on the 4-sphere, with no sign flip: v with |v| ∈ [0, π) and quatExp(v) = q exactly, for
// unit q ≠ −1. Unlike quatLog it is continuous across w = 0 (rotations of 180°), so a curve through
// quaternions on either side of it keeps one sign; its one cut is at q = −1.
Eigen::Vector3d quatLogOnSphere(const Eigen::Quaterniond& q);

// d/dε quatExp(v + ε·dv) at ε = 0.
Eigen::Quaterniond quatExpDerivative(const Eigen::Vector3d& v, const Eigen::Vector3d& dv);

// d/dε quatLog(q + ε·dq) at ε = 0, for unit q with w ≠ 0 and dq tangent to the unit sphere.
Eigen::Vector3d quatLogDerivative(const Eigen::Quaterniond& q, const Eigen::Quaterniond& dq);

// d/dε quatLogOnSphere(q + ε·dq) at ε = 0, for unit q ≠ −1 and dq tangent to the unit sphere.
Eigen::Vector3d quatLogOnSphereDerivative(const Eigen::Quaterniond& q, const Eigen::Quaterniond& dq);


// Spherical linear interpolation along the short arc: q0·(q0⁻¹q1)^t, exact for tiny arcs and for arcs
// near 180°; t outside [0, 1] extrapolates along the same great circle.
Eigen::Quaterniond slerp(const Eigen::Quaterniond& q0, const Eigen::Quaterniond& q1, double t);

// Normalised linear interpolation along the short arc.
Eigen::Quaterniond nlerp(const Eigen::Quaterniond& q0, const Eigen::Quaterniond& q1, double t);

// World-frame angular velocity of a quaternion curve with value q and derivative dq:
// ω = vec(2·dq·q⁻¹), q⁻¹ = conj(q)/|q|². For a non-unit q (an unnormalised spline) this equals the
// angular velocity of q/|q|, because the scalar part that the norm's change adds is discarded.
Eigen::Vector3d angularVelocity(const Eigen::Quaterniond& q, const Eigen::Quaterniond& dq);

// Derivative of q/|q| given the derivative dq of q: dq/|q| − q·(q·dq)/|q|³.
Eigen::Quaterniond normalizedDerivative(const Eigen::Quaterniond& q, const Eigen::Quaterniond& dq);

// a·p + b·q, coefficient-wise.
inline Eigen::Quaterniond linearCombination(double a, const Eigen::Quaterniond& p, double b,
                                            const Eigen::Quaterniond& q)
{
    Eigen::Quaterniond r;
    r.coeffs() = a * p.coeffs() + b * q.coeffs();
    return r;
}

// s·q, coefficient-wise.
inline Eigen::Quaterniond scaled(const Eigen::Quaterniond& q, double s)
{
    Eigen::Quaterniond r;
    r.coeffs() = s * q.coeffs();
    return r;
}

// q or -q, whichever has w ≥ 0: the representative on the short-arc side of the identity.
inline Eigen::Quaterniond shortArc(const Eigen::Quaterniond& q)
{
    return q.w() < 0.0 ? scaled(q, -1.0) : q;
}

// `to`, or -`to`, whichever is nearer `from` on the 4-sphere (non-negative dot product).
inline Eigen::Quaterniond alignedWith(const Eigen::Quaterniond& to, const Eigen::Quaterniond& from)
{
    return to.coeffs().dot(from.coeffs()) < 0.0 ? scaled(to, -1.0) : to;
}

// The pure quaternion (0, v).
inline Eigen::Quaterniond pureQuaternion(const Eigen::Vector3d& v)
{
    return Eigen::Quaterniond(0.0, v.x(), v.y(), v.z());
}

} // namespace gyre
