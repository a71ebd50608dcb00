#include "app/viewport/skeleton.h"

#include <Eigen/Geometry>

namespace gyre::app {

namespace {

// A bone from `joint`'s origin along `localDirection` (in the joint's frame), `length` long; none for a
// length at rounding's scale, which has no direction. Returns whether there is one.
bool appendBone(std::vector<Bone>& bones, model::ObjectId joint, const Pose& jointPose,
                const Eigen::Vector3d& localDirection, double length)
{
    constexpr double kRounding = 1e-9; // relative to the distance from the origin
    if (!(length > kRounding * (1.0 + jointPose.position.norm())))
        return false;
    const Eigen::Quaterniond along = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), localDirection);
    bones.push_back({joint, Pose{jointPose.orientation * along, jointPose.position}, length});
    return true;
}

} // namespace

void Skeleton::update(const model::Scene& scene, const model::SceneMotion& motion, double time)
{
    const std::size_t count = scene.objects.size();
    model::findParentIndices(scene, parentIndex_);
    model::findJoints(scene, parentIndex_, joints_);

    bones_.clear();
    boneCounts_.assign(count, 0);
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t parent = parentIndex_[i];
        if (!joints_[i] || parent == i || !joints_[parent] || !scene.objects[parent].visible)
            continue;
        // The child's origin in its parent joint's frame: where the parent's bone points.
        const Pose parentPose = motion.worldPose(scene.objects[parent].id, time);
        const Eigen::Vector3d offset = parentPose.inverse().apply(motion.worldPose(scene.objects[i].id, time).position);
        boneCounts_[parent] += appendBone(bones_, scene.objects[parent].id, parentPose, offset, offset.norm()) ? 1 : 0;
    }
    for (std::size_t i = 0; i < count; ++i) {
        if (!joints_[i] || boneCounts_[i] > 0 || parentIndex_[i] == i || !scene.objects[i].visible)
            continue;
        // A leaf (a hand, an end site), or a joint whose child joints all sit at its own place: on
        // along its own offset, the way its parent's bone came in.
        const Pose pose = motion.worldPose(scene.objects[i].id, time);
        const Eigen::Vector3d offset = motion.parentWorldPose(scene.objects[i].id, time).inverse().apply(pose.position);
        boneCounts_[i] += appendBone(bones_, scene.objects[i].id, pose, offset, kLeafBoneFraction * offset.norm()) ? 1 : 0;
    }
    // Still without a bone (a root whose child joints sit at its place, as a BVH's hips often do):
    // one along its own x axis, so that it shows and can be clicked, kStubFraction of the mean bone.
    double total = 0.0;
    for (const Bone& bone : bones_)
        total += bone.length;
    const double stub = kStubFraction * (bones_.empty() ? 1.0 : total / double(bones_.size()));
    for (std::size_t i = 0; i < count; ++i)
        if (joints_[i] && boneCounts_[i] == 0 && scene.objects[i].visible) {
            const Pose pose = motion.worldPose(scene.objects[i].id, time);
            appendBone(bones_, scene.objects[i].id, pose, Eigen::Vector3d::UnitX(), stub);
        }
}

} // namespace gyre::app
