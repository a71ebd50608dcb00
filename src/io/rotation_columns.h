#pragma once
// The sets of columns that can hold a rotation in a pose file, and the conversions between their
// values and quaternions. Angles the user reads or writes are in degrees, except in a rotation
// vector, whose length is its angle in radians.

#include "core/euler_angles.h"
#include "core/name_table.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace gyre::io {

enum class RotationColumns {
    Quaternion,     // qw,qx,qy,qz
    Matrix,         // m00,m01,m02,m10,…,m22: row-major, v′ = M·v
    AxisAngle,      // ax,ay,az,angle: any nonzero axis, angle in degrees
    RotationVector, // rx,ry,rz: axis times angle in radians
    Euler,          // e1,e2,e3: degrees, e1 about the first axis of the convention's order
};

// Every set, with the name that --to and messages use for it.
inline constexpr NameTable<RotationColumns, 5> kRotationColumnsNames{{
    {RotationColumns::Quaternion, "quat"},
    {RotationColumns::Matrix, "matrix"},
    {RotationColumns::AxisAngle, "axis-angle"},
    {RotationColumns::RotationVector, "rotvec"},
    {RotationColumns::Euler, "euler"},
}};

// How far a quaternion's norm may be from 1 and still be read (and then normalised): values written
// with a few digits drift by far less, while a scaled or garbled quaternion is caught.
inline constexpr double kQuaternionNormTolerance = 0.01;
// How far a matrix may be from orthonormal, max |(MᵀM − I)ᵢⱼ| (core rotationMatrixError), and still
// be read (and then projected onto the nearest rotation).
inline constexpr double kRotationMatrixTolerance = 0.01;

// The set's name on the command line: "quat", "matrix", "axis-angle", "rotvec" or "euler".
std::string_view rotationColumnsName(RotationColumns columns);

// The header names of a set, in the order they are written.
std::span<const std::string_view> rotationColumnNames(RotationColumns columns);

// The unit quaternion that a set's values, in rotationColumnNames order, describe. Throws
// std::invalid_argument saying what is wrong: a zero quaternion or one whose norm is off by more
// than the tolerance, a matrix that is a reflection or not orthonormal, a zero axis with a nonzero
// angle. A quaternion that is unit to rounding is kept exactly as given, so that files round-trip
// bit for bit.
Eigen::Quaterniond rotationFromColumnValues(RotationColumns columns, std::span<const double> values,
                                            const EulerConvention& convention);

// The values of a set's columns for a sequence of rotations: one row per rotation, columns in
// rotationColumnNames order. Euler angles are unwrapped along the sequence (core's Euler filter) so
// that they have no 2π jumps. Where `eulerCarry` is given, the unwrapping goes on from the angles it
// holds (radians) and it is left holding the last rotation's, so that a long sequence converted
// block by block reads as one.
Eigen::MatrixXd rotationColumnValues(RotationColumns columns, const std::vector<Eigen::Quaterniond>& rotations,
                                     const EulerConvention& convention,
                                     std::optional<Eigen::Vector3d>* eulerCarry = nullptr);

} // namespace gyre::io
