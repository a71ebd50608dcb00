#include "model/scene_joints.h"

#include <unordered_map>
#include <unordered_set>

namespace gyre::model {

void findParentIndices(const Scene& scene, std::vector<std::size_t>& parents)
{
    const std::size_t count = scene.objects.size();
    std::unordered_map<ObjectId, std::size_t> indexOf;
    indexOf.reserve(count);
    parents.assign(count, 0);
    for (std::size_t i = 0; i < count; ++i) {
        const SceneObject& object = scene.objects[i];
        indexOf.emplace(object.id, i);
        const auto parent = indexOf.find(object.parent); // parents come first
        parents[i] = parent != indexOf.end() ? parent->second : i;
    }
}

void findJoints(const Scene& scene, const std::vector<std::size_t>& parents, std::vector<bool>& joints)
{
    // An empty is a frame on its own, never a joint, and makes none of its parent or children.
    const auto meshless = [&](std::size_t i) { return scene.objects[i].mesh == nullptr && !scene.objects[i].empty; };
    std::unordered_set<ObjectId> skinJoints;
    for (const SceneObject& object : scene.objects)
        if (object.mesh)
            skinJoints.insert(object.mesh->skin.joints.begin(), object.mesh->skin.joints.end());
    joints.assign(scene.objects.size(), false);
    for (std::size_t i = 0; i < joints.size(); ++i) {
        if (meshless(i) && skinJoints.contains(scene.objects[i].id))
            joints[i] = true;
        const std::size_t parent = parents[i];
        if (parent != i && meshless(i) && meshless(parent))
            joints[i] = joints[parent] = true;
    }
}

std::vector<bool> findJoints(const Scene& scene)
{
    std::vector<std::size_t> parents;
    findParentIndices(scene, parents);
    std::vector<bool> joints;
    findJoints(scene, parents, joints);
    return joints;
}

} // namespace gyre::model
