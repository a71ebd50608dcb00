#include "model/scene_queries.h"

#include <algorithm>

namespace gyre::model {

const SceneObject* findObject(const Scene& scene, ObjectId id)
{
    const auto found = std::find_if(scene.objects.begin(), scene.objects.end(),
                                    [id](const SceneObject& object) { return object.id == id; });
    return found == scene.objects.end() ? nullptr : &*found;
}

SceneObject* findObject(Scene& scene, ObjectId id)
{
    return const_cast<SceneObject*>(findObject(static_cast<const Scene&>(scene), id));
}

std::optional<std::size_t> objectIndex(const Scene& scene, ObjectId id)
{
    if (const SceneObject* object = findObject(scene, id))
        return static_cast<std::size_t>(object - scene.objects.data());
    return std::nullopt;
}

bool isAncestor(const Scene& scene, ObjectId ancestor, ObjectId object)
{
    const SceneObject* current = findObject(scene, object);
    for (std::size_t steps = 0; current && steps < scene.objects.size(); ++steps) {
        if (current->parent == kNoObject)
            return false;
        if (current->parent == ancestor)
            return true;
        current = findObject(scene, current->parent);
    }
    return false;
}

std::vector<ObjectId> subtreeOf(const Scene& scene, ObjectId root)
{
    std::vector<ObjectId> subtree;
    for (const SceneObject& object : scene.objects)
        if (object.id == root || isAncestor(scene, root, object.id))
            subtree.push_back(object.id);
    return subtree;
}

std::vector<ObjectId> objectOrder(const Scene& scene)
{
    std::vector<ObjectId> order;
    order.reserve(scene.objects.size());
    for (const SceneObject& object : scene.objects)
        order.push_back(object.id);
    return order;
}

std::size_t keyframeCount(const Scene& scene)
{
    std::size_t count = 0;
    for (const SceneObject& object : scene.objects)
        count += object.track.keys.size();
    return count;
}

} // namespace gyre::model
