#pragma once
// Where a scene's objects are at any time: each object's track evaluated (TrackMotion) and composed
// up its parent chain, since a track gives the pose relative to the parent. Made once per change of
// the scene, not per frame. It holds each track's SharedTrackMotion (motion_cache.h): made from the
// document's, it shares the motions of the tracks that did not change, and build() builds the rest,
// which the viewport does off the UI thread while the artist drags.
// Reparenting with the world pose kept asks it for the old and new parents' frames at each key.

#include "core/pose.h"
#include "model/motion_cache.h"
#include "model/scene.h"

#include <functional>
#include <memory>
#include <unordered_map>
#include <vector>

namespace gyre::model {

class SceneMotion {
public:
    // The motion of an object's track in this scene.
    using MotionOf = std::function<std::shared_ptr<const SharedTrackMotion>(const SceneObject&)>;

    SceneMotion() = default; // no objects
    // The scene's objects, each moving by motionOf(object), typically the document's motion().
    SceneMotion(const Scene& scene, const MotionOf& motionOf);

    // Builds every track's motion not built yet, so that evaluating then only evaluates. Throws
    // std::invalid_argument where TrackMotion does.
    void build() const;

    // Whether the motion was built from a scene holding the object.
    bool contains(ObjectId id) const { return entries_.contains(id); }
    // The object's pose in the world at `time`; an unknown object is at the identity.
    Pose worldPose(ObjectId id, double time) const;
    // The world pose of the frame its track is relative to: its parent's world pose, or the identity.
    Pose parentWorldPose(ObjectId id, double time) const;
    // worldPose of each of `ids`, each track evaluated once however many of them share it as an ancestor, so
    // that the joints of a deep hierarchy cost a track evaluation each, not one per level below them.
    std::vector<Pose> worldPoses(const std::vector<ObjectId>& ids, double time) const;

private:
    struct Entry {
        ObjectId parent = kNoObject;
        std::shared_ptr<const SharedTrackMotion> motion;
    };

    std::unordered_map<ObjectId, Entry> entries_;
};

} // namespace gyre::model
