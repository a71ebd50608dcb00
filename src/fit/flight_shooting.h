#pragma once
// The free flight between two keys: the start angular velocity ω₀ for which the torque-free motion
// (core/torque_free.h) from the first key's orientation reaches the second key's orientation exactly at the
// second key's time. A boundary-value problem solved by shooting: three unknowns (ω₀, world frame), three
// residuals r(ω₀) = log(q(T)⁻¹·q₁), solved by Ceres from several seeds.
//
// It has many solutions: the body may make extra turns on the way, or flip about its intermediate axis. Every
// seed that converges (keys met to kFlightKeyTolerance rad) is kept once, the solutions are ordered by kinetic
// energy and the kMaxFlightSolutions of least energy are offered.
//
// Runs on any thread; the same input always gives the same output. What a span's fixed seeds give is remembered
// (the last 1024 spans, by the exact values of their inertia, keys and duration), so that dragging a key of a
// ballistic track solves again only the two spans it ends.

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <cstddef>
#include <optional>
#include <vector>

namespace gyre::fit {

struct FlightSpan {
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity();  // body frame, symmetric positive definite
    Eigen::Quaterniond start = Eigen::Quaterniond::Identity();
    Eigen::Quaterniond end = Eigen::Quaterniond::Identity();
    double duration = 1.0;  // seconds, > 0
};

struct FlightSolution {
    Eigen::Vector3d startAngularVelocity;  // world, rad/s
    double kineticEnergy = 0.0;            // ½·L·ω₀, in the inertia's units per s²
    double keyError = 0.0;                 // rotation angle from q(T) to the end key, rad
};

// A solution meets the end key when its rotation angle from it is at most this.
inline constexpr double kFlightKeyTolerance = 1e-10;
// The solutions offered: the fewest turns and the flip, not every loop a seed may find.
inline constexpr std::size_t kMaxFlightSolutions = 6;

// The solutions of the span, least kinetic energy first, distinct (start angular velocities further apart than
// 1e-6 of their size). `hint` is one more seed, the angular velocity the artist's motion has at the start.
// Throws std::invalid_argument for an inertia inertiaProblem (core/mass_properties.h) refuses, keys not finite,
// a duration not finite and > 0, or when no seed converges.
std::vector<FlightSolution> solveFlight(const FlightSpan& span,
                                        const std::optional<Eigen::Vector3d>& hint = std::nullopt);

// How often solveFlight found a span's fixed seeds' results remembered, and how often it solved them, since the
// program started: what tells a test that an edit re-solved only the spans it changed.
struct FlightCacheStatistics {
    std::size_t hits = 0;
    std::size_t misses = 0;
};
FlightCacheStatistics flightCacheStatistics();

// The index of the solution whose start angular velocity is nearest `omega`; 0 for an empty list.
std::size_t nearestFlightSolution(const std::vector<FlightSolution>& solutions, const Eigen::Vector3d& omega);

} // namespace gyre::fit
