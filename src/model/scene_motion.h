#pragma once
// Where a scene's objects are at any time: each object's track evaluated (TrackMotion) and composed
// up its parent chain, since a track gives the pose relative to the parent. Built once per change of
// the scene, not per frame; building subdivides every screw track, so the viewport builds it off the
// UI thread while the artist drags.
// Reparenting with the world pose kept asks it for the old and new parents' frames at each key.

#include "core/pose.h"
#include "model/scene.h"
#include "model/track_evaluation.h"

#include <unordered_map>

namespace gyre::model {

class SceneMotion {
public:
    SceneMotion() = default; // no objects
    explicit SceneMotion(const Scene& scene);

    // Whether the motion was built from a scene holding the object.
    bool contains(ObjectId id) const { return entries_.contains(id); }
    // The object's pose in the world at `time`; an unknown object is at the identity.
    Pose worldPose(ObjectId id, double time) const;
    // The world pose of the frame its track is relative to: its parent's world pose, or the identity.
    Pose parentWorldPose(ObjectId id, double time) const;

private:
    struct Entry {
        ObjectId parent = kNoObject;
        TrackMotion motion;
    };

    std::unordered_map<ObjectId, Entry> entries_;
};

} // namespace gyre::model
