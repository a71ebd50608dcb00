#include "fit/flight_shooting.h"

#include "core/mass_properties.h"
#include "core/quaternion_math.h"
#include "core/torque_free.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace gyre::fit {

namespace {

// The integration tolerance while the solver iterates, and for every Jacobian: 10⁵ coarser than playback's, so
// about ten times fewer steps.
constexpr double kIterationTolerance = 1e-7;

// r(ω₀) = log(q(T)⁻¹·q₁), the half rotation vector from where the flight ends to the end key, its flight
// integrated to `tolerance`; the Jacobian by forward differences of flights integrated to kIterationTolerance
// (steps of 1e-5·max(1, |ω₀|)). Its error, about 1e-2 relative, only slows the last iterations from quadratic to
// linear convergence at that rate, while each iteration costs one fine integration instead of the seven of
// central differences at the fine tolerance.
class EndKeyResidual final : public ceres::SizedCostFunction<3, 3> {
public:
    EndKeyResidual(const FlightSpan& span, double tolerance) : span_(span), tolerance_(tolerance) {}

    bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override
    {
        const Eigen::Vector3d omega(parameters[0][0], parameters[0][1], parameters[0][2]);
        const Eigen::Vector3d r = endError(omega, tolerance_);
        std::copy(r.data(), r.data() + 3, residuals);
        if (jacobians && jacobians[0]) {
            const double step = 1e-5 * std::max(1.0, omega.norm());
            const Eigen::Vector3d base = tolerance_ == kIterationTolerance ? r : endError(omega, kIterationTolerance);
            Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> jacobian(jacobians[0]);
            for (int j = 0; j < 3; ++j)
                jacobian.col(j) = (endError(omega + step * Eigen::Vector3d::Unit(j), kIterationTolerance) - base) / step;
            return jacobian.allFinite() && r.allFinite();
        }
        return r.allFinite();
    }

    // NaN where the flight cannot be integrated (a seed that wandered to a spin past the step budget): Ceres
    // then takes the step as failed, and no exception unwinds through ceres::Solve.
    Eigen::Vector3d endError(const Eigen::Vector3d& omega, double tolerance) const
    {
        try {
            const TorqueFreeMotion motion(span_.inertia, span_.start, omega, span_.duration,
                                          TorqueFreeMotion::Solver::Automatic, tolerance);
            return quatLog(motion.orientation(span_.duration).conjugate() * span_.end);
        } catch (const std::invalid_argument&) {
            return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
        }
    }

private:
    const FlightSpan& span_;
    double tolerance_;
};

// The seeds: the slerp's constant ω, and with one extra turn (2π/T, either way) about the body's principal axes
// at the start and about the slerp's own axis; the hint last. Turns about the world axes as well cost 60% more
// and found a few more solutions, of higher energy than the first four.
std::vector<Eigen::Vector3d> seeds(const FlightSpan& span, const std::optional<Eigen::Vector3d>& hint)
{
    const Eigen::Quaterniond arc = shortArc(span.end * span.start.conjugate());
    const Eigen::Vector3d slerp = 2.0 * quatLog(arc) / span.duration;
    const Eigen::Matrix3d principal = span.start.toRotationMatrix() * principalAxes(span.inertia).axes;
    std::vector<Eigen::Vector3d> axes{principal.col(0), principal.col(1), principal.col(2)};
    if (slerp.norm() > 1e-9)
        axes.push_back(slerp.normalized());
    std::vector<Eigen::Vector3d> result{slerp};
    const double turn = 2.0 * std::numbers::pi / span.duration;
    for (const Eigen::Vector3d& axis : axes)
        for (const double k : {-1.0, 1.0})
            result.push_back(slerp + k * turn * axis);
    if (hint && hint->allFinite())
        result.push_back(*hint);
    return result;
}

// The Ceres options, chosen for a square system of three equations with isolated roots:
// - Levenberg–Marquardt: a trust region, so a seed far from a root still moves toward one instead of jumping;
// - DENSE_QR: the Jacobian is 3×3 and dense;
// - the function and gradient tolerances at zero: the solve stops when the step is below 1e-14 of ω₀ or after
//   `iterations`, and the key error is checked afterwards, not inferred from a relative decrease;
// - one thread: one solve per span, and a result independent of scheduling.
ceres::Solver::Options solverOptions(int iterations)
{
    ceres::Solver::Options options;
    options.minimizer_type = ceres::TRUST_REGION;
    options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
    options.linear_solver_type = ceres::DENSE_QR;
    options.max_num_iterations = iterations;
    options.function_tolerance = 0.0;
    options.gradient_tolerance = 0.0;
    options.parameter_tolerance = 1e-14;
    options.num_threads = 1;
    options.logging_type = ceres::SILENT;
    return options;
}

// Gives up on a seed still far from any root after a few iterations: seeds that converge do so in fewer (the
// residual is a half rotation vector, so a cost of 1e-4 is still about a degree off).
class FarSeedAbort final : public ceres::IterationCallback {
public:
    ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override
    {
        return summary.iteration >= 8 && summary.cost > 1e-4 ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
    }
};

// ω₀ solved from `omega` with the flight integrated to `tolerance`, each component kept within `bound` so that no
// seed wanders off to flights of many turns (each costlier to integrate than the last).
Eigen::Vector3d solvedFrom(const FlightSpan& span, const Eigen::Vector3d& omega, double tolerance, double bound,
                           int iterations)
{
    std::array<double, 3> unknowns{omega.x(), omega.y(), omega.z()};
    ceres::Problem problem;
    problem.AddResidualBlock(new EndKeyResidual(span, tolerance), nullptr, unknowns.data());
    for (int j = 0; j < 3; ++j) {
        problem.SetParameterLowerBound(unknowns.data(), j, std::min(-bound, unknowns[j]));
        problem.SetParameterUpperBound(unknowns.data(), j, std::max(bound, unknowns[j]));
    }
    ceres::Solver::Options options = solverOptions(iterations);
    FarSeedAbort abort;
    options.callbacks.push_back(&abort);
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    return {unknowns[0], unknowns[1], unknowns[2]};
}

bool near(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double relative)
{
    return (a - b).norm() <= relative * std::max(1.0, std::max(a.norm(), b.norm()));
}

} // namespace

// Two passes: every seed iterated with coarse flights until its key error is below 1e-6 rad; the distinct
// candidates then polished with playback's flights, and kept where they meet the key to kFlightKeyTolerance.
std::vector<FlightSolution> solveFlight(const FlightSpan& span, const std::optional<Eigen::Vector3d>& hint)
{
    if (!std::isfinite(span.duration) || !(span.duration > 0.0))
        throw std::invalid_argument("a free flight lasts a finite time > 0");
    const std::vector<Eigen::Vector3d> starts = seeds(span, hint);
    double bound = 0.0;
    for (const Eigen::Vector3d& start : starts)
        bound = std::max(bound, start.cwiseAbs().maxCoeff());
    bound += 2.0 * std::numbers::pi / span.duration;

    const EndKeyResidual coarse(span, kIterationTolerance);
    std::vector<Eigen::Vector3d> candidates;
    for (const Eigen::Vector3d& start : starts) {
        const Eigen::Vector3d found = solvedFrom(span, start, kIterationTolerance, bound, 20);
        if (found.allFinite() && 2.0 * coarse.endError(found, kIterationTolerance).norm() < 1e-6 &&
            std::none_of(candidates.begin(), candidates.end(),
                         [&](const Eigen::Vector3d& known) { return near(known, found, 1e-4); }))
            candidates.push_back(found);
    }

    const EndKeyResidual fine(span, kTorqueFreeTolerance);
    std::vector<FlightSolution> solutions;
    for (const Eigen::Vector3d& candidate : candidates) {
        const Eigen::Vector3d found = solvedFrom(span, candidate, kTorqueFreeTolerance, bound, 8);
        const double keyError = 2.0 * fine.endError(found, kTorqueFreeTolerance).norm();
        if (!(keyError <= kFlightKeyTolerance) ||
            std::any_of(solutions.begin(), solutions.end(), [&](const FlightSolution& known) {
                return near(known.startAngularVelocity, found, 1e-6);
            }))
            continue;
        const TorqueFreeMotion motion(span.inertia, span.start, found, span.duration);
        solutions.push_back({found, motion.kineticEnergy(), keyError});
    }
    if (solutions.empty())
        throw std::invalid_argument("no free flight found that meets the next key");
    std::sort(solutions.begin(), solutions.end(),
              [](const FlightSolution& a, const FlightSolution& b) { return a.kineticEnergy < b.kineticEnergy; });
    if (solutions.size() > kMaxFlightSolutions)
        solutions.resize(kMaxFlightSolutions);
    return solutions;
}

std::size_t nearestFlightSolution(const std::vector<FlightSolution>& solutions, const Eigen::Vector3d& omega)
{
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < solutions.size(); ++i)
        if ((solutions[i].startAngularVelocity - omega).norm() <
            (solutions[nearest].startAngularVelocity - omega).norm())
            nearest = i;
    return nearest;
}

} // namespace gyre::fit
