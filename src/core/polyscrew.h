#pragma once
// A polyscrew: a piecewise screw motion through a sequence of poses, each consecutive pair joined by
// its screw. Evaluated at a parameter u in which pose i sits at u = i / posesPerUnit, so a polyscrew
// subdivided L levels and built with posesPerUnit = 2^L keeps the control poses at integer u.

#include "core/pose.h"
#include "core/screw.h"

#include <cstddef>
#include <vector>

namespace gyre {

class Polyscrew {
public:
    // Throws std::invalid_argument for no poses or posesPerUnit < 1.
    Polyscrew(std::vector<Pose> poses, bool cyclic, std::size_t posesPerUnit = 1);

    // u ∈ [0, duration()]; clamped for an open polyscrew, wrapped for a cycle.
    Pose at(double u) const;
    // The parameter span: spans / posesPerUnit.
    double duration() const;
    std::size_t spanCount() const { return screws_.size(); }
    bool isCyclic() const { return cyclic_; }
    const std::vector<Pose>& poses() const { return poses_; }

private:
    std::vector<Pose> poses_;
    std::vector<Screw> screws_;
    bool cyclic_;
    double posesPerUnit_;
};

// A point of the moving body over u, with its velocity and acceleration by central differences of
// the samples (one-sided at the ends of an open motion): the smoothness plots of ScrewBender's Fig. 10.
struct TrajectorySample {
    double u = 0.0;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
    Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();
};

// `samples` evenly spaced samples over the whole motion (at least 3); for a cycle the last sample
// stops one step short of wrapping around to the first.
std::vector<TrajectorySample> sampleTrajectory(const Polyscrew& motion, const Eigen::Vector3d& localPoint,
                                               std::size_t samples);

} // namespace gyre
