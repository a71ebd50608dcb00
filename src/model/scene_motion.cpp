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

std::vector<Pose> SceneMotion::worldPoses(const std::vector<ObjectId>& ids, double time) const
{
    std::unordered_map<ObjectId, Pose> world; // of every object met so far, ancestors included
    std::vector<ObjectId> chain;
    std::vector<Pose> poses;
    poses.reserve(ids.size());
    for (const ObjectId id : ids) {
        // Up from the object to the first ancestor whose world pose is known, or past the root; at most one step
        // per object, as parentWorldPose.
        chain.clear();
        Pose frame;
        for (auto link = entries_.find(id); link != entries_.end() && chain.size() < entries_.size();
             link = entries_.find(link->second.parent)) {
            if (const auto known = world.find(link->first); known != world.end()) {
                frame = known->second;
                break;
            }
            chain.push_back(link->first);
        }
        // Then down again: each one's world pose is its parent's times its track's pose.
        for (auto object = chain.rbegin(); object != chain.rend(); ++object) {
            frame = frame * entries_.at(*object).motion->motion().at(time);
            world.insert_or_assign(*object, frame);
        }
        poses.push_back(frame); // the identity for an unknown object
    }
    return poses;
}

} // namespace gyre::model
