#pragma once
// Torque-free motion of a rigid body: the orientation and world angular velocity of a body in free
// flight, from its inertia tensor, an orientation and an angular velocity at the start of a span.
//
// Euler's equations I·ω̇ = (I·ω)×ω say that the world angular momentum L = R·I·Rᵀ·ω is constant. The
// motion is integrated in the frame of the principal axes (I = V·D·Vᵀ, V a rotation, D diagonal), as the
// orientation p = q·V alone: with the body angular momentum ℓ = pᵀ·L·p (rotated into the principal frame),
//     ṗ = ½·p⊗(0, D⁻¹·ℓ)          (q̇ = ½·q⊗(0, ω_body) with ω_body = I⁻¹·ℓ)
// so L is exactly the constant it started as, and ℓ obeys Euler's equation ℓ̇ = ℓ × D⁻¹ℓ. The kinetic
// energy ½·ℓᵀD⁻¹ℓ is kept to the integrator's accuracy: Dormand–Prince 5(4), steps controlled to an absolute
// error per step (kTorqueFreeTolerance on the unit quaternion), p renormalised after each step. A body with two
// equal principal moments (A, A, C, symmetry axis e) takes the closed form of steady precession instead:
//     q(t) = exp(t·L/(2A)) ⊗ q₀ ⊗ exp(t·(1 − C/A)·ω_e·e/2),   ω_e = ω_body·e constant,
// a turn about the fixed L at |L|/A and a turn about the body's symmetry axis at (1 − C/A)·ω_e.
// Between the stored steps the orientation is the quintic Hermite curve through p, ṗ and p̈ at the step
// ends (error O(h⁶), below the step's own), so evaluation at a time is a search and a polynomial.

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <array>
#include <vector>

namespace gyre {

// The per-step error tolerance of the integration (on the unit quaternion): far below 1e-9 of any quantity
// over a span of thousands of steps.
inline constexpr double kTorqueFreeTolerance = 1e-12;

// Two principal moments within this relative difference make a symmetric body, played by its closed form.
inline constexpr double kSymmetricMomentTolerance = 1e-12;

class TorqueFreeMotion {
public:
    enum class Solver { Automatic, Numerical };  // Numerical: integrate even a symmetric body (for tests)

    // The motion from `start` (orientation, world angular velocity in rad/s) over [0, duration] seconds, its steps
    // controlled to `tolerance` (a coarser one only where a solver iterates). Throws std::invalid_argument for a
    // non-finite start, a duration not finite and ≥ 0, or an inertia that inertiaProblem (core/mass_properties.h)
    // refuses.
    TorqueFreeMotion(const Eigen::Matrix3d& inertia, const Eigen::Quaterniond& startOrientation,
                     const Eigen::Vector3d& startAngularVelocity, double duration, Solver solver = Solver::Automatic,
                     double tolerance = kTorqueFreeTolerance);

    // The orientation at `duration` alone, integrated as the constructor does but keeping no step between: what a
    // solver shooting for a key evaluates thousands of times (a third less work a step). Throws as the constructor.
    static Eigen::Quaterniond endOrientation(const Eigen::Matrix3d& inertia, const Eigen::Quaterniond& startOrientation,
                                             const Eigen::Vector3d& startAngularVelocity, double duration,
                                             double tolerance = kTorqueFreeTolerance);

    // At t ∈ [0, duration] (clamped outside): the unit orientation and the world angular velocity.
    Eigen::Quaterniond orientation(double t) const;
    Eigen::Vector3d angularVelocity(double t) const;

    double duration() const { return duration_; }
    const Eigen::Vector3d& angularMomentum() const { return momentum_; }  // world L, constant
    // ½·ωᵀ(R·I·Rᵀ)ω = ½·L·ω at the start.
    double kineticEnergy() const;
    bool closedForm() const { return symmetric_; }
    std::size_t stepCount() const { return steps_.size(); }

private:
    struct Step {
        double time;
        Eigen::Vector4d p, dp, ddp;  // w, x, y, z of the principal frame's orientation and its derivatives
    };
    using Quaternion4 = std::array<double, 4>;  // w, x, y, z
    enum class Kept { EveryStep, End };
    TorqueFreeMotion(const Eigen::Matrix3d& inertia, const Eigen::Quaterniond& startOrientation,
                     const Eigen::Vector3d& startAngularVelocity, double duration, Solver solver, double tolerance,
                     Kept kept);
    void integrate(double tolerance, Kept kept);
    void rate(const double* p, double* dp) const;
    Step stepAt(double time, const Eigen::Vector4d& p) const;
    Eigen::Quaterniond principalOrientation(double t) const;

    Eigen::Vector3d moments_;         // D, increasing
    Eigen::Quaterniond axes_;         // V: its columns are the principal axes in the body frame
    Eigen::Vector3d inverseMoments_;  // D⁻¹
    Eigen::Quaterniond start_;
    Eigen::Vector3d startAngularVelocity_;
    Eigen::Vector3d momentum_;
    double duration_;
    bool symmetric_ = false;
    // The closed form's symmetry axis in the body frame and the rates of its two turns.
    Eigen::Vector3d symmetryAxis_ = Eigen::Vector3d::UnitZ();
    Eigen::Vector3d precession_ = Eigen::Vector3d::Zero();  // L/A, world
    double spin_ = 0.0;                                        // (1 − C/A)·ω_e
    std::vector<Step> steps_;
};

} // namespace gyre
