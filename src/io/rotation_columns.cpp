#include "io/rotation_columns.h"

#include "core/number_text.h"
#include "core/rotation.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace gyre::io {

namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

// Re-normalising a unit quaternion can change its last bits; within this of 1 the squared norm is
// unit to rounding and the quaternion is kept as it is.
constexpr double kUnitSquaredNormRounding = 64 * std::numeric_limits<double>::epsilon();

constexpr std::array<std::string_view, 4> kQuaternionNames{"qw", "qx", "qy", "qz"};
constexpr std::array<std::string_view, 9> kMatrixNames{"m00", "m01", "m02", "m10", "m11",
                                                       "m12", "m20", "m21", "m22"};
constexpr std::array<std::string_view, 4> kAxisAngleNames{"ax", "ay", "az", "angle"};
constexpr std::array<std::string_view, 3> kRotationVectorNames{"rx", "ry", "rz"};
constexpr std::array<std::string_view, 3> kEulerNames{"e1", "e2", "e3"};

Eigen::Quaterniond quaternionFromValues(std::span<const double> v)
{
    const Eigen::Quaterniond q(v[0], v[1], v[2], v[3]);
    const double squaredNorm = q.squaredNorm();
    if (squaredNorm == 0.0)
        throw std::invalid_argument("the quaternion is zero");
    if (std::abs(squaredNorm - 1.0) <= kUnitSquaredNormRounding)
        return q;
    const double norm = q.norm();
    if (!(std::abs(norm - 1.0) <= kQuaternionNormTolerance))
        throw std::invalid_argument("the quaternion has norm " + formatNumber(norm) + ", not within " +
                                    formatNumber(kQuaternionNormTolerance) + " of 1");
    return q.normalized();
}

Eigen::Quaterniond quaternionFromMatrixValues(std::span<const double> v)
{
    const Eigen::Matrix3d m = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(v.data());
    const double determinant = m.determinant();
    if (!(determinant > 0.0))
        throw std::invalid_argument("the matrix has determinant " + formatNumber(determinant) +
                                    "; a rotation has determinant 1");
    const double error = rotationMatrixError(m);
    if (!(error <= kRotationMatrixTolerance))
        throw std::invalid_argument("the matrix is not a rotation: MᵀM differs from the identity by " +
                                    formatNumber(error) + ", more than " + formatNumber(kRotationMatrixTolerance));
    return Eigen::Quaterniond(nearestRotation(m));
}

Eigen::Quaterniond quaternionFromAxisAngleValues(std::span<const double> v)
{
    const Eigen::Vector3d axis(v[0], v[1], v[2]);
    const double angle = v[3] * kRadiansPerDegree;
    // stableNorm: an axis such as (1e-200, 0, 0) is still a direction.
    const double length = axis.stableNorm();
    if (length == 0.0) {
        if (angle != 0.0)
            throw std::invalid_argument("the axis is zero but the angle is not");
        return Eigen::Quaterniond::Identity();
    }
    return quaternionFromAxisAngle({axis / length, angle});
}

Eigen::Vector3d vector3(std::span<const double> v) { return {v[0], v[1], v[2]}; }

void setQuaternionRow(Eigen::MatrixXd& values, Eigen::Index row, const Eigen::Quaterniond& q)
{
    values.row(row) << q.w(), q.x(), q.y(), q.z();
}

void setMatrixRow(Eigen::MatrixXd& values, Eigen::Index row, const Eigen::Quaterniond& q)
{
    const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> m = q.toRotationMatrix();
    values.row(row) = Eigen::Map<const Eigen::Matrix<double, 1, 9>>(m.data());
}

void setAxisAngleRow(Eigen::MatrixXd& values, Eigen::Index row, const Eigen::Quaterniond& q)
{
    const AxisAngle axisAngle = axisAngleFromQuaternion(q);
    values.row(row) << axisAngle.axis.transpose(), axisAngle.angle * kDegreesPerRadian;
}

} // namespace

std::string_view rotationColumnsName(RotationColumns columns) { return nameOf(kRotationColumnsNames, columns); }

std::span<const std::string_view> rotationColumnNames(RotationColumns columns)
{
    switch (columns) {
    case RotationColumns::Quaternion: return kQuaternionNames;
    case RotationColumns::Matrix: return kMatrixNames;
    case RotationColumns::AxisAngle: return kAxisAngleNames;
    case RotationColumns::RotationVector: return kRotationVectorNames;
    case RotationColumns::Euler: return kEulerNames;
    }
    throw std::invalid_argument("unknown rotation column set");
}

Eigen::Quaterniond rotationFromColumnValues(RotationColumns columns, std::span<const double> values,
                                            const EulerConvention& convention)
{
    if (values.size() != rotationColumnNames(columns).size())
        throw std::invalid_argument("wrong number of rotation values");
    switch (columns) {
    case RotationColumns::Quaternion: return quaternionFromValues(values);
    case RotationColumns::Matrix: return quaternionFromMatrixValues(values);
    case RotationColumns::AxisAngle: return quaternionFromAxisAngleValues(values);
    case RotationColumns::RotationVector: return quaternionFromRotationVector(vector3(values));
    case RotationColumns::Euler: return quaternionFromEulerAngles(vector3(values) * kRadiansPerDegree, convention);
    }
    throw std::invalid_argument("unknown rotation column set");
}

Eigen::MatrixXd rotationColumnValues(RotationColumns columns, const std::vector<Eigen::Quaterniond>& rotations,
                                     const EulerConvention& convention, std::optional<Eigen::Vector3d>* eulerCarry)
{
    const std::vector<Eigen::Vector3d> eulerAngles =
        columns == RotationColumns::Euler
            ? unwrappedEulerAngles(rotations, convention, eulerCarry ? *eulerCarry : std::nullopt)
            : std::vector<Eigen::Vector3d>{};
    if (eulerCarry && !eulerAngles.empty())
        *eulerCarry = eulerAngles.back();
    const auto rowCount = static_cast<Eigen::Index>(rotations.size());
    Eigen::MatrixXd values(rowCount, static_cast<Eigen::Index>(rotationColumnNames(columns).size()));
    for (Eigen::Index row = 0; row < rowCount; ++row) {
        const auto index = static_cast<std::size_t>(row);
        const Eigen::Quaterniond& q = rotations[index];
        switch (columns) {
        case RotationColumns::Quaternion: setQuaternionRow(values, row, q); break;
        case RotationColumns::Matrix: setMatrixRow(values, row, q); break;
        case RotationColumns::AxisAngle: setAxisAngleRow(values, row, q); break;
        case RotationColumns::RotationVector: values.row(row) = rotationVectorFromQuaternion(q).transpose(); break;
        case RotationColumns::Euler: values.row(row) = eulerAngles[index].transpose() * kDegreesPerRadian; break;
        }
    }
    return values;
}

} // namespace gyre::io
