#pragma once
// The trail of a track that ScrewBender does not edit (onion skinning), for every selected object: copies of it at evenly
// spaced times of the motion the viewport draws (the document's one evaluated motion per track, composed
// up the parent chain), so a joint's copies stand where it really was while its parents moved. No OpenGL:
// tests check the poses against the motion.
//
// Spacing: by default the copies are spread over the scene's whole range, as ScrewBender's trail shows
// its whole motion; it then stays still while the motion plays. With every N frames the copies sit about
// the current frame, half before and half after (Blender's onion skinning), and follow it.

#include "core/pose.h"
#include "model/scene.h"
#include "model/scene_motion.h"

#include <cstddef>
#include <vector>

namespace gyre::app {

struct TrailSpacing {
    // The budget: at most this many copies an object, the setting clamped to it up front.
    static constexpr int kMaxCopies = 256;
    // And at most this many across the selected objects: the trails of the first maxObjects() of them (the active
    // one first), the rest none, decided up front from the setting (not from how many copies fall in the range).
    static constexpr int kMaxTotalCopies = 1024;
    static constexpr int kMaxEveryFrames = 1000;

    int copies = 16;
    int everyFrames = 0; // 0: spread over the scene's range; N: every N frames about the current frame

    // The setting within [2, kMaxCopies] and [0, kMaxEveryFrames].
    TrailSpacing clamped() const;
    // kMaxTotalCopies / the clamped copies: 64 objects at 16 copies, 4 at 256.
    std::size_t maxObjects() const;
};

// One object's copies.
struct ObjectTrail {
    model::ObjectId object = model::kNoObject;
    std::vector<Pose> poses;
};

// The copies' times, increasing, within the scene's range. Spread: `copies` times from the start to the
// end inclusive. Every N frames: copies/2 before the current time and the rest after, N/fps apart, the
// current time itself left out (the object stands there); those outside the range are dropped.
std::vector<double> trailTimes(const model::Scene& scene, const TrailSpacing& spacing);

// The object's world pose at each time.
std::vector<Pose> trailPoses(const model::SceneMotion& motion, model::ObjectId object, const std::vector<double>& times);

// Each object's world poses at the times, in the objects' order.
std::vector<ObjectTrail> trailPoses(const model::SceneMotion& motion, const std::vector<model::ObjectId>& objects,
                                    const std::vector<double>& times);

// The objects that get a sampled trail: of `selected`, `active` first and then the others in their order, leaving
// out `screwTrailObject` (whose trail is ScrewBender's subdivided motion), joints and empties (drawn as bones and
// axes: their centre paths say where they go) and objects the scene lacks, at most spacing.maxObjects() of them.
std::vector<model::ObjectId> sampledTrailObjects(const model::Scene& scene, const std::vector<model::ObjectId>& selected,
                                                 model::ObjectId active, model::ObjectId screwTrailObject,
                                                 const TrailSpacing& spacing);

} // namespace gyre::app
