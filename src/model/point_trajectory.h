#pragma once
// A point of a moving object over the scene's time: its position, velocity and acceleration at evenly
// spaced times, the data of ScrewBender's smoothness plots (Fig. 10), here over time in seconds
// rather than over the polyscrew's parameter, and for every interpolation a track may use.

#include "model/track_evaluation.h"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace gyre::model {

struct PointTrajectory {
    std::vector<double> times;                 // seconds, evenly spaced from the start to the end
    std::vector<Eigen::Vector3d> positions;     // units, in the frame of the object's parent
    std::vector<Eigen::Vector3d> velocities;    // units/s
    std::vector<Eigen::Vector3d> accelerations; // units/s²
};

// `samples` times t_k = start + k·Δ, Δ = (end − start)/(samples − 1), and at each the track's pose
// (`motion`) applied to `localPoint`. The derivatives are central differences,
//   v_k = (p_{k+1} − p_{k−1}) / 2Δ,   a_k = (p_{k+1} − 2p_k + p_{k−1}) / Δ²,
// with the motion also sampled one step before the start and one after the end, so the ends are
// central too. Throws std::invalid_argument for fewer than 2 samples or an end not after the start.
PointTrajectory samplePointTrajectory(const TrackMotion& motion, const Eigen::Vector3d& localPoint,
                                      double start, double end, std::size_t samples);

} // namespace gyre::model
