#pragma once
// Assimp's single-precision vectors, quaternions and matrices to Eigen's doubles and back. Both use
// Hamilton quaternions w, x, y, z and matrices acting on column vectors (aiMatrix4x4 a1..a4 is row 0).

#include "core/pose.h"

#include <assimp/matrix4x4.h>
#include <assimp/quaternion.h>
#include <assimp/vector3.h>

#include <Eigen/Geometry>

namespace gyre::io::assimp_math {

inline Eigen::Vector3d toEigen(const aiVector3D& v) { return {v.x, v.y, v.z}; }

inline Eigen::Quaterniond toEigen(const aiQuaternion& q) { return {q.w, q.x, q.y, q.z}; }

inline aiVector3D toAssimp(const Eigen::Vector3d& v)
{
    return {static_cast<ai_real>(v.x()), static_cast<ai_real>(v.y()), static_cast<ai_real>(v.z())};
}

inline aiQuaternion toAssimp(const Eigen::Quaterniond& q)
{
    return {static_cast<ai_real>(q.w()), static_cast<ai_real>(q.x()), static_cast<ai_real>(q.y()),
            static_cast<ai_real>(q.z())};
}

// The homogeneous matrix [R p; 0 1] of a pose.
inline aiMatrix4x4 toAssimpMatrix(const Pose& pose)
{
    return aiMatrix4x4(aiVector3D(1, 1, 1), toAssimp(pose.orientation.normalized()), toAssimp(pose.position));
}

} // namespace gyre::io::assimp_math
