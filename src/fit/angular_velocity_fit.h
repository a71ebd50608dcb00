#pragma once
// The angular-velocity fit of the sketch-editing paper (Xie et al. 2011, Algorithm 1): the rotation
// q(t) through the constrained keyframes whose angular velocity matches a target ωˢ(t), smoothly.
//
// The curve is a Hermite quaternion spline; its unknowns are the quaternions and quaternion
// derivatives at the control points (keyframes, plus variable frames inserted where the fit is poor).
// It minimises E = αW_T + βW_A subject to q(tᵢ) = qᵢ at constrained keys and |q(t)| = 1. Only the
// window [t_a, t_b] is refitted: outside it the motion is the initial motion (the paper's InitCurve:
// by default the spline through the keys, or any motion through them the caller gives), and at the
// window's ends its value and derivative are held, so the motion stays C¹ there. Translation is not
// the fit's business.
//
// Runs on any thread; one fit uses one core. The same input always gives the same output.

#include "core/name_table.h"
#include "core/orientation_curves.h"
#include "fit/angular_velocity_target.h"

#include <Eigen/Geometry>

#include <functional>
#include <optional>
#include <vector>

namespace gyre::fit {

struct FitKey {
    double time = 0.0;
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    bool constrained = true;  // kept exactly; a freed key is an ordinary unknown
};

struct TimeWindow {
    double start = 0.0;
    double end = 0.0;
};

struct FitSettings {
    double alpha = 0.002;  // weight of W_T, the tangential acceleration (smoothness)
    double beta = 1.0;     // weight of W_A, the deviation from the target angular velocity
    // The largest relative fragment error accepted, F_n/S̄ in seconds (relativeFragmentError).
    double delta = 0.1;
    double fragmentSeconds = 0.25;  // ΔT, the length of the fragments F_n is measured on
    int maxRounds = 10;             // solves, each after inserting variable frames
    int maxVariableFrames = 100;
    std::optional<TimeWindow> window;  // the span to refit; the target's span if absent
};

// The fragment error δ bounds, F_n/S̄: the paper's F_n = ∫|ω − ωˢ|² dt over a fragment, measured in
// the target's own size, its mean squared speed over the window S̄ = ∫|ωˢ|² dt/(t_b − t_a). For a
// target of S̄ = 1 rad²/s² it is the paper's F_n; a target twice as fast makes errors four times as
// large and is allowed four times as much, so one δ suits a leaf tumbling at 0.5 rad/s and a pen
// whirling at 20 (the paper's absolute F_n ≤ δ asked 50 times more of the pen than of the leaf). With
// the default ΔT = 0.25 s, δ = 0.1 lets a fragment's mean squared error reach 0.4·S̄. A target slower
// than kSlowestTargetSpeed on average counts as that slow: near stillness the ratio would measure
// noise.
inline constexpr double kSlowestTargetSpeed = 0.01;  // rad/s, about half a degree a second
double relativeFragmentError(double fragmentError, double targetMeanSquare);

// S̄ over the window, by Gauss–Legendre quadrature on each fragment of `fragmentSeconds`: the fit's own.
double targetMeanSquare(const AngularVelocityTarget& target, const TimeWindow& window, double fragmentSeconds);

// The most fragments a fit measures F_n on, the window's length over ΔT. Each fragment is integrated
// and may get a variable frame; 100,000 of them keep one round's error pass to a few hundred
// milliseconds and its memory to a few megabytes.
inline constexpr double kMaxFragments = 100000.0;

// Throws std::invalid_argument, naming the count, when `window` in fragments of `fragmentSeconds`
// (finite, > 0) would be more than kMaxFragments.
void checkFragmentCount(const TimeWindow& window, double fragmentSeconds);

enum class FitOutcome {
    Converged,          // every fragment error is at most δ
    RoundLimit,         // maxRounds solves were made
    VariableFrameLimit, // maxVariableFrames were inserted
    NoPlaceForFrame,    // every poorly fitted fragment already has a control point at its middle
    Cancelled,          // the caller asked to stop; the result holds no curve
};

inline constexpr NameTable<FitOutcome, 5> kFitOutcomeNames{{
    {FitOutcome::Converged, "converged"},
    {FitOutcome::RoundLimit, "round limit"},
    {FitOutcome::VariableFrameLimit, "variable frame limit"},
    {FitOutcome::NoPlaceForFrame, "no place for a variable frame"},
    {FitOutcome::Cancelled, "cancelled"},
}};

struct FitProgress {
    int round = 0;      // 1-based
    int iteration = 0;  // solver iterations so far, over all rounds
    double energy = 0.0;  // E plus the unit-norm penalty, at this iteration
    std::optional<double> largestRelativeError;  // F_n/S̄, after the last finished round
};

// The motion the fit starts from and keeps outside its window (the paper's InitCurve): the orientation
// and its time derivative at a time. The fit reads it at the window's ends, which it holds, and at the
// keys inside the window, whose derivatives start there; a key's value is the key's own rotation.
// Empty: the Hermite spline through the keys (HermiteQuaternionSpline::throughKeys).
using InitialMotion = std::function<OrientationSample(double time)>;

struct FitHooks {
    std::function<void(const FitProgress&)> onProgress;  // called from the fitting thread
    std::function<bool()> isCancelled;  // polled once per solver iteration
};

struct EnergyTerms {
    double tangential = 0.0;  // W_T over the window
    double angular = 0.0;     // W_A over the window
};

struct FitResult {
    FitOutcome outcome = FitOutcome::Converged;
    TimeWindow window;
    // The fitted spline over the window, not normalised: HermiteQuaternionSpline::sample normalises it.
    std::vector<HermiteControlPoint> controlPoints;
    // The input keys; those freed inside the window carry the fitted orientation.
    std::vector<FitKey> keys;
    int rounds = 0;
    int iterations = 0;
    int variableFrames = 0;
    double largestRelativeError = 0.0;  // the largest F_n/S̄, which converged holds within δ
    double largestFragmentError = 0.0;  // the largest F_n, rad²/s
    double targetMeanSquare = 0.0;      // S̄, rad²/s²
    double largestNormDeviation = 0.0;  // max over the window of | |q(t)| − 1 | before normalising
    // Of the initial spline: the Hermite spline through the control points as the initial motion
    // gives them, the initial motion itself when that is the spline through the keys.
    EnergyTerms before;
    EnergyTerms after;
    double solveSeconds = 0.0;
};

// Throws std::invalid_argument, with a message naming what is wrong, for fewer than two keys, key
// times that do not increase, a zero or non-finite quaternion, a target reaching outside the keys'
// span, a window outside the keys' span or not covered by the target, or settings out of range.
FitResult fitAngularVelocity(const std::vector<FitKey>& keys, const AngularVelocityTarget& target,
                             const FitSettings& settings, const FitHooks& hooks = {},
                             const InitialMotion& initialMotion = {});

} // namespace gyre::fit
