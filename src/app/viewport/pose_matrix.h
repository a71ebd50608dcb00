#pragma once
// A pose as the 4×4 matrix that the shaders read: x ↦ R·(scale·x) + p.

#include "core/pose.h"

#include <Eigen/Core>

#include <vector>

namespace gyre::app {

// The floats of one pose's matrix in an instance buffer.
inline constexpr int kFloatsPerMatrix = 16;

inline Eigen::Matrix4d poseMatrix(const Pose& pose, double scale = 1.0)
{
    Eigen::Matrix4d matrix = Eigen::Matrix4d::Identity();
    matrix.block<3, 3>(0, 0) = scale * pose.orientation.toRotationMatrix();
    matrix.block<3, 1>(0, 3) = pose.position;
    return matrix;
}

// Appends the pose's matrix, column-major as the shader reads it: kFloatsPerMatrix floats.
inline void appendPoseMatrix(std::vector<float>& out, const Pose& pose, double scale = 1.0)
{
    const Eigen::Matrix4f matrix = poseMatrix(pose, scale).cast<float>();
    out.insert(out.end(), matrix.data(), matrix.data() + matrix.size());
}

} // namespace gyre::app
