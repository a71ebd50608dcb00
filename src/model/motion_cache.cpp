#include "model/motion_cache.h"

#include <utility>

namespace gyre::model {

SharedTrackMotion::SharedTrackMotion(MotionTrack track, std::shared_ptr<std::atomic<std::size_t>> builds)
    : track_(std::move(track))
    , builds_(std::move(builds))
{
}

const TrackMotion& SharedTrackMotion::motion() const
{
    // call_once runs the build once even when threads ask together; a build that throws is kept as
    // its exception, so a refused track is not built again at every call.
    std::call_once(built_, [this] {
        if (builds_)
            ++*builds_;
        try {
            motion_.emplace(track_);
        } catch (...) {
            error_ = std::current_exception();
        }
    });
    if (error_)
        std::rethrow_exception(error_);
    return *motion_;
}

std::shared_ptr<const SharedTrackMotion> MotionCache::motion(const SceneObject& object)
{
    std::shared_ptr<const SharedTrackMotion>& motion = motions_[object.id];
    if (!motion)
        motion = std::make_shared<const SharedTrackMotion>(object.track, builds_);
    return motion;
}

} // namespace gyre::model
