#include "fit/flight_shooting.h"

#include "core/mass_properties.h"
#include "core/quaternion_math.h"
#include "core/torque_free.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace gyre::fit {

namespace {

// The integration tolerance per step while a seed iterates, and for every Jacobian: 10⁷ coarser than playback's,
// so about 25 times fewer steps (Dormand–Prince's steps grow as the tolerance's fifth root). That is all a seed
// needs to find its root's neighbourhood: the polish takes it from there. At 1e-7 the solve took twice as long
// and found the same flights.
constexpr double kIterationTolerance = 1e-5;

// A seed's coarse iterations stop once its coarse flight ends this close to the key (rad): a candidate.
constexpr double kCandidateError = 1e-7;

// r(ω₀) = log(q(T)⁻¹·q₁), the half rotation vector from where the flight from ω₀, integrated to `tolerance`, ends
// to the end key. NaN where the flight cannot be integrated (a seed that wandered to a spin past the step
// budget): Ceres then takes the step as failed, and no exception unwinds through ceres::Solve.
Eigen::Vector3d endError(const FlightSpan& span, const Eigen::Vector3d& omega, double tolerance)
{
    try {
        const Eigen::Quaterniond end =
            TorqueFreeMotion::endOrientation(span.inertia, span.start, omega, span.duration, tolerance);
        return quatLog(end.conjugate() * span.end);
    } catch (const std::invalid_argument&) {
        return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    }
}

// The seeds' residual r(ω₀) with coarse flights, and its Jacobian by forward differences of coarse flights, steps
// of 1e-4·max(1, |ω₀|). Flights from nearby ω₀ take nearly the same steps, so their integration errors mostly
// cancel in the difference: the Jacobian is off by a few per cent, which only slows the last iterations from
// quadratic to linear convergence, while each costs four coarse flights instead of the seven fine ones of
// central differences at playback's tolerance.
class EndKeyResidual final : public ceres::SizedCostFunction<3, 3> {
public:
    explicit EndKeyResidual(const FlightSpan& span) : span_(span) {}

    bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override
    {
        const Eigen::Vector3d omega(parameters[0][0], parameters[0][1], parameters[0][2]);
        const Eigen::Vector3d r = endError(span_, omega, kIterationTolerance);
        std::copy(r.data(), r.data() + 3, residuals);
        if (jacobians && jacobians[0]) {
            const double step = 1e-4 * std::max(1.0, omega.norm());
            Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> jacobian(jacobians[0]);
            for (int j = 0; j < 3; ++j)
                jacobian.col(j) =
                    (endError(span_, omega + step * Eigen::Vector3d::Unit(j), kIterationTolerance) - r) / step;
            return jacobian.allFinite() && r.allFinite();
        }
        return r.allFinite();
    }

private:
    const FlightSpan& span_;
};

// The seeds: the slerp's constant ω, and with one extra turn (2π/T, either way) about the body's principal axes
// at the start and about the slerp's own axis. Turns about the world axes as well cost 60% more and found a few
// more solutions, of higher energy than the first four. The artist's hint is one seed more, taken last.
std::vector<Eigen::Vector3d> fixedSeeds(const FlightSpan& span)
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
    return result;
}

// The Ceres options, chosen for a square system of three equations with isolated roots:
// - Levenberg–Marquardt: a trust region, so a seed far from a root still moves toward one instead of jumping;
// - DENSE_QR: the Jacobian is 3×3 and dense;
// - the function and gradient tolerances at zero: the solve stops when SeedProgress says, when the step is below
//   1e-14 of ω₀ or after `iterations`, and the key error is checked afterwards, not inferred from a relative
//   decrease;
// - Ceres' projected line search within each step kept (it runs for a problem with bounds): without it, a quarter
//   of the spans of a random trial lost one of their least-energy flights;
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

// Ends a seed's iterations: successfully once its flight ends within kCandidateError of the key (the polish takes
// it from there), and as a failure while it is still far from any root (the residual is a half rotation
// vector, so a cost of 0.1 is some 50° off and 1e-4 about a degree): seeds that converge do so in fewer
// iterations. The cost is ½|r|², so the key error 2|r| is 2·√(2·cost).
class SeedProgress final : public ceres::IterationCallback {
public:
    ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override
    {
        if (2.0 * std::sqrt(2.0 * summary.cost) < kCandidateError)
            return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
        const bool far =
            (summary.iteration >= 4 && summary.cost > 0.1) || (summary.iteration >= 8 && summary.cost > 1e-4);
        return far ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
    }
};

// A seed iterated with coarse flights, each component of ω₀ kept within `bound` so that no seed wanders off to
// flights of many turns (each costlier to integrate than the last); nothing unless its coarse flight ends within
// 1e-6 rad of the key (SeedProgress stops it at kCandidateError; the iteration cap may stop it a little short).
std::optional<Eigen::Vector3d> candidateFrom(const FlightSpan& span, const Eigen::Vector3d& seed, double bound)
{
    std::array<double, 3> unknowns{seed.x(), seed.y(), seed.z()};
    ceres::Problem problem;
    problem.AddResidualBlock(new EndKeyResidual(span), nullptr, unknowns.data());
    for (int j = 0; j < 3; ++j) {
        problem.SetParameterLowerBound(unknowns.data(), j, std::min(-bound, unknowns[j]));
        problem.SetParameterUpperBound(unknowns.data(), j, std::max(bound, unknowns[j]));
    }
    ceres::Solver::Options options = solverOptions(20);
    SeedProgress progress;
    options.callbacks.push_back(&progress);
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    const Eigen::Vector3d found(unknowns[0], unknowns[1], unknowns[2]);
    if (!summary.IsSolutionUsable() || !found.allFinite() || !(2.0 * std::sqrt(2.0 * summary.final_cost) < 1e-6))
        return std::nullopt;
    return found;
}

// A candidate polished with playback's flights by Newton's iteration ω ← ω − J⁻¹·r(ω), J the coarse flights'
// Jacobian at the candidate: the candidate is within about 1e-5 of the root, where J's error (a few per cent)
// makes each iteration gain more than a digit; two to four playback flights meet the key. It stops at a key
// error of kFlightKeyTolerance/100, after 8 iterations, or when an iteration no longer gains; nothing when the key
// is not met to kFlightKeyTolerance.
std::optional<FlightSolution> polished(const FlightSpan& span, const Eigen::Vector3d& candidate)
{
    const EndKeyResidual coarse(span);
    const double* parameters[] = {candidate.data()};
    Eigen::Vector3d unused;
    Eigen::Matrix<double, 3, 3, Eigen::RowMajor> jacobian;
    double* jacobians[] = {jacobian.data()};
    if (!coarse.Evaluate(parameters, unused.data(), jacobians))
        return std::nullopt;
    const Eigen::PartialPivLU<Eigen::Matrix3d> newton(jacobian);
    Eigen::Vector3d omega = candidate;
    Eigen::Vector3d r = endError(span, omega, kTorqueFreeTolerance);
    for (int iteration = 0; iteration < 8 && r.allFinite() && 2.0 * r.norm() > 1e-2 * kFlightKeyTolerance;
         ++iteration) {
        const Eigen::Vector3d next = omega - newton.solve(r);
        const Eigen::Vector3d nextR = endError(span, next, kTorqueFreeTolerance);
        if (!(nextR.norm() < r.norm()))
            break;
        omega = next;
        r = nextR;
    }
    const double keyError = 2.0 * r.norm();
    if (!omega.allFinite() || !(keyError <= kFlightKeyTolerance))
        return std::nullopt;
    const double energy = 0.5 * angularMomentum(span.inertia, span.start.normalized(), omega).dot(omega);
    return FlightSolution{omega, energy, keyError};
}

bool near(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double relative)
{
    return (a - b).norm() <= relative * std::max(1.0, std::max(a.norm(), b.norm()));
}

// What the fixed seeds give a span: the distinct candidates, and their polished solutions in that order (before
// the hint's, the sorting by energy and the cut to kMaxFlightSolutions).
struct SeedResults {
    std::vector<Eigen::Vector3d> candidates;
    std::vector<FlightSolution> solutions;
};

// Adds the seed's candidate and its solution where they are new: candidates within 1e-4 of a known one, and
// solutions within 1e-6, are the same flight found twice.
void addSeed(const FlightSpan& span, const Eigen::Vector3d& seed, double bound, SeedResults& results)
{
    const std::optional<Eigen::Vector3d> found = candidateFrom(span, seed, bound);
    if (!found || std::any_of(results.candidates.begin(), results.candidates.end(),
                              [&](const Eigen::Vector3d& known) { return near(known, *found, 1e-4); }))
        return;
    results.candidates.push_back(*found);
    const std::optional<FlightSolution> solution = polished(span, *found);
    if (solution && std::none_of(results.solutions.begin(), results.solutions.end(), [&](const FlightSolution& known) {
            return near(known.startAngularVelocity, solution->startAngularVelocity, 1e-6);
        }))
        results.solutions.push_back(*solution);
}

// The seeds' components bound the search: the largest, plus one turn.
double searchBound(const FlightSpan& span, const std::vector<Eigen::Vector3d>& seeds)
{
    double bound = 0.0;
    for (const Eigen::Vector3d& seed : seeds)
        bound = std::max(bound, seed.cwiseAbs().maxCoeff());
    return bound + 2.0 * std::numbers::pi / span.duration;
}

// The spans solved lately, by the exact values of their inertia, keys and duration: a key dragged on a ballistic
// track changes the two spans it ends, and every other span's solve is found here. At most kCachedSpans are
// kept (each a few hundred bytes), the least recently used dropped. Shared by every thread, behind a mutex; two
// threads solving one span at once both store the same result.
class SolvedSpans {
public:
    static constexpr std::size_t kCachedSpans = 1024;
    using Key = std::array<double, 18>;

    static Key keyOf(const FlightSpan& span)
    {
        Key key;
        std::copy(span.inertia.data(), span.inertia.data() + 9, key.begin());
        std::copy(span.start.coeffs().data(), span.start.coeffs().data() + 4, key.begin() + 9);
        std::copy(span.end.coeffs().data(), span.end.coeffs().data() + 4, key.begin() + 13);
        key[17] = span.duration;
        return key;
    }

    std::optional<SeedResults> find(const Key& key)
    {
        const std::lock_guard lock(mutex_);
        const auto found = entries_.find(key);
        if (found == entries_.end()) {
            ++statistics_.misses;
            return std::nullopt;
        }
        ++statistics_.hits;
        found->second.lastUse = ++clock_;
        return found->second.results;
    }

    void store(const Key& key, const SeedResults& results)
    {
        const std::lock_guard lock(mutex_);
        if (entries_.size() >= kCachedSpans && !entries_.count(key))
            entries_.erase(std::min_element(entries_.begin(), entries_.end(), [](const auto& a, const auto& b) {
                return a.second.lastUse < b.second.lastUse;
            }));
        entries_[key] = {results, ++clock_};
    }

    FlightCacheStatistics statistics()
    {
        const std::lock_guard lock(mutex_);
        return statistics_;
    }

private:
    struct Entry {
        SeedResults results;
        std::uint64_t lastUse = 0;
    };
    std::mutex mutex_;
    std::map<Key, Entry> entries_;
    std::uint64_t clock_ = 0;
    FlightCacheStatistics statistics_;
};

SolvedSpans& solvedSpans()
{
    static SolvedSpans spans;
    return spans;
}

} // namespace

// Two passes per seed: iterated with coarse flights until its key error is below kCandidateError, then, where the
// candidate is new, polished with playback's flights and kept where it meets the key to kFlightKeyTolerance. The
// fixed seeds' results are remembered per span (SolvedSpans); the hint, which changes with the neighbouring keys,
// is solved each time, last, as if it were the last fixed seed.
std::vector<FlightSolution> solveFlight(const FlightSpan& span, const std::optional<Eigen::Vector3d>& hint)
{
    if (!std::isfinite(span.duration) || !(span.duration > 0.0))
        throw std::invalid_argument("a free flight lasts a finite time > 0");
    if (inertiaProblem(span.inertia) != InertiaProblem::None)
        throw std::invalid_argument("the inertia tensor is not one a body can have");
    if (!span.start.coeffs().allFinite() || !span.end.coeffs().allFinite())
        throw std::invalid_argument("the keys of a free flight are not finite");
    const SolvedSpans::Key key = SolvedSpans::keyOf(span);
    std::optional<SeedResults> results = solvedSpans().find(key);
    const std::vector<Eigen::Vector3d> seeds = fixedSeeds(span);
    const double bound = searchBound(span, seeds);
    if (!results) {
        results.emplace();
        for (const Eigen::Vector3d& seed : seeds)
            addSeed(span, seed, bound, *results);
        solvedSpans().store(key, *results);
    }
    // The hint's own box, so that a hint beyond the fixed seeds' still has a turn of room; the fixed seeds' results
    // do not depend on it.
    if (hint && hint->allFinite())
        addSeed(span, *hint, std::max(bound, searchBound(span, {*hint})), *results);

    std::vector<FlightSolution> solutions = std::move(results->solutions);
    if (solutions.empty())
        throw std::invalid_argument("no free flight found that meets the next key");
    std::sort(solutions.begin(), solutions.end(),
              [](const FlightSolution& a, const FlightSolution& b) { return a.kineticEnergy < b.kineticEnergy; });
    if (solutions.size() > kMaxFlightSolutions)
        solutions.resize(kMaxFlightSolutions);
    return solutions;
}

FlightCacheStatistics flightCacheStatistics() { return solvedSpans().statistics(); }

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
