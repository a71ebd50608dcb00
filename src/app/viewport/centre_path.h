#pragma once
// The selected objects' centre paths (View ▸ Trajectory): where each one's mesh centre (a joint's origin, where
// its bones meet) is in the world over the scene's range, one point a frame, from the motion the viewport draws.
// They are sampled off the UI thread on a job of their own (drawn_motion.h); their budget, up front, bounds the
// worker's memory and time: at most kMaxPathObjects paths (the active object's first), each of at most
// kMaxPathSamples + 1 points, so at most 64 × 4097 = 262,208 points (3 MB of floats) and as many track
// evaluations a request (each ancestor's track evaluated once a time, however many selected objects hang below
// it); a longer scene is sampled more sparsely than once a frame. No OpenGL: tests check the points against the
// motion, and tst_drawn_motion prints what the whole budget costs.

#include "app/viewport/sampled_trail.h"
#include "model/scene.h"
#include "model/scene_motion.h"

#include <Eigen/Core>

#include <atomic>
#include <cstddef>
#include <memory>
#include <vector>

namespace gyre::app {

inline constexpr int kMaxPathSamples = 4096;
inline constexpr std::size_t kMaxPathObjects = 64;

// One object whose path is sampled.
struct PathObject {
    model::ObjectId object = model::kNoObject;
    // The mesh whose bounding box's centre the path follows (the drawn one: its own, or the default shape or an
    // empty's hull, held without ownership); null for a joint, whose path is its origin's.
    std::shared_ptr<const model::Mesh> mesh;
};

// The first kMaxPathObjects of the plan's selected objects (the active one first, then in the selection's order).
std::vector<PathObject> pathObjects(const model::Scene& scene, const TrailPlan& plan);

// One time a frame over the scene's range, both ends included, at most kMaxPathSamples + 1 of them evenly
// spread; none for an empty range.
std::vector<double> pathTimes(const model::Scene& scene);

// Each object's path: the world position of its centre at each time, the objects' world poses found together
// at each time (SceneMotion::worldPoses). Returns early, with paths cut short, once `stop` is set.
std::vector<std::vector<Eigen::Vector3f>> centrePaths(const model::SceneMotion& motion, const std::vector<PathObject>& objects,
                                                      const std::vector<double>& times, const std::atomic<bool>& stop);

} // namespace gyre::app
