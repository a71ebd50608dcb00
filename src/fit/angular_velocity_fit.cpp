#include "fit/angular_velocity_fit.h"

#include "core/number_text.h"
#include "core/quaternion_math.h"
#include "fit/compressed_cost.h"
#include "fit/gauss_legendre.h"
#include "fit/segment_energy.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <numeric>
#include <ranges>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

namespace gyre::fit {

namespace {

// Quadrature of the energy: about two nodes per frame at 24 fps, at least four per segment.
constexpr double kNodesPerSecond = 48.0;
constexpr int kMinNodesPerSegment = 4;
constexpr int kMaxNodesPerSegment = 64;
// Nodes per piece (a fragment or segment cut at control points) when measuring errors and energies.
constexpr int kMeasureNodes = 8;

// The unit-norm condition U = 0 is a penalty μU that grows tenfold until | |q| − 1 | ≤ 5·10⁻⁴ at
// kNormSamplesPerSegment samples of every segment: half the 10⁻³ promised, as margin for the
// stretches between samples. The penalty starts at kInitialPenalty relative to β.
constexpr double kInitialPenalty = 10.0;
constexpr double kPenaltyGrowth = 10.0;
constexpr int kMaxPenaltyIncreases = 8;
constexpr double kNormTolerance = 5e-4;
constexpr int kNormSamplesPerSegment = 32;

// A variable frame is not inserted closer than this fraction of the window to a control point.
constexpr double kMinFrameSpacing = 1e-6;

enum class Role {
    Held,           // a window end inside the animation: value and derivative are the outside curve's
    ConstrainedKey, // value fixed, derivative free
    Free,           // a freed key or a variable frame
};

struct ControlPoint {
    double time = 0.0;
    Role role = Role::Free;
    std::optional<std::size_t> key;    // the input key it stands for, if any
    std::array<double, 4> value{};     // w, x, y, z
    std::array<double, 4> derivative{}; // w, x, y, z per second
};

// The blocks the solve holds constant: a constrained key's or a held end's value, a held end's derivative.
bool valueHeld(const ControlPoint& point) { return point.role != Role::Free; }
bool derivativeHeld(const ControlPoint& point) { return point.role == Role::Held; }

std::array<double, 4> wxyz(const Eigen::Quaterniond& q) { return {q.w(), q.x(), q.y(), q.z()}; }
Eigen::Quaterniond quaternion(const std::array<double, 4>& a) { return {a[0], a[1], a[2], a[3]}; }

std::vector<HermiteControlPoint> hermitePoints(const std::vector<ControlPoint>& points)
{
    std::vector<HermiteControlPoint> hermite;
    hermite.reserve(points.size());
    for (const ControlPoint& point : points)
        hermite.push_back({point.time, quaternion(point.value), quaternion(point.derivative)});
    return hermite;
}

std::vector<OrientationKey> orientationKeys(const std::vector<FitKey>& keys)
{
    std::vector<OrientationKey> orientations;
    orientations.reserve(keys.size());
    for (const FitKey& key : keys)
        orientations.push_back({key.time, key.rotation});
    return orientations;
}

std::string spanText(double start, double end)
{
    return "[" + std::to_string(start) + ", " + std::to_string(end) + "] s";
}

void checkKeys(const std::vector<FitKey>& keys)
{
    if (keys.size() < 2)
        throw std::invalid_argument("the fit needs at least two keys");
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const std::string which = "key " + std::to_string(i);
        if (!std::isfinite(keys[i].time) || !keys[i].rotation.coeffs().allFinite())
            throw std::invalid_argument(which + " is not finite");
        if (keys[i].rotation.squaredNorm() == 0.0)
            throw std::invalid_argument(which + " has a zero quaternion");
        if (i > 0 && !(keys[i].time > keys[i - 1].time))
            throw std::invalid_argument(which + ": key times must strictly increase");
    }
}

void checkSettings(const FitSettings& settings)
{
    const auto require = [](bool holds, const char* message) {
        if (!holds)
            throw std::invalid_argument(message);
    };
    require(settings.alpha >= 0.0 && std::isfinite(settings.alpha), "alpha must be a finite number ≥ 0");
    require(settings.beta > 0.0 && std::isfinite(settings.beta), "beta must be a finite number > 0");
    require(settings.delta > 0.0 && std::isfinite(settings.delta), "delta must be a finite number > 0");
    require(settings.fragmentSeconds > 0.0 && std::isfinite(settings.fragmentSeconds),
            "the fragment length must be a finite number of seconds > 0");
    require(settings.maxRounds >= 1, "the fit needs at least one round");
    require(settings.maxVariableFrames >= 0, "the cap on variable frames must be ≥ 0");
}

} // namespace

void checkFragmentCount(const TimeWindow& window, double fragmentSeconds)
{
    const double fragments = std::ceil((window.end - window.start) / fragmentSeconds);
    if (!(fragments <= kMaxFragments))
        throw std::invalid_argument("a window of " + formatNumber(window.end - window.start) + " s in fragments of " +
                                    formatNumber(fragmentSeconds) + " s makes " + formatNumber(fragments) +
                                    " fragments; the budget is " + formatNumber(kMaxFragments));
}

double relativeFragmentError(double fragmentError, double targetMeanSquare)
{
    return fragmentError / std::max(targetMeanSquare, kSlowestTargetSpeed * kSlowestTargetSpeed);
}

namespace {

// ∫ f(t) dt over [from, to] by `quadrature` on each piece between the times in `cuts` (increasing;
// where the integrand's derivatives jump, as a spline's do at its control points).
template <class Cuts, class Integrand>
double integrateInPieces(const QuadratureRule& quadrature, double from, double to, const Cuts& cuts,
                         const Integrand& integrand)
{
    double sum = 0.0;
    double start = from;
    auto next = std::ranges::upper_bound(cuts, from);
    while (start < to) {
        const double end = next != std::ranges::end(cuts) ? std::min(*next, to) : to;
        for (std::size_t j = 0; j < quadrature.nodes.size(); ++j)
            sum += quadrature.weights[j] * (end - start) * integrand(start + quadrature.nodes[j] * (end - start));
        start = end;
        if (next != std::ranges::end(cuts))
            ++next;
    }
    return sum;
}

// ∫ f(t) dt over each fragment of the window, fragmentSeconds long from its start (the last may be
// shorter): the paper's Eq. 2 pieces, each by integrateInPieces.
template <class Cuts, class Integrand>
std::vector<double> fragmentIntegrals(const QuadratureRule& quadrature, const TimeWindow& window,
                                      double fragmentSeconds, const Cuts& cuts, const Integrand& integrand)
{
    std::vector<double> integrals;
    for (double start = window.start; start < window.end; start += fragmentSeconds)
        integrals.push_back(
            integrateInPieces(quadrature, start, std::min(start + fragmentSeconds, window.end), cuts, integrand));
    return integrals;
}

} // namespace

double targetMeanSquare(const AngularVelocityTarget& target, const TimeWindow& window, double fragmentSeconds)
{
    AngularVelocityTarget::Reader reader(target);
    const std::vector<double> fragments =
        fragmentIntegrals(gaussLegendre(kMeasureNodes), window, fragmentSeconds, std::span<const double>{},
                          [&reader](double t) { return reader.at(t).squaredNorm(); });
    return std::accumulate(fragments.begin(), fragments.end(), 0.0) / (window.end - window.start);
}

namespace {

// The window to refit, checked against the keys and the target.
TimeWindow checkedWindow(const std::vector<FitKey>& keys, const AngularVelocityTarget& target,
                         const FitSettings& settings)
{
    const double first = keys.front().time;
    const double last = keys.back().time;
    if (target.startTime() < first || target.endTime() > last)
        throw std::invalid_argument("the target " + spanText(target.startTime(), target.endTime()) +
                                    " reaches outside the keys' span " + spanText(first, last));
    const TimeWindow window = settings.window.value_or(TimeWindow{target.startTime(), target.endTime()});
    if (!std::isfinite(window.start) || !std::isfinite(window.end) || !(window.start < window.end))
        throw std::invalid_argument("the window must be two finite times, the first before the second");
    if (window.start < first || window.end > last)
        throw std::invalid_argument("the window " + spanText(window.start, window.end) +
                                    " lies outside the keys' span " + spanText(first, last));
    if (window.start < target.startTime() || window.end > target.endTime())
        throw std::invalid_argument("the window " + spanText(window.start, window.end) +
                                    " is not covered by the target " +
                                    spanText(target.startTime(), target.endTime()));
    checkFragmentCount(window, settings.fragmentSeconds);
    return window;
}

class ProgressCallback;

// One run of Algorithm 1.
class FitRun {
public:
    FitRun(const std::vector<FitKey>& keys, const AngularVelocityTarget& target, const FitSettings& settings,
           const FitHooks& hooks, const InitialMotion& initialMotion)
        : keys_(keys)
        , target_(target)
        , settings_(settings)
        , hooks_(hooks)
        , initialMotion_(initialMotion)
        , window_(checkedWindow(keys, target, settings))
        , base_(HermiteQuaternionSpline::throughKeys(orientationKeys(keys)))
        , penalty_(kInitialPenalty * settings.beta)
    {
    }

    FitResult run();

private:
    friend class ProgressCallback;

    OrientationSample initialAt(double time) const { return initialMotion_ ? initialMotion_(time) : base_.sample(time); }
    ControlPoint keyPoint(std::size_t key) const;
    void placeControlPoints();
    bool solveUnitNorm();
    bool solve();
    ceres::CostFunction* segmentEnergy(std::size_t segment, AngularVelocityTarget::Reader& target) const;
    const QuadratureRule& rule(int nodes) const;
    const std::shared_ptr<const SegmentQuadrature>& segmentQuadrature(int nodes) const;
    HermiteQuaternionSpline spline() const { return HermiteQuaternionSpline(hermitePoints(points_)); }
    double largestNormDeviation(const HermiteQuaternionSpline& curve) const;
    // The control points' times, where integrals are cut: the spline's second derivative jumps there.
    auto controlPointTimes() const { return std::views::transform(points_, &ControlPoint::time); }
    EnergyTerms energyTerms(const HermiteQuaternionSpline& curve) const;
    struct FragmentErrors {
        std::vector<double> relative;  // F_n/S̄ of each fragment, in seconds (relativeFragmentError)
        double largest = 0.0;          // the largest F_n
    };
    FragmentErrors fragmentErrors(const HermiteQuaternionSpline& curve) const;
    int insertVariableFrames(const HermiteQuaternionSpline& curve, const std::vector<double>& errors);
    FitResult result(FitOutcome outcome, const HermiteQuaternionSpline& curve) const;
    std::optional<double> largestRelativeError() const
    {
        return errors_ ? std::optional(*std::ranges::max_element(errors_->relative)) : std::nullopt;
    }

    const std::vector<FitKey>& keys_;
    const AngularVelocityTarget& target_;
    const FitSettings& settings_;
    const FitHooks& hooks_;
    const InitialMotion& initialMotion_;
    TimeWindow window_;
    HermiteQuaternionSpline base_;
    std::vector<ControlPoint> points_;
    mutable std::map<int, QuadratureRule> rules_;
    mutable std::map<int, std::shared_ptr<const SegmentQuadrature>> segmentQuadratures_;
    double penalty_;
    int round_ = 0;
    int iterations_ = 0;
    int variableFrames_ = 0;
    double targetMeanSquare_ = 0.0;
    std::optional<FragmentErrors> errors_;  // of the last finished round
    EnergyTerms before_;
};

class ProgressCallback final : public ceres::IterationCallback {
public:
    explicit ProgressCallback(const FitRun& run)
        : run_(run)
    {
    }

    ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override
    {
        if (run_.hooks_.isCancelled && run_.hooks_.isCancelled())
            return ceres::SOLVER_ABORT;
        if (run_.hooks_.onProgress)
            run_.hooks_.onProgress({run_.round_, run_.iterations_ + summary.iteration, 2.0 * summary.cost,
                                    run_.largestRelativeError()});
        return ceres::SOLVER_CONTINUE;
    }

private:
    const FitRun& run_;
};

// Key `key` as a control point: its rotation, and the initial motion's derivative there (the spline's
// own control point when the initial motion is the spline through the keys).
ControlPoint FitRun::keyPoint(std::size_t key) const
{
    const FitKey& fitKey = keys_[key];
    const Role role = fitKey.constrained ? Role::ConstrainedKey : Role::Free;
    if (!initialMotion_) {
        const HermiteControlPoint& initial = base_.controlPoints()[key];
        return {fitKey.time, role, key, wxyz(initial.value), wxyz(initial.derivative)};
    }
    const OrientationSample initial = initialAt(fitKey.time);
    const Eigen::Quaterniond value = fitKey.rotation.normalized();
    // q and −q are one rotation; the derivative goes with the sign of the value it belongs to.
    const double sign = value.coeffs().dot(initial.value.coeffs()) < 0.0 ? -1.0 : 1.0;
    return {fitKey.time, role, key, wxyz(value), wxyz(Eigen::Quaterniond(sign * initial.derivative.coeffs()))};
}

void FitRun::placeControlPoints()
{
    // A held end takes the outside motion's normalised value and derivative: unit, so that the norm
    // condition can hold there, and tangent, so that the fitted curve, once normalised, leaves the end
    // with the outside motion's value and derivative.
    const auto held = [this](double time) {
        const OrientationSample outside = initialAt(time);
        return ControlPoint{time, Role::Held, std::nullopt, wxyz(outside.value), wxyz(outside.derivative)};
    };
    // A window end strictly inside the animation holds the outside curve there; at the animation's
    // own ends there is no outside, and the end key is an ordinary one.
    if (window_.start > keys_.front().time)
        points_.push_back(held(window_.start));
    for (std::size_t i = 0; i < keys_.size(); ++i) {
        const double time = keys_[i].time;
        const bool isEnd = i == 0 || i + 1 == keys_.size();
        const bool inside = (time > window_.start && time < window_.end) ||
                            (isEnd && time >= window_.start && time <= window_.end);
        if (!inside)
            continue;
        points_.push_back(keyPoint(i));
    }
    if (window_.end < keys_.back().time)
        points_.push_back(held(window_.end));
    // Each point on the hemisphere of the one before, so that the cubic in R⁴ between them takes the
    // short way (the spline through the keys is aligned already).
    for (std::size_t k = 1; k < points_.size(); ++k) {
        ControlPoint& point = points_[k];
        if (quaternion(point.value).coeffs().dot(quaternion(points_[k - 1].value).coeffs()) >= 0.0)
            continue;
        for (std::size_t c = 0; c < 4; ++c) {
            point.value[c] = -point.value[c];
            point.derivative[c] = -point.derivative[c];
        }
    }
}

const QuadratureRule& FitRun::rule(int nodes) const
{
    auto found = rules_.find(nodes);
    if (found == rules_.end())
        found = rules_.emplace(nodes, gaussLegendre(nodes)).first;
    return found->second;
}

const std::shared_ptr<const SegmentQuadrature>& FitRun::segmentQuadrature(int nodes) const
{
    auto found = segmentQuadratures_.find(nodes);
    if (found == segmentQuadratures_.end())
        found = segmentQuadratures_.emplace(nodes, std::make_shared<const SegmentQuadrature>(rule(nodes))).first;
    return found->second;
}

ceres::CostFunction* FitRun::segmentEnergy(std::size_t segment, AngularVelocityTarget::Reader& target) const
{
    const double start = points_[segment].time;
    const double duration = points_[segment + 1].time - start;
    // Clamped as a double, so that a long segment cannot overflow the cast.
    const int nodes = static_cast<int>(std::clamp(std::ceil(duration * kNodesPerSecond),
                                                  static_cast<double>(kMinNodesPerSegment),
                                                  static_cast<double>(kMaxNodesPerSegment)));
    const std::shared_ptr<const SegmentQuadrature>& quadrature = segmentQuadrature(nodes);
    std::vector<Eigen::Vector3d> targets;
    targets.reserve(quadrature->nodes().size());
    for (const SegmentQuadrature::Node& node : quadrature->nodes())
        targets.push_back(target.at(start + node.u * duration));
    // The blocks solve() holds constant, in the order they enter the residual: q₀, d₀, q₁, d₁.
    const ControlPoint& from = points_[segment];
    const ControlPoint& to = points_[segment + 1];
    const std::vector<bool> held{valueHeld(from), derivativeHeld(from), valueHeld(to), derivativeHeld(to)};
    return new CompressedCost(std::make_unique<SegmentEnergy>(duration, quadrature, std::move(targets),
                                                              EnergyWeights{settings_.alpha, settings_.beta, penalty_}),
                              held);
}

// Solves once at the current penalty. The hard constraints: a constrained key's quaternion and a held
// window end are constant parameter blocks, so they hold exactly; |q| = 1 is the penalty μU, raised by
// solveUnitNorm until it holds to tolerance (a penalty continuation; the paper used SQP).
bool FitRun::solve()
{
    ceres::Problem problem;
    for (ControlPoint& point : points_) {
        problem.AddParameterBlock(point.value.data(), 4);
        problem.AddParameterBlock(point.derivative.data(), 4);
        if (valueHeld(point))
            problem.SetParameterBlockConstant(point.value.data());
        if (derivativeHeld(point))
            problem.SetParameterBlockConstant(point.derivative.data());
    }
    AngularVelocityTarget::Reader target(target_);
    for (std::size_t segment = 0; segment + 1 < points_.size(); ++segment) {
        ControlPoint& from = points_[segment];
        ControlPoint& to = points_[segment + 1];
        problem.AddResidualBlock(segmentEnergy(segment, target), nullptr, from.value.data(), from.derivative.data(),
                                 to.value.data(), to.derivative.data());
    }

    ceres::Solver::Options options;
    // Each residual block touches the four parameter blocks of one segment, so the normal equations
    // are block-banded (bandwidth two control points, 16 unknowns): SPARSE_NORMAL_CHOLESKY with
    // Eigen's simplicial LDLᵀ, after Ceres' default AMD ordering of the parameter blocks, which on a
    // chain finds the order along it and so no fill beyond the band. A factorisation then costs time
    // linear in the segments and under 4% of a fit at 3,000 keys. What grew faster than linearly was
    // the Jacobian Ceres stores and walks seven times an iteration (evaluation, validity check, column
    // norms, scaling, JᵀJ, J·x and Jᵀ·x): 80 rows a segment, 20 MB at 2,000 keys, out of every cache.
    // CompressedCost hands Ceres 17 rows a segment with the same JᵀJ, Jᵀr and cost instead, so the
    // steps are those of the full residuals (compressed_cost.h). DENSE_QR or DENSE_NORMAL_CHOLESKY
    // would cost the cube of the unknowns; ITERATIVE_SCHUR needs an e-block structure the chain lacks.
    options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    options.sparse_linear_algebra_library_type = ceres::EIGEN_SPARSE;
    options.num_threads = 1;  // one core per fit, and a result independent of scheduling
    options.max_num_iterations = 100;
    options.function_tolerance = 1e-9;
    options.gradient_tolerance = 1e-12;
    options.parameter_tolerance = 1e-10;
    options.logging_type = ceres::SILENT;
    ProgressCallback callback(*this);
    options.callbacks.push_back(&callback);

    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    iterations_ += std::max(0, static_cast<int>(summary.iterations.size()) - 1);
    if (summary.termination_type == ceres::USER_FAILURE)
        return false;
    if (summary.termination_type == ceres::FAILURE)
        throw std::runtime_error("the fit's solver failed: " + summary.message);
    return true;
}

bool FitRun::solveUnitNorm()
{
    for (int increase = 0;; ++increase) {
        if (!solve())
            return false;
        if (largestNormDeviation(spline()) <= kNormTolerance || increase == kMaxPenaltyIncreases)
            return true;
        penalty_ *= kPenaltyGrowth;
    }
}

double FitRun::largestNormDeviation(const HermiteQuaternionSpline& curve) const
{
    double largest = 0.0;
    for (std::size_t segment = 0; segment + 1 < points_.size(); ++segment) {
        const double start = points_[segment].time;
        const double step = (points_[segment + 1].time - start) / kNormSamplesPerSegment;
        for (int k = 0; k <= kNormSamplesPerSegment; ++k)
            largest = std::max(largest, std::abs(curve.raw(start + k * step).value.norm() - 1.0));
    }
    return largest;
}

EnergyTerms FitRun::energyTerms(const HermiteQuaternionSpline& curve) const
{
    const QuadratureRule& quadrature = rule(kMeasureNodes);
    EnergyTerms terms;
    AngularVelocityTarget::Reader target(target_);
    terms.angular = integrateInPieces(quadrature, window_.start, window_.end, controlPointTimes(), [&](double t) {
        return (curve.sample(t).angularVelocity - target.at(t)).squaredNorm();
    });
    terms.tangential = integrateInPieces(quadrature, window_.start, window_.end, controlPointTimes(), [&](double t) {
        const HermiteQuaternionSpline::RawSample raw = curve.raw(t);
        const double along = raw.value.coeffs().dot(raw.secondDerivative.coeffs());
        return raw.secondDerivative.squaredNorm() - along * along / raw.value.squaredNorm();
    });
    return terms;
}

// F_n of the paper's Eq. 2 on fragments of length ΔT from the window's start (the last may be
// shorter), each relative to the target's size.
FitRun::FragmentErrors FitRun::fragmentErrors(const HermiteQuaternionSpline& curve) const
{
    FragmentErrors errors;
    AngularVelocityTarget::Reader target(target_);
    const std::vector<double> fragments =
        fragmentIntegrals(rule(kMeasureNodes), window_, settings_.fragmentSeconds, controlPointTimes(),
                          [&](double t) { return (curve.sample(t).angularVelocity - target.at(t)).squaredNorm(); });
    for (const double error : fragments) {
        errors.relative.push_back(relativeFragmentError(error, targetMeanSquare_));
        errors.largest = std::max(errors.largest, error);
    }
    return errors;
}

// Inserts a variable frame at the middle of each fragment whose error exceeds δ, worst first, up to
// the cap; each starts on the current curve, so the curve is unchanged until the next solve.
int FitRun::insertVariableFrames(const HermiteQuaternionSpline& curve, const std::vector<double>& errors)
{
    std::vector<std::size_t> poor;
    for (std::size_t n = 0; n < errors.size(); ++n)
        if (errors[n] > settings_.delta)
            poor.push_back(n);
    std::ranges::stable_sort(poor, [&errors](std::size_t a, std::size_t b) { return errors[a] > errors[b]; });
    const double spacing = kMinFrameSpacing * (window_.end - window_.start);
    int inserted = 0;
    for (const std::size_t n : poor) {
        if (variableFrames_ == settings_.maxVariableFrames)
            break;
        const double start = window_.start + static_cast<double>(n) * settings_.fragmentSeconds;
        const double middle = 0.5 * (start + std::min(start + settings_.fragmentSeconds, window_.end));
        const auto at = std::ranges::lower_bound(points_, middle, {}, &ControlPoint::time);
        const bool crowded = (at != points_.end() && at->time - middle < spacing) ||
                             (at != points_.begin() && middle - std::prev(at)->time < spacing);
        if (crowded)
            continue;
        const HermiteQuaternionSpline::RawSample raw = curve.raw(middle);
        points_.insert(at, {middle, Role::Free, std::nullopt, wxyz(raw.value), wxyz(raw.derivative)});
        ++variableFrames_;
        ++inserted;
    }
    return inserted;
}

FitResult FitRun::result(FitOutcome outcome, const HermiteQuaternionSpline& curve) const
{
    FitResult result;
    result.outcome = outcome;
    result.window = window_;
    result.keys = keys_;
    result.rounds = round_;
    result.iterations = iterations_;
    result.variableFrames = variableFrames_;
    result.before = before_;
    if (outcome == FitOutcome::Cancelled)
        return result;
    result.controlPoints = curve.controlPoints();
    for (const ControlPoint& point : points_) {
        if (!point.key || point.role != Role::Free)
            continue;
        FitKey& key = result.keys[*point.key];
        key.rotation = alignedWith(quaternion(point.value).normalized(), key.rotation);
    }
    result.largestRelativeError = largestRelativeError().value_or(0.0);
    result.largestFragmentError = errors_ ? errors_->largest : 0.0;
    result.targetMeanSquare = targetMeanSquare_;
    result.largestNormDeviation = largestNormDeviation(curve);
    result.after = energyTerms(curve);
    return result;
}

FitResult FitRun::run()
{
    placeControlPoints();
    targetMeanSquare_ = targetMeanSquare(target_, window_, settings_.fragmentSeconds);
    before_ = energyTerms(spline());
    while (true) {
        ++round_;
        if (!solveUnitNorm())
            return result(FitOutcome::Cancelled, spline());
        const HermiteQuaternionSpline curve = spline();
        errors_ = fragmentErrors(curve);
        if (*largestRelativeError() <= settings_.delta)
            return result(FitOutcome::Converged, curve);
        if (round_ == settings_.maxRounds)
            return result(FitOutcome::RoundLimit, curve);
        if (insertVariableFrames(curve, errors_->relative) == 0)
            return result(variableFrames_ == settings_.maxVariableFrames ? FitOutcome::VariableFrameLimit
                                                                         : FitOutcome::NoPlaceForFrame,
                          curve);
    }
}

} // namespace

FitResult fitAngularVelocity(const std::vector<FitKey>& keys, const AngularVelocityTarget& target,
                             const FitSettings& settings, const FitHooks& hooks, const InitialMotion& initialMotion)
{
    checkKeys(keys);
    checkSettings(settings);
    const auto started = std::chrono::steady_clock::now();
    FitRun run(keys, target, settings, hooks, initialMotion);
    FitResult result = run.run();
    result.solveSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

} // namespace gyre::fit
