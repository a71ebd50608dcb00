#include "model/physics_target.h"

#include "core/torque_free.h"
#include "model/sketch_fit_problem.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gyre::model {

std::optional<std::pair<double, double>> physicsTargetWindow(const MotionTrack& track)
{
    if (const std::optional<fit::TimeWindow> window = editWindow(track))
        return std::pair(window->start, window->end);
    if (track.keys.size() < 2)
        return std::nullopt;
    return std::pair(track.keys.front().time, track.keys.back().time);
}

PhysicsTarget physicsTarget(const MotionTrack& track, const TrackMotion& motion, const MassProperties& body,
                            double fps)
{
    const std::optional<std::pair<double, double>> window = physicsTargetWindow(track);
    if (!window)
        throw SketchFitError(
            SketchFitError::tr("the physics target needs at least two keyframes").toStdString());
    const auto [start, end] = *window;
    // At the first key the motion's central difference straddles the held pose before it and reads half the
    // ω: there it is read kAngularVelocityStep later, a change of ω far below what a sketch shows.
    const Eigen::Vector3d startVelocity =
        motion.angularVelocity(std::max(start, track.keys.front().time + kAngularVelocityStep));
    if (!(startVelocity.norm() > 0.0))
        throw SketchFitError(
            SketchFitError::tr("the object is at rest at %1 s, so a free flight from there has no direction")
                .arg(start)
                .toStdString());
    const double duration = end - start;
    const TorqueFreeMotion flight(body.inertia, motion.at(start).orientation, startVelocity, duration);
    const int intervals =
        static_cast<int>(std::clamp(std::ceil(duration * fps), double{kFewestPhysicsSamples}, double{kMostPhysicsSamples}));
    PhysicsTarget target;
    DirectionStroke& stroke = target.directionStrokes.emplace_back();
    for (int sample = 0; sample <= intervals; ++sample) {
        // The last sample at the end exactly, not a rounding error before it.
        const double t = sample == intervals ? duration : duration * sample / intervals;
        const Eigen::Vector3d omega = flight.angularVelocity(t);
        stroke.points.push_back(omega.normalized());
        stroke.times.push_back(start + t);
        target.magnitude.push_back({start + t, omega.norm()});
    }
    return target;
}

} // namespace gyre::model
