#pragma once
// The bones of a scene's joint hierarchies (the joints of model/scene_joints.h): the viewport draws
// joints as bones instead of the default shape, and a click on a bone selects its joint.
// No OpenGL, so that tests can check the bones and picking on their own.

#include "core/pose.h"
#include "model/scene.h"
#include "model/scene_joints.h"
#include "model/scene_motion.h"

#include <cstddef>
#include <vector>

namespace gyre::app {

// An octahedral bone of one joint (its head), pointing along the pose's x axis, boneMesh() scaled
// by `length`. It turns with its joint: its direction is fixed in the joint's frame.
struct Bone {
    model::ObjectId joint = model::kNoObject;
    Pose pose;
    double length = 0.0;
    Eigen::Vector3d head() const { return pose.position; }
    Eigen::Vector3d tail() const { return pose.apply(Eigen::Vector3d(length, 0.0, 0.0)); }
};

class Skeleton {
public:
    // A leaf joint's bone continues its parent's: along its own offset, this fraction of its length.
    static constexpr double kLeafBoneFraction = 0.5;
    // A joint that has no bone otherwise gets one along its x axis, this fraction of the mean bone.
    static constexpr double kStubFraction = 0.5;

    // Finds the joints and places their bones at `time`; keeps its storage from call to call.
    void update(const model::Scene& scene, const model::SceneMotion& motion, double time);

    // Whether scene.objects[index] is a joint, as of the last update.
    bool isJoint(std::size_t index) const { return index < joints_.size() && joints_[index]; }
    // A bone from each joint to each of its child joints away from its origin; one on from each
    // joint without such, along its offset; one along the x axis of each joint that still has none.
    // A hidden joint (SceneObject::visible) has none: its bones hide with it.
    const std::vector<Bone>& bones() const { return bones_; }

private:
    std::vector<bool> joints_;
    std::vector<Bone> bones_;
    std::vector<std::size_t> parentIndex_; // of each object, or its own index for a root
    std::vector<int> boneCounts_; // of each object
};

} // namespace gyre::app
