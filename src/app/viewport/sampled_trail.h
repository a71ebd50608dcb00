#pragma once
// The trail of a track that ScrewBender does not edit (onion skinning), for every selected object: copies of it at evenly
// spaced times of the motion the viewport draws (the document's one evaluated motion per track, composed
// up the parent chain), so a joint's copies stand where it really was while its parents moved. No OpenGL:
// tests check the poses against the motion.
//
// Spacing: by default the copies are spread over the scene's whole range, as ScrewBender's trail shows
// its whole motion; it then stays still while the motion plays. With every N frames the copies sit about
// the current frame, half before and half after (Blender's onion skinning), and follow it.
//
// A screw track's trail is its polyscrew subdivided (ScrewBender's stroboscope, jobs/subdivision_job.h), not
// sampled: planTrails says which selected object gets which, within the budget below.

#include "core/pose.h"
#include "model/scene.h"
#include "model/scene_motion.h"

#include <cstddef>
#include <vector>

namespace gyre::app {

struct TrailSpacing {
    // The budget: at most this many copies an object's sampled trail, the setting clamped to it up front.
    static constexpr int kMaxCopies = 256;
    // And at most this many across the selected objects' trails, the active screw track's left out (planTrails):
    // with sampled trails alone, those of the first kMaxTotalCopies / copies of them (the active one first: 64
    // objects at 16 copies, 4 at 256), the rest none, decided up front from the setting (not from how many copies
    // fall in the range).
    static constexpr int kMaxTotalCopies = 1024;
    static constexpr int kMaxEveryFrames = 1000;

    int copies = 16;
    int everyFrames = 0; // 0: spread over the scene's range; N: every N frames about the current frame

    // The setting within [2, kMaxCopies] and [0, kMaxEveryFrames].
    TrailSpacing clamped() const;
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

// Whether ScrewBender edits the object's track: a screw track with keys. Its control poses are drawn and dragged,
// and its trail is its subdivided polyscrew. Another track's keys may all sit in one place (a spinning top's 85
// keys at its tip), where control poses would only hide the object. False for null.
bool isScrewBenderTrack(const model::SceneObject* object);

// Which selected object gets which trail, decided up front from the settings and the key counts (not from the
// poses). The active object's screw track gets its whole subdivision, as ScrewBender edits it, whatever the object
// (a joint's or an empty's too: its control poses are drawn and dragged like any other's): its size is the track's
// own budget (model::kMaxSubdividedPoses, checked whenever the track is set). The other selected objects, the
// active one first and then in the selection's order, share TrailSpacing::kMaxTotalCopies: a screw track takes its
// subdivision's pose count at its levels, or at the most levels that fit what is left (a coarser stroboscope of the
// same motion, down to its control poses), any other object spacing.copies (clamped); one whose trail does not fit
// what is left gets none. Other joints and empties (drawn as bones and axes: their centre paths say where they go)
// and objects the scene lacks get none.
struct TrailPlan {
    // A selected object the scene holds.
    struct Object {
        model::ObjectId id = model::kNoObject;
        std::size_t index = 0; // in scene.objects
        bool joint = false;    // model::findJoints
    };
    struct Subdivided {
        model::ObjectId object = model::kNoObject;
        int levels = 0; // the track's, or fewer
        bool operator==(const Subdivided&) const = default;
    };
    // The selected objects the scene holds, the active one first and then in the selection's order: the order in
    // which the trails share their budget, and the centre paths theirs (centre_path.h).
    std::vector<Object> objects;
    std::vector<Subdivided> subdivided; // the screw tracks, in the objects' order
    std::vector<model::ObjectId> sampled;
};
// The scene is searched once, whatever the number of selected objects.
TrailPlan planTrails(const model::Scene& scene, const std::vector<model::ObjectId>& selected, model::ObjectId active,
                     const TrailSpacing& spacing);

} // namespace gyre::app
