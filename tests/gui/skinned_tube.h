#pragma once
// Skinned scenes made in code for the viewport's tests and the user guide's picture.

#include "model/scene.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

namespace gyre::test {

// An object with one key at `position`, unturned.
inline model::SceneObject sceneObject(model::ObjectId id, const char* name, model::ObjectId parent, const Eigen::Vector3d& position,
                                      std::shared_ptr<const model::Mesh> mesh)
{
    model::SceneObject result{id, QString::fromLatin1(name), std::move(mesh), parent, {}, true};
    result.track.keys = {model::Keyframe{0.0, Pose{Eigen::Quaterniond::Identity(), position}, true}};
    return result;
}

// A chain of `joints` joints `spacing` apart along x, each turned `bend` radians about z from its
// parent, and a tube of `rings` rings of 64 vertices along it, radius half the spacing, skinned to the
// chain: each vertex weighs on the two joints it lies between. Ids 1 to `joints` are the joints, the
// tube's object comes last.
inline model::Scene skinnedTube(int joints, int rings, double spacing, double bend)
{
    constexpr int kAround = 64;
    model::Scene scene;
    const double length = spacing * (joints - 1);
    auto tube = std::make_shared<model::Mesh>();
    model::Skin& skin = tube->skin;
    for (int j = 0; j < joints; ++j) {
        const auto id = static_cast<model::ObjectId>(j + 1);
        model::SceneObject joint = sceneObject(id, "Joint", j == 0 ? model::kNoObject : id - 1,
                                               Eigen::Vector3d(j == 0 ? 0.0 : spacing, 0, 0), nullptr);
        joint.track.keys.edit()[0].pose.orientation = Eigen::AngleAxisd(bend, Eigen::Vector3d::UnitZ());
        scene.objects.push_back(joint);
        skin.joints.push_back(id);
        Eigen::Matrix4f inverseBind = Eigen::Matrix4f::Identity();
        inverseBind(0, 3) = -static_cast<float>(spacing * j);
        skin.inverseBinds.push_back(inverseBind);
    }
    for (int ring = 0; ring < rings; ++ring) {
        const double x = length * ring / (rings - 1);
        const double along = x / spacing;
        const auto before = static_cast<std::uint16_t>(std::min(int(along), joints - 2));
        const auto onNext = static_cast<float>(along - before);
        for (int k = 0; k < kAround; ++k) {
            const double angle = 2 * std::numbers::pi * k / kAround;
            tube->positions.emplace_back(float(x), float(0.5 * spacing * std::cos(angle)), float(0.5 * spacing * std::sin(angle)));
            skin.vertexJoints.push_back({before, std::uint16_t(before + 1), 0, 0});
            skin.vertexWeights.emplace_back(1.0F - onNext, onNext, 0.0F, 0.0F);
            if (ring + 1 < rings) {
                const auto a = std::uint32_t(ring * kAround + k);
                const auto b = std::uint32_t(ring * kAround + (k + 1) % kAround);
                tube->indices.insert(tube->indices.end(), {a, b, b + kAround, a, b + kAround, a + kAround});
            }
        }
    }
    const auto tubeId = static_cast<model::ObjectId>(joints + 1);
    scene.objects.push_back(sceneObject(tubeId, "Tube", model::kNoObject, Eigen::Vector3d::Zero(), tube));
    scene.nextObjectId = tubeId + 1;
    return scene;
}

} // namespace gyre::test
