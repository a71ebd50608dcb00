#include "app/viewport/sampled_trail.h"

#include "app/viewport/skeleton.h"
#include "core/subdivision.h"
#include "model/scene_joints.h"
#include "model/scene_queries.h"

#include <algorithm>
#include <optional>

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

TrailPlan planTrails(const model::Scene& scene, const std::vector<model::ObjectId>& selected, model::ObjectId active,
                     const TrailSpacing& spacing)
{
    std::vector<model::ObjectId> ordered;
    if (std::find(selected.begin(), selected.end(), active) != selected.end())
        ordered.push_back(active);
    for (const model::ObjectId id : selected)
        if (id != active)
            ordered.push_back(id);
    const std::vector<bool> joints = model::findJoints(scene);
    const std::size_t copies = static_cast<std::size_t>(spacing.clamped().copies);
    std::size_t left = TrailSpacing::kMaxTotalCopies;
    TrailPlan plan;
    for (const model::ObjectId id : ordered) {
        const model::SceneObject* object = model::findObject(scene, id);
        if (object == nullptr || object->empty || joints[static_cast<std::size_t>(object - scene.objects.data())])
            continue;
        const model::MotionTrack& track = object->track;
        if (track.keys.empty() || track.interpolation != InterpolationMethod::Screw) {
            if (copies <= left) {
                plan.sampled.push_back(id);
                left -= copies;
            }
            continue;
        }
        if (id == active) {
            plan.subdivided.push_back({id, track.subdivision.levels});
            continue;
        }
        // The most levels, up to the track's, whose poses fit (n·2^L for a cycle, (n − 1)·2^L + 1 open).
        for (int levels = track.subdivision.levels; levels >= 0; --levels) {
            const std::optional<std::size_t> poses =
                subdividedPoseCount(track.keys.size(), levels, track.subdivision.cyclic);
            if (poses && *poses <= left) {
                plan.subdivided.push_back({id, levels});
                left -= *poses;
                break;
            }
        }
    }
    return plan;
}

} // namespace gyre::app
