#include "app/viewport/centre_path.h"

#include "app/viewport/default_shape.h"

#include <algorithm>
#include <cmath>

namespace gyre::app {

namespace {

// The centre of the mesh's bounding box, in its own frame.
Eigen::Vector3d meshCentre(const model::Mesh& mesh)
{
    if (mesh.positions.empty())
        return Eigen::Vector3d::Zero();
    Eigen::Vector3f low = mesh.positions.front();
    Eigen::Vector3f high = low;
    for (const Eigen::Vector3f& position : mesh.positions) {
        low = low.cwiseMin(position);
        high = high.cwiseMax(position);
    }
    return (0.5F * (low + high)).cast<double>();
}

} // namespace

std::vector<PathObject> pathObjects(const model::Scene& scene, const TrailPlan& plan)
{
    std::vector<PathObject> objects;
    objects.reserve(std::min(plan.objects.size(), kMaxPathObjects));
    for (const TrailPlan::Object& each : plan.objects) {
        if (objects.size() == kMaxPathObjects)
            break;
        if (each.joint) {
            objects.push_back({each.id, nullptr});
            continue;
        }
        // The default shapes live as long as the program: an empty owner (the aliasing constructor) holds them.
        const model::SceneObject& object = scene.objects[each.index];
        objects.push_back({each.id, object.mesh ? object.mesh
                                                : std::shared_ptr<const model::Mesh>(
                                                      std::shared_ptr<const model::Mesh>(), &displayMesh(object))});
    }
    return objects;
}

std::vector<double> pathTimes(const model::Scene& scene)
{
    std::vector<double> times;
    if (!(scene.endTime > scene.startTime))
        return times;
    const double frames = std::ceil((scene.endTime - scene.startTime) * scene.fps);
    const int samples = static_cast<int>(std::clamp(frames, 1.0, double(kMaxPathSamples))) + 1;
    times.reserve(static_cast<std::size_t>(samples));
    // t_i = start + (end − start)·i/(n − 1).
    for (int i = 0; i < samples; ++i)
        times.push_back(scene.startTime + (scene.endTime - scene.startTime) * i / (samples - 1));
    return times;
}

std::vector<std::vector<Eigen::Vector3f>> centrePaths(const model::SceneMotion& motion, const std::vector<PathObject>& objects,
                                                      const std::vector<double>& times, const std::atomic<bool>& stop)
{
    std::vector<model::ObjectId> ids;
    std::vector<Eigen::Vector3d> centres;
    std::vector<std::vector<Eigen::Vector3f>> paths(objects.size());
    for (const PathObject& object : objects) {
        ids.push_back(object.object);
        centres.push_back(object.mesh ? meshCentre(*object.mesh) : Eigen::Vector3d::Zero());
        paths[ids.size() - 1].reserve(times.size());
    }
    for (const double time : times) {
        if (stop)
            break;
        const std::vector<Pose> poses = motion.worldPoses(ids, time);
        for (std::size_t i = 0; i < poses.size(); ++i)
            paths[i].push_back(poses[i].apply(centres[i]).cast<float>());
    }
    return paths;
}

} // namespace gyre::app
