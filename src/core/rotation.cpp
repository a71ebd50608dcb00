#include "core/rotation.h"

#include "core/quaternion_math.h"

#include <Eigen/SVD>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace gyre {

AxisAngle axisAngleFromQuaternion(const Eigen::Quaterniond& q)
{
    // angle = 2·atan2(|vec|, w) on the short arc: exact near 0 and near π, and never above π.
    const Eigen::Quaterniond p = shortArc(q);
    const double s = p.vec().norm();
    if (s == 0.0)
        return {};
    return {p.vec() / s, 2.0 * std::atan2(s, p.w())};
}

Eigen::Quaterniond quaternionFromAxisAngle(const AxisAngle& axisAngle)
{
    const double length = axisAngle.axis.norm();
    if (length == 0.0) {
        if (axisAngle.angle != 0.0)
            throw std::invalid_argument("a rotation by a nonzero angle needs a nonzero axis");
        return Eigen::Quaterniond::Identity();
    }
    return quatExp((0.5 * axisAngle.angle / length) * axisAngle.axis);
}

Eigen::Vector3d rotationVectorFromQuaternion(const Eigen::Quaterniond& q)
{
    return 2.0 * quatLog(q.normalized());
}

Eigen::Quaterniond quaternionFromRotationVector(const Eigen::Vector3d& r)
{
    return quatExp(0.5 * r);
}

Eigen::Matrix3d nearestRotation(const Eigen::Matrix3d& m)
{
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d u = svd.matrixU();
    const Eigen::Matrix3d& v = svd.matrixV();
    if ((u * v.transpose()).determinant() < 0.0)
        u.col(2) = -u.col(2); // flip the direction of the smallest singular value
    return u * v.transpose();
}

double rotationMatrixError(const Eigen::Matrix3d& m)
{
    if (!(m.determinant() > 0.0))
        return std::numeric_limits<double>::infinity();
    return (m.transpose() * m - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
}

} // namespace gyre
