#pragma once
// Linear blend skinning, the formula the viewport's vertex shader (resources/shaders/mesh.vert) runs
// and the viewport's picking runs on the CPU. A position v of a skinned mesh, held by an object whose
// world pose is M, goes in that object's frame to
//   v' = Σ_k w_k · J_{j_k} · v + (1 − Σ_k w_k) · v,   J_j = M⁻¹ · W_j · B_j,
// with W_j the joint's world pose now and B_j its inverse bind matrix (Skin, scene.h). Drawn at M, the
// point is Σ_k w_k · W_j · B_j · v in the world: the object's own pose is applied once, whether or not
// it moves the joints. In the bind pose W_j = M · B_j⁻¹, so J_j is the identity and the mesh is as modelled.

#include "core/pose.h"
#include "model/scene.h"
#include "model/scene_motion.h"

#include <Eigen/Core>

#include <stdexcept>
#include <string>
#include <vector>

namespace gyre::model {

// J_j for each joint of `skin`, held by `object`, at `time`, from the shared motion. A joint the
// motion does not hold (an object deleted since) gets the identity: its part of the mesh stays as
// modelled, following the object.
std::vector<Eigen::Matrix4f> jointMatrices(const Skin& skin, ObjectId object, const SceneMotion& motion, double time);

// v' of position `vertex` of the skin, whose position is `position`, under `joints` (jointMatrices).
Eigen::Vector3f skinnedPosition(const Skin& skin, const std::vector<Eigen::Matrix4f>& joints, std::size_t vertex,
                                const Eigen::Vector3f& position);
// Every position of `mesh` skinned; the mesh's own positions when it has no skin.
std::vector<Eigen::Vector3f> skinnedPositions(const Mesh& mesh, const std::vector<Eigen::Matrix4f>& joints);

// `skin` with each joint id replaced by idOf(id); throws std::invalid_argument naming a joint that
// idOf cannot map (it returns kNoObject for those): reading and importing keep no dangling joint.
template <class IdOf>
Skin skinWithJoints(Skin skin, IdOf idOf)
{
    for (ObjectId& joint : skin.joints) {
        const ObjectId mapped = idOf(joint);
        if (mapped == kNoObject)
            throw std::invalid_argument("the skin's joint " + std::to_string(joint) + " is not an object of the scene");
        joint = mapped;
    }
    return skin;
}

} // namespace gyre::model
