#include "app/viewport/sampled_trail.h"

#include <algorithm>

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

} // namespace gyre::app
