#include "app/viewport/sampled_trail.h"

#include "app/viewport/skeleton.h"
#include "core/subdivision.h"
#include "model/scene_joints.h"

#include <algorithm>
#include <optional>
#include <unordered_map>
#include <utility>

namespace gyre::app {

TrailSpacing TrailSpacing::clamped() const
{
    return {std::clamp(copies, 2, kMaxCopies), std::clamp(everyFrames, 0, kMaxEveryFrames)};
}

std::vector<double> trailTimes(const model::Scene& scene, const TrailSpacing& setting)
{
    const TrailSpacing spacing = setting.clamped();
    std::vector<double> times;
    if (!(scene.endTime > scene.startTime))
        return times;
    if (spacing.everyFrames == 0) {
        // t_i = start + (end − start)·i/(n − 1), i = 0 … n − 1.
        for (int i = 0; i < spacing.copies; ++i)
            times.push_back(scene.startTime + (scene.endTime - scene.startTime) * i / (spacing.copies - 1));
        return times;
    }
    const double step = spacing.everyFrames / scene.fps;
    const int before = spacing.copies / 2;
    for (int i = -before; i <= spacing.copies - before; ++i) {
        const double time = scene.currentTime + i * step;
        if (i != 0 && time >= scene.startTime && time <= scene.endTime)
            times.push_back(time);
    }
    return times;
}

std::vector<Pose> trailPoses(const model::SceneMotion& motion, model::ObjectId object, const std::vector<double>& times)
{
    std::vector<Pose> poses;
    poses.reserve(times.size());
    for (const double time : times)
        poses.push_back(motion.worldPose(object, time));
    return poses;
}

std::vector<ObjectTrail> trailPoses(const model::SceneMotion& motion, const std::vector<model::ObjectId>& objects,
                                    const std::vector<double>& times)
{
    std::vector<ObjectTrail> trails;
    trails.reserve(objects.size());
    for (const model::ObjectId object : objects)
        trails.push_back({object, trailPoses(motion, object, times)});
    return trails;
}

bool isScrewBenderTrack(const model::SceneObject* object)
{
    return object != nullptr && !object->track.keys.empty() && object->track.interpolation == InterpolationMethod::Screw;
}

TrailPlan planTrails(const model::Scene& scene, const std::vector<model::ObjectId>& selected, model::ObjectId active,
                     const TrailSpacing& spacing)
{
    // Each selected object's rank, the active one's first, found in one pass over the scene, then put in rank order.
    std::unordered_map<model::ObjectId, std::size_t> ranks;
    ranks.reserve(selected.size());
    for (std::size_t i = 0; i < selected.size(); ++i)
        ranks.emplace(selected[i], selected[i] == active ? 0 : i + 1);
    const std::vector<bool> joints = model::findJoints(scene);
    std::vector<std::pair<std::size_t, TrailPlan::Object>> ranked;
    ranked.reserve(selected.size());
    for (std::size_t index = 0; index < scene.objects.size(); ++index)
        if (const auto rank = ranks.find(scene.objects[index].id); rank != ranks.end())
            ranked.push_back({rank->second, {rank->first, index, joints[index]}});
    std::sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });

    TrailPlan plan;
    plan.objects.reserve(ranked.size());
    const std::size_t copies = static_cast<std::size_t>(spacing.clamped().copies);
    std::size_t left = TrailSpacing::kMaxTotalCopies;
    for (const auto& [rank, each] : ranked) {
        plan.objects.push_back(each);
        const model::SceneObject& object = scene.objects[each.index];
        const model::MotionTrack& track = object.track;
        const bool screw = isScrewBenderTrack(&object);
        if (screw && each.id == active) {
            plan.subdivided.push_back({each.id, track.subdivision.levels});
            continue;
        }
        if (object.empty || each.joint)
            continue;
        if (!screw) {
            if (copies <= left) {
                plan.sampled.push_back(each.id);
                left -= copies;
            }
            continue;
        }
        // The most levels, up to the track's, whose poses fit (n·2^L for a cycle, (n − 1)·2^L + 1 open).
        for (int levels = track.subdivision.levels; levels >= 0; --levels) {
            const std::optional<std::size_t> poses =
                subdividedPoseCount(track.keys.size(), levels, track.subdivision.cyclic);
            if (poses && *poses <= left) {
                plan.subdivided.push_back({each.id, levels});
                left -= *poses;
                break;
            }
        }
    }
    return plan;
}

} // namespace gyre::app
