#include "model/skinning.h"

#include <Eigen/Geometry>

namespace gyre::model {

std::vector<Eigen::Matrix4f> jointMatrices(const Skin& skin, ObjectId object, const SceneMotion& motion, double time)
{
    // M⁻¹ · W_j composed as poses in double precision, then B_j in the mesh's single precision.
    const Pose toObject = motion.worldPose(object, time).inverse();
    std::vector<Eigen::Matrix4f> joints;
    joints.reserve(skin.joints.size());
    for (std::size_t j = 0; j < skin.joints.size(); ++j) {
        if (motion.contains(skin.joints[j])) {
            const Pose relative = toObject * motion.worldPose(skin.joints[j], time);
            const Eigen::Matrix4d matrix = (Eigen::Translation3d(relative.position) * relative.orientation).matrix();
            joints.push_back(matrix.cast<float>() * skin.inverseBinds[j]);
        } else {
            joints.push_back(Eigen::Matrix4f::Identity());
        }
    }
    return joints;
}

Eigen::Vector3f skinnedPosition(const Skin& skin, const std::vector<Eigen::Matrix4f>& joints, std::size_t vertex,
                                const Eigen::Vector3f& position)
{
    const Eigen::Vector4f& weights = skin.vertexWeights[vertex];
    const Eigen::Vector4f point = position.homogeneous();
    Eigen::Vector4f moved = (1.0F - weights.sum()) * point;
    for (int k = 0; k < 4; ++k)
        moved += weights[k] * (joints[skin.vertexJoints[vertex][k]] * point);
    return moved.head<3>();
}

std::vector<Eigen::Vector3f> skinnedPositions(const Mesh& mesh, const std::vector<Eigen::Matrix4f>& joints)
{
    if (mesh.skin.empty())
        return mesh.positions;
    std::vector<Eigen::Vector3f> positions(mesh.positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v)
        positions[v] = skinnedPosition(mesh.skin, joints, v, mesh.positions[v]);
    return positions;
}

} // namespace gyre::model
