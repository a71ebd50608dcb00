#include "model/commands/object_fields.h"

#include "model/scene_queries.h"

#include <algorithm>

namespace gyre::model {

SceneObject& objectIn(Scene& scene, ObjectId id) { return *findObject(scene, id); }
const SceneObject& objectIn(const Scene& scene, ObjectId id) { return *findObject(scene, id); }

ParentField::Value ParentField::get(const Scene& scene, const FieldTarget& target)
{
    return {objectIn(scene, target.object).parent, objectOrder(scene)};
}

void ParentField::set(Scene& scene, const FieldTarget& target, Value value)
{
    objectIn(scene, target.object).parent = value.first;
    const std::vector<ObjectId>& order = value.second;
    const auto rank = [&order](const SceneObject& object) {
        return std::find(order.begin(), order.end(), object.id) - order.begin();
    };
    std::stable_sort(scene.objects.begin(), scene.objects.end(),
                     [&rank](const SceneObject& a, const SceneObject& b) { return rank(a) < rank(b); });
}

ParentAndKeysField::Value ParentAndKeysField::get(const Scene& scene, const FieldTarget& target)
{
    return {ParentField::get(scene, target), objectIn(scene, target.object).track.keys};
}

void ParentAndKeysField::set(Scene& scene, const FieldTarget& target, Value value)
{
    // The keys first: ParentField::set reorders the objects.
    objectIn(scene, target.object).track.keys = std::move(value.second);
    ParentField::set(scene, target, std::move(value.first));
}

TimeRangeField::Value TimeRangeField::get(const Scene& scene, const FieldTarget&)
{
    return {scene.fps, scene.startTime, scene.endTime};
}

void TimeRangeField::set(Scene& scene, const FieldTarget&, Value value)
{
    scene.fps = value.fps;
    scene.startTime = value.startTime;
    scene.endTime = value.endTime;
}

} // namespace gyre::model
