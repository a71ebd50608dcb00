#include "model/motion_cache.h"

#include "model/fit_input.h"

#include <utility>

namespace gyre::model {

SharedTrackMotion::SharedTrackMotion(MotionTrack track, std::shared_ptr<std::atomic<std::size_t>> builds,
                                     const MassProperties& body, const Gravity& gravity)
    : track_(std::move(track))
    , builds_(std::move(builds))
    , body_(body)
    , gravity_(gravity)
{
}

const TrackMotion& SharedTrackMotion::motion() const
{
    return build(motion_, [this] { return TrackMotion(track_, body_, gravity_); });
}

const TrackMotion& SharedTrackMotion::motionWithoutFit() const
{
    if (track_.sketch.fittedCurve.empty())
        return motion();
    return build(withoutFit_, [this] { return TrackMotion(withoutFit(track_), body_, gravity_); });
}

const TrackMotion& SharedTrackMotion::build(Lazy& lazy, const std::function<TrackMotion()>& make) const
{
    // call_once runs the build once even when threads ask together; a build that throws is kept as
    // its exception, so a refused track is not built again at every call.
    std::call_once(lazy.built, [this, &lazy, &make] {
        if (builds_)
            ++*builds_;
        try {
            lazy.motion.emplace(make());
        } catch (...) {
            lazy.error = std::current_exception();
        }
    });
    if (lazy.error)
        std::rethrow_exception(lazy.error);
    return *lazy.motion;
}

std::shared_ptr<const SharedTrackMotion> MotionCache::motion(const SceneObject& object, const Gravity& gravity)
{
    std::shared_ptr<const SharedTrackMotion>& motion = motions_[object.id];
    if (!motion)
        motion = std::make_shared<const SharedTrackMotion>(object.track, builds_, flightBodyOf(object), gravity);
    return motion;
}

} // namespace gyre::model
