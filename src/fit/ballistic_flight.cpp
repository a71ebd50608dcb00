#include "fit/ballistic_flight.h"

#include "core/orientation_curves.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gyre::fit {

namespace {

std::vector<OrientationKey> orientationKeys(const std::vector<FlightKey>& keys)
{
    std::vector<OrientationKey> result;
    result.reserve(keys.size());
    for (const FlightKey& key : keys)
        result.push_back({key.time, key.pose.orientation});
    return result;
}

} // namespace

BallisticFlight::BallisticFlight(const std::vector<FlightKey>& keys, const FlightBody& body,
                                 const std::vector<std::optional<std::size_t>>& choices)
    : body_(body)
    , keys_(keys)
{
    if (keys.size() < 2)
        throw std::invalid_argument("a free flight needs two keys or more");
    if (!std::isfinite(body.gravity) || body.gravity < 0.0)
        throw std::invalid_argument("gravity must be finite and ≥ 0");
    if (!body.up.allFinite() || !(body.up.norm() > 0.0))
        throw std::invalid_argument("the up axis must be a finite non-zero vector");
    body_.up.normalize();
    // The Hermite spline's ω at each span's start: the default solution is the one nearest it.
    const HermiteQuaternionSpline hermite = HermiteQuaternionSpline::throughKeys(orientationKeys(keys));
    const Eigen::Vector3d g = body_.gravity * body_.up;
    spans_.reserve(keys.size() - 1);
    for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
        const FlightKey& from = keys[i];
        const FlightKey& to = keys[i + 1];
        const double duration = to.time - from.time;
        const Eigen::Vector3d hint = hermite.sample(from.time).angularVelocity;
        std::vector<FlightSolution> solutions =
            solveFlight({body.inertia, from.pose.orientation, to.pose.orientation, duration}, hint);
        const std::size_t chosen = (i < choices.size() && choices[i]) ? *choices[i] % solutions.size()
                                                                         : nearestFlightSolution(solutions, hint);
        TorqueFreeMotion motion(body.inertia, from.pose.orientation, solutions[chosen].startAngularVelocity, duration);
        const Eigen::Vector3d c0 = from.pose.apply(body.centreOfMass);
        const Eigen::Vector3d c1 = to.pose.apply(body.centreOfMass);
        const Eigen::Vector3d v0 = (c1 - c0) / duration + 0.5 * duration * g;
        spans_.push_back({from.time, std::move(solutions), chosen, std::move(motion), c0, v0});
    }
}

const BallisticFlight::Span* BallisticFlight::spanAt(double time) const
{
    if (!(time > keys_.front().time) || !(time < keys_.back().time))
        return nullptr;
    const auto after = std::upper_bound(spans_.begin(), spans_.end(), time,
                                        [](double t, const Span& span) { return t < span.startTime; });
    return &*(after - 1);
}

Pose BallisticFlight::at(double time) const
{
    const Span* span = spanAt(time);
    if (!span)
        return time <= keys_.front().time ? keys_.front().pose : keys_.back().pose;
    const double t = time - span->startTime;
    const Eigen::Quaterniond orientation = span->motion.orientation(t);
    const Eigen::Vector3d centre = span->startCentre + t * span->startVelocity - 0.5 * body_.gravity * t * t * body_.up;
    return {orientation, centre - orientation * body_.centreOfMass};
}

} // namespace gyre::fit
