#pragma once
// One evaluated motion per track (issue 18). Building a TrackMotion subdivides a screw track, which
// grows with 2^levels; every view and job that shows or reads the selected track used to build its
// own. The document keeps one SharedTrackMotion per object in a MotionCache, forgets it when the
// object's track changes, and hands the same one to everyone until then.
//
// A SharedTrackMotion is made on the UI thread, cheaply (the track is copied; its keys are shared,
// shared_vector.h), and built on the first call of motion() by whichever thread makes it, typically
// a view's worker: the UI thread does not pay for the subdivision. Other callers, on any thread, wait
// for that one build and share it. Once built it never changes, so it may be read from any thread.

#include "model/scene.h"
#include "model/track_evaluation.h"

#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <unordered_map>

namespace gyre::model {

class SharedTrackMotion {
public:
    // `builds`, if not null, counts the builds (MotionCache::builds). `body` is what a ballistic track flies
    // (flightBodyOf), under `gravity` (the scene's).
    explicit SharedTrackMotion(MotionTrack track, std::shared_ptr<std::atomic<std::size_t>> builds = nullptr,
                               const MassProperties& body = {}, const Gravity& gravity = {});

    // The track as it was when this was made.
    const MotionTrack& track() const { return track_; }
    // The track's TrackMotion, built by the first call. Throws std::invalid_argument where
    // TrackMotion does (a subdivision too large to hold), at every call, building only once.
    const TrackMotion& motion() const;
    // The motion of the track without its applied fit (withoutFit, fit_input.h: the views' "before
    // the fit"), built by the first call as motion() is; motion() itself for a track without a fit.
    const TrackMotion& motionWithoutFit() const;

private:
    // A TrackMotion built once, by the first thread that asks.
    struct Lazy {
        std::once_flag built;
        std::optional<TrackMotion> motion;
        std::exception_ptr error;
    };

    // `make` builds the motion, within the one build: a call after it copies nothing.
    const TrackMotion& build(Lazy& lazy, const std::function<TrackMotion()>& make) const;

    MotionTrack track_;
    std::shared_ptr<std::atomic<std::size_t>> builds_;
    MassProperties body_;
    Gravity gravity_;
    mutable Lazy motion_;
    mutable Lazy withoutFit_;
};

// The SharedTrackMotion of each object, made on first request. Used on one thread (the document's);
// what it hands out may go anywhere.
class MotionCache {
public:
    // The object's motion under `gravity`: the one made for it since it was last forgotten, else a new one.
    std::shared_ptr<const SharedTrackMotion> motion(const SceneObject& object, const Gravity& gravity);
    // The object's track changed or it is gone.
    void forget(ObjectId id) { motions_.erase(id); }
    // A new scene, or new gravity.
    void clear() { motions_.clear(); }
    // How many motions were built, on any thread: the hook tests count rebuilds with.
    std::size_t builds() const { return builds_->load(); }

private:
    std::unordered_map<ObjectId, std::shared_ptr<const SharedTrackMotion>> motions_;
    std::shared_ptr<std::atomic<std::size_t>> builds_ = std::make_shared<std::atomic<std::size_t>>(0);
};

} // namespace gyre::model
