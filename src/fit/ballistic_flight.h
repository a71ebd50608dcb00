#pragma once
// A motion through keys in which every span between two keys is a free flight: the orientation is the
// torque-free motion of flight_shooting.h that meets both keys, and the centre of mass follows the parabola
// under gravity through its positions at the two keys,
//     c(t) = c₀ + v₀·t − ½·g·up·t²,   v₀ = (c₁ − c₀)/T + ½·g·T·up,   t ∈ [0, T].
// The object's origin is c(t) − R(t)·centreOfMass. Each span offers its solutions by kinetic energy; its chosen
// one is the one the caller names (an index taken modulo the count, so stepping cycles), by default the one
// whose start angular velocity is nearest the Hermite spline's through the keys (the hermite interpolation's
// motion, what the track would do without physics). Before the first key and after the last the end pose is held.
//
// Built once (every span solved, which takes milliseconds each), evaluated at many times; runs on any thread.

#include "core/pose.h"
#include "core/torque_free.h"
#include "fit/flight_shooting.h"

#include <Eigen/Dense>

#include <cstddef>
#include <optional>
#include <vector>

namespace gyre::fit {

struct FlightKey {
    double time = 0.0;
    Pose pose;
};

struct FlightBody {
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity();    // body frame, about the centre of mass
    Eigen::Vector3d centreOfMass = Eigen::Vector3d::Zero();    // body frame
    double gravity = 9.81;                                     // m/s², ≥ 0
    Eigen::Vector3d up = Eigen::Vector3d::UnitZ();             // unit; Gyre's world is Z-up
};

class BallisticFlight {
public:
    struct Span {
        double startTime;
        std::vector<FlightSolution> solutions;  // least energy first
        std::size_t chosen;
        TorqueFreeMotion motion;
        Eigen::Vector3d startCentre, startVelocity;  // of the centre of mass's parabola
    };

    // `choices[i]` for span i (from key i to key i + 1); missing or empty entries take the default. Throws
    // std::invalid_argument for fewer than two keys, times that do not strictly increase, a gravity that is not
    // finite and ≥ 0 or an up that is not a finite non-zero vector, or a span solveFlight refuses.
    BallisticFlight(const std::vector<FlightKey>& keys, const FlightBody& body,
                    const std::vector<std::optional<std::size_t>>& choices = {});

    Pose at(double time) const;
    const std::vector<Span>& spans() const { return spans_; }

private:
    const Span* spanAt(double time) const;  // null outside the keys

    FlightBody body_;
    std::vector<FlightKey> keys_;
    std::vector<Span> spans_;
};

} // namespace gyre::fit
