#include "core/position_curve.h"

#include "core/timed_keys.h"

#include <utility>

namespace gyre {

HermiteBasis hermiteBasis(double u)
{
    const double u2 = u * u;
    const double u3 = u2 * u;
    return {{2 * u3 - 3 * u2 + 1, u3 - 2 * u2 + u, -2 * u3 + 3 * u2, u3 - u2},
            {6 * u2 - 6 * u, 3 * u2 - 4 * u + 1, -6 * u2 + 6 * u, 3 * u2 - 2 * u},
            {12 * u - 6, 6 * u - 4, -12 * u + 6, 6 * u - 2}};
}

PositionCurve::PositionCurve(std::vector<PositionKey> keys, Shape shape)
    : keys_(std::move(keys))
{
    requireIncreasingTimes(keys_);
    if (shape == Shape::Linear || keys_.size() < 2)
        return;
    slopes_.reserve(keys_.size());
    for (std::size_t i = 0; i < keys_.size(); ++i) {
        const PositionKey& before = keys_[i == 0 ? 0 : i - 1];
        const PositionKey& after = keys_[i + 1 == keys_.size() ? i : i + 1];
        slopes_.push_back((after.position - before.position) / (after.time - before.time));
    }
}

Eigen::Vector3d PositionCurve::at(double time) const
{
    if (time <= keys_.front().time)
        return keys_.front().position;
    if (time >= keys_.back().time)
        return keys_.back().position;
    const std::size_t i = segmentAt(keys_, time);
    const PositionKey& start = keys_[i];
    const PositionKey& end = keys_[i + 1];
    const double duration = end.time - start.time;
    const double u = (time - start.time) / duration;
    if (slopes_.empty())
        return (1.0 - u) * start.position + u * end.position;
    const std::array<double, 4>& h = hermiteBasis(u).value;
    return h[0] * start.position + h[1] * duration * slopes_[i] + h[2] * end.position + h[3] * duration * slopes_[i + 1];
}

Eigen::Vector3d PositionCurve::velocity(double time) const
{
    if (time < keys_.front().time || time > keys_.back().time || keys_.size() < 2)
        return Eigen::Vector3d::Zero();
    const std::size_t i = segmentAt(keys_, time);
    const PositionKey& start = keys_[i];
    const PositionKey& end = keys_[i + 1];
    const double duration = end.time - start.time;
    if (slopes_.empty())
        return (end.position - start.position) / duration;
    // dp/dt = (dp/du)/duration, with the basis' first derivatives in u.
    const std::array<double, 4>& h = hermiteBasis((time - start.time) / duration).first;
    return (h[0] * start.position + h[2] * end.position) / duration + h[1] * slopes_[i] + h[3] * slopes_[i + 1];
}

} // namespace gyre
