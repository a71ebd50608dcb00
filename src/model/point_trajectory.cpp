#include "model/point_trajectory.h"

#include <stdexcept>

namespace gyre::model {

PointTrajectory samplePointTrajectory(const TrackMotion& motion, const Eigen::Vector3d& localPoint,
                                      double start, double end, std::size_t samples)
{
    if (samples < 2 || !(end > start))
        throw std::invalid_argument("a point trajectory needs two samples or more over a range that ends after it starts");
    const double step = (end - start) / static_cast<double>(samples - 1);
    // p[k + 1] is the point at t_k: one extra sample on each side of the range.
    std::vector<Eigen::Vector3d> p(samples + 2);
    for (std::size_t k = 0; k < p.size(); ++k) {
        const double time = start + (static_cast<double>(k) - 1.0) * step;
        p[k] = motion.at(time).apply(localPoint);
    }

    PointTrajectory trajectory;
    trajectory.times.resize(samples);
    trajectory.positions.resize(samples);
    trajectory.velocities.resize(samples);
    trajectory.accelerations.resize(samples);
    for (std::size_t k = 0; k < samples; ++k) {
        const Eigen::Vector3d& before = p[k];
        const Eigen::Vector3d& middle = p[k + 1];
        const Eigen::Vector3d& after = p[k + 2];
        trajectory.times[k] = start + static_cast<double>(k) * step;
        trajectory.positions[k] = middle;
        trajectory.velocities[k] = (after - before) / (2.0 * step);
        trajectory.accelerations[k] = (after - 2.0 * middle + before) / (step * step);
    }
    return trajectory;
}

} // namespace gyre::model
