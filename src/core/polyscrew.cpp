#include "core/polyscrew.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace gyre {

Polyscrew::Polyscrew(std::vector<Pose> poses, bool cyclic, std::size_t posesPerUnit)
    : poses_(std::move(poses))
    , cyclic_(cyclic)
    , posesPerUnit_(static_cast<double>(posesPerUnit))
{
    if (poses_.empty())
        throw std::invalid_argument("a polyscrew needs at least one pose");
    if (posesPerUnit < 1)
        throw std::invalid_argument("a polyscrew needs at least one pose per unit");
    const std::size_t spans = cyclic_ ? poses_.size() : poses_.size() - 1;
    screws_.reserve(spans);
    for (std::size_t i = 0; i < spans; ++i)
        screws_.emplace_back(poses_[i], poses_[(i + 1) % poses_.size()]);
}

double Polyscrew::duration() const
{
    return static_cast<double>(screws_.size()) / posesPerUnit_;
}

Pose Polyscrew::at(double u) const
{
    if (screws_.empty())
        return poses_.front();
    const double spans = static_cast<double>(screws_.size());
    double x = u * posesPerUnit_;
    if (cyclic_) {
        x = std::fmod(x, spans);
        if (x < 0.0)
            x += spans;
    } else {
        x = std::clamp(x, 0.0, spans);
    }
    const std::size_t span = std::min(static_cast<std::size_t>(x), screws_.size() - 1);
    return screws_[span].at(x - static_cast<double>(span));
}

std::vector<TrajectorySample> sampleTrajectory(const Polyscrew& motion, const Eigen::Vector3d& localPoint,
                                               std::size_t samples)
{
    if (samples < 3)
        throw std::invalid_argument("a trajectory needs at least three samples");
    const bool cyclic = motion.isCyclic();
    const double step = motion.duration() / static_cast<double>(cyclic ? samples : samples - 1);
    std::vector<TrajectorySample> result(samples);
    for (std::size_t k = 0; k < samples; ++k) {
        result[k].u = static_cast<double>(k) * step;
        result[k].position = motion.at(result[k].u).apply(localPoint);
    }
    if (step == 0.0)
        return result;
    // Central differences inside (and across the seam of a cycle); at the ends of an open motion the
    // one-sided difference of the neighbouring triple.
    for (std::size_t k = 0; k < samples; ++k) {
        std::size_t centre = k;
        if (!cyclic)
            centre = std::clamp<std::size_t>(k, 1, samples - 2);
        const Eigen::Vector3d& before = result[(centre + samples - 1) % samples].position;
        const Eigen::Vector3d& middle = result[centre].position;
        const Eigen::Vector3d& after = result[(centre + 1) % samples].position;
        result[k].acceleration = (after - 2.0 * middle + before) / (step * step);
        if (centre == k)
            result[k].velocity = (after - before) / (2.0 * step);
        else if (k == 0)
            result[k].velocity = (middle - before) / step;
        else
            result[k].velocity = (after - middle) / step;
    }
    return result;
}

} // namespace gyre
