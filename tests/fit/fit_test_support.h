#pragma once
// A motion whose angular velocity is known in closed form, for the fit's known-answer tests and
// benchmarks: a top that spins, precesses and nutates,
//
//   q(t) = Rz(φ(t))·Rx(θ(t))·Rz(ψ(t)),  φ = Ωₚt,  θ = θ₀ + a·sin(νt),  ψ = Ωₛt,
//
// with the world angular velocity of the composition, term by term:
//
//   ω = φ′·ẑ + θ′·Rz(φ)x̂ + ψ′·Rz(φ)Rx(θ)ẑ.
//
// Written with Eigen's AngleAxis only, independently of the code under test.

#include "fit/angular_velocity_fit.h"

#include <Eigen/Geometry>

#include <cmath>
#include <optional>
#include <vector>

namespace gyre::test {

struct NutatingTop {
    double precession = 2.0;   // Ωₚ, rad/s
    double spin = 6.0;         // Ωₛ, rad/s
    double tilt = 0.4;         // θ₀, rad
    double nutation = 0.15;    // a, rad
    double nutationRate = 7.0; // ν, rad/s

    double theta(double t) const { return tilt + nutation * std::sin(nutationRate * t); }

    Eigen::Quaterniond rotation(double t) const
    {
        return Eigen::Quaterniond(Eigen::AngleAxisd(precession * t, Eigen::Vector3d::UnitZ()) *
                                  Eigen::AngleAxisd(theta(t), Eigen::Vector3d::UnitX()) *
                                  Eigen::AngleAxisd(spin * t, Eigen::Vector3d::UnitZ()));
    }

    Eigen::Vector3d angularVelocity(double t) const
    {
        const Eigen::AngleAxisd precessed(precession * t, Eigen::Vector3d::UnitZ());
        const Eigen::AngleAxisd tilted(theta(t), Eigen::Vector3d::UnitX());
        const double thetaRate = nutation * nutationRate * std::cos(nutationRate * t);
        return precession * Eigen::Vector3d::UnitZ() + thetaRate * (precessed * Eigen::Vector3d::UnitX()) +
               spin * (precessed * tilted * Eigen::Vector3d::UnitZ());
    }

    // Keys every `spacing` seconds over [0, duration], all constrained.
    std::vector<fit::FitKey> keys(double duration, double spacing) const
    {
        std::vector<fit::FitKey> keys;
        const int count = static_cast<int>(std::lround(duration / spacing));
        for (int i = 0; i <= count; ++i)
            keys.push_back({i * spacing, rotation(i * spacing), true});
        return keys;
    }

    // ω sampled at `rate` per second over [start, end].
    fit::AngularVelocityTarget target(double start, double end, double rate) const
    {
        std::vector<fit::TimedVector> samples;
        const int count = static_cast<int>(std::lround((end - start) * rate));
        for (int i = 0; i <= count; ++i) {
            const double t = start + (end - start) * i / count;
            samples.push_back({t, angularVelocity(t)});
        }
        return fit::AngularVelocityTarget::fromSamples(std::move(samples));
    }
};

// The motion after a fit whose initial motion is the spline through the keys: the fitted spline inside
// the window, the spline through the original keys outside it.
class FittedMotion {
public:
    FittedMotion(const std::vector<fit::FitKey>& originalKeys, const fit::FitResult& result)
        : outside_(HermiteQuaternionSpline::throughKeys(orientationKeys(originalKeys)))
    {
        if (!result.controlPoints.empty())
            inside_.emplace(result.controlPoints);
    }

    OrientationSample sample(double time) const
    {
        if (inside_ && time >= inside_->startTime() && time <= inside_->endTime())
            return inside_->sample(time);
        return outside_.sample(time);
    }

private:
    static std::vector<OrientationKey> orientationKeys(const std::vector<fit::FitKey>& keys)
    {
        std::vector<OrientationKey> orientations;
        for (const fit::FitKey& key : keys)
            orientations.push_back({key.time, key.rotation});
        return orientations;
    }

    HermiteQuaternionSpline outside_;
    std::optional<HermiteQuaternionSpline> inside_;
};

} // namespace gyre::test
