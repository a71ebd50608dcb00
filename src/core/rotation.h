#pragma once
// Rotation representations other than three-angle sequences (see euler_angles.h), and exact
// conversions between them. Quaternion ↔ matrix is Eigen's own (Shepperd's method); matrices act on
// column vectors, v' = R·v.

#include <Eigen/Geometry>

namespace gyre {

// A rotation by `angle` radians about the unit vector `axis`, right-handed.
struct AxisAngle {
    Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
    double angle = 0.0;
};

// The axis-angle of q with angle ∈ [0, π]; the identity gives axis x, angle 0.
AxisAngle axisAngleFromQuaternion(const Eigen::Quaterniond& q);

// The unit quaternion of an axis-angle; the axis need not be unit but must not be zero unless the
// angle is.
Eigen::Quaterniond quaternionFromAxisAngle(const AxisAngle& axisAngle);

// The rotation vector (exponential coordinates) angle·axis, |r| ∈ [0, π].
Eigen::Vector3d rotationVectorFromQuaternion(const Eigen::Quaterniond& q);

// The unit quaternion exp(r/2) of a rotation vector r; exact for tiny |r|.
Eigen::Quaterniond quaternionFromRotationVector(const Eigen::Vector3d& r);

// The rotation matrix nearest to m in the Frobenius norm (U·Vᵀ of its SVD, with the sign that makes
// the determinant +1). Used to accept matrices written with limited precision.
Eigen::Matrix3d nearestRotation(const Eigen::Matrix3d& m);

// How far m is from being a rotation: max |(mᵀm − I)ᵢⱼ|, and +∞ if det m ≤ 0.
double rotationMatrixError(const Eigen::Matrix3d& m);

} // namespace gyre
