#include "model/scene_motion.h"

namespace gyre::model {

SceneMotion::SceneMotion(const Scene& scene, const MotionOf& motionOf)
{
    for (const SceneObject& object : scene.objects)
        entries_.insert_or_assign(object.id, Entry{object.parent, motionOf(object)});
}

void SceneMotion::build() const
{
    for (const auto& [id, entry] : entries_)
        entry.motion->motion();
}

Pose SceneMotion::worldPose(ObjectId id, double time) const
{
    const auto found = entries_.find(id);
    if (found == entries_.end())
        return {};
    return parentWorldPose(id, time) * found->second.motion->motion().at(time);
}

Pose SceneMotion::parentWorldPose(ObjectId id, double time) const
{
    Pose world;
    // At most one step per object, so a broken hierarchy cannot loop forever.
    auto link = entries_.find(id);
    for (std::size_t steps = 0; link != entries_.end() && steps < entries_.size(); ++steps) {
        link = entries_.find(link->second.parent);
        if (link == entries_.end())
            break;
        world = link->second.motion->motion().at(time) * world;
    }
    return world;
}

} // namespace gyre::model
