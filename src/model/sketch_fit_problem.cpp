#include "model/sketch_fit_problem.h"

#include "model/fit_input.h"
#include "model/track_evaluation.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace gyre::model {

namespace {

// Target samples per second where the sketch gives none: dense enough that ω linear between them
// follows the motion's own angular velocity closely at any spin an artist animates.
constexpr double kTargetSamplesPerSecond = 120.0;
// The most target samples a sketch fit builds over its window: 2.4 hours at kTargetSamplesPerSecond,
// each sample an evaluation of the track and a few dozen bytes, so the target takes seconds and
// megabytes at most.
constexpr double kMaxTargetSamples = 1048576.0;
// Target sample times closer than this are one sample.
constexpr double kSameTime = 1e-9;
// Below this |ω| (rad/s) the motion has no spin axis to keep.
constexpr double kStill = 1e-9;

using Span = std::pair<double, double>;

std::optional<Span> unite(const std::optional<Span>& span, double start, double end)
{
    if (!span)
        return Span{start, end};
    return Span{std::min(span->first, start), std::max(span->second, end)};
}

// The span the sketch's timed parts cover; the keys' span when only untimed strokes are drawn.
std::optional<Span> sketchedSpan(const MotionTrack& track)
{
    const SketchState& sketch = track.sketch;
    std::optional<Span> span;
    for (const DirectionStroke& stroke : sketch.directionStrokes)
        if (!stroke.times.empty())
            span = unite(span, stroke.times.front(), stroke.times.back());
    if (!sketch.magnitude.empty())
        span = unite(span, sketch.magnitude.front().time, sketch.magnitude.back().time);
    const bool anyUntimedStroke = std::ranges::any_of(
        sketch.directionStrokes, [](const DirectionStroke& stroke) { return stroke.times.empty(); });
    if (anyUntimedStroke)
        return Span{track.keys.front().time, track.keys.back().time};
    return span;
}

std::vector<fit::TimedVector> timedStroke(const DirectionStroke& stroke, const fit::TimeWindow& window)
{
    if (stroke.times.empty())
        return fit::spreadByArcLength(stroke.points, window.start, window.end);
    std::vector<fit::TimedVector> timed;
    timed.reserve(stroke.points.size());
    for (std::size_t i = 0; i < stroke.points.size(); ++i)
        timed.push_back({stroke.times[i], stroke.points[i]});
    return timed;
}

std::vector<fit::TimedVector> withPattern(std::vector<fit::TimedVector> stroke, const SketchState& sketch)
{
    if (sketch.pattern.size() < 2 || sketch.patternRepeat < 1)
        return stroke;
    try {
        return fit::applyPattern(stroke, sketch.pattern, sketch.patternRepeat);
    } catch (const std::invalid_argument&) {
        return stroke; // a stroke of no length, or a pattern with no extent along it: nothing to follow
    }
}

// One stroke as a direction over time: its great arcs, read through the fit's own sketch target with
// a unit magnitude.
struct StrokeDirection {
    double start = 0.0;
    double end = 0.0;
    fit::AngularVelocityTarget direction;
};

std::vector<StrokeDirection> strokeDirections(const std::vector<std::vector<fit::TimedVector>>& strokes)
{
    std::vector<StrokeDirection> directions;
    for (std::size_t i = 0; i < strokes.size(); ++i) {
        const std::vector<fit::TimedVector>& stroke = strokes[i];
        if (stroke.size() < 2)
            continue; // a single point covers no time
        try {
            const double start = stroke.front().time;
            const double end = stroke.back().time;
            directions.push_back({start, end, fit::AngularVelocityTarget::fromSketch(stroke, {{start, 1.0}, {end, 1.0}})});
        } catch (const std::invalid_argument& problem) {
            throw SketchFitError(SketchFitError::tr("Direction stroke %1 cannot be followed: %2")
                                     .arg(i + 1)
                                     .arg(QString::fromUtf8(problem.what()))
                                     .toStdString());
        }
    }
    return directions;
}

// The sketched magnitude at `time`, where the curve covers it.
std::optional<double> sketchedMagnitude(const std::vector<MagnitudePoint>& curve, double time)
{
    if (curve.size() < 2 || time < curve.front().time || time > curve.back().time)
        return std::nullopt;
    const auto after = std::ranges::upper_bound(curve, time, {}, &MagnitudePoint::time);
    if (after == curve.end())
        return curve.back().magnitude;
    const MagnitudePoint& b = *after;
    const MagnitudePoint& a = *(after - 1);
    const double u = (time - a.time) / (b.time - a.time);
    return a.magnitude + u * (b.magnitude - a.magnitude);
}

// A grid over the window, plus every time the sketch gives inside it, so the target passes through
// each drawn point.
std::vector<double> targetTimes(const fit::TimeWindow& window, const std::vector<std::vector<fit::TimedVector>>& strokes,
                                const std::vector<MagnitudePoint>& magnitude)
{
    std::vector<double> times;
    const double length = window.end - window.start;
    const auto steps = static_cast<std::size_t>(std::ceil(length * kTargetSamplesPerSecond));
    for (std::size_t k = 0; k <= steps; ++k)
        times.push_back(window.start + length * static_cast<double>(k) / static_cast<double>(steps));
    const auto addInside = [&](double time) {
        if (time > window.start && time < window.end)
            times.push_back(time);
    };
    for (const auto& stroke : strokes)
        for (const fit::TimedVector& point : stroke)
            addInside(point.time);
    for (const MagnitudePoint& point : magnitude)
        addInside(point.time);
    std::ranges::sort(times);
    const auto repeated = std::ranges::unique(times, [](double a, double b) { return b - a < kSameTime; });
    times.erase(repeated.begin(), repeated.end());
    return times;
}

// What was drawn over the window, read at any time together with a motion's own angular velocity there.
class DrawnSketch {
public:
    explicit DrawnSketch(const MotionTrack& track)
        : strokes_(timedStrokes(track))
        , directions_(strokeDirections(strokes_))
        , magnitude_(track.sketch.magnitude)
    {
    }

    // The drawn ω at `time`, completed by `omega`, some motion's angular velocity there: the drawn speed
    // or |omega|, along the latest stroke covering `time` or the axis of `omega`.
    Eigen::Vector3d completedAt(double time, const Eigen::Vector3d& omega) const
    {
        const double speed = sketchedMagnitude(magnitude_, time).value_or(omega.norm());
        if (const std::optional<Eigen::Vector3d> direction = drawnDirection(time))
            return speed * *direction;
        return omega.norm() > kStill ? Eigen::Vector3d(speed * omega.normalized()) : Eigen::Vector3d::Zero();
    }

    // |omega − completedAt(time, omega)|²; a motion standing still has no axis to carry a drawn speed,
    // which then counts in full.
    double squaredErrorAt(double time, const Eigen::Vector3d& omega) const
    {
        if (omega.norm() <= kStill && !drawnDirection(time))
            return std::pow(sketchedMagnitude(magnitude_, time).value_or(0.0), 2);
        return (omega - completedAt(time, omega)).squaredNorm();
    }

    std::vector<double> sampleTimes(const fit::TimeWindow& window) const { return targetTimes(window, strokes_, magnitude_); }

private:
    // The latest stroke covering `time`, where one does.
    std::optional<Eigen::Vector3d> drawnDirection(double time) const
    {
        const auto stroke = std::find_if(directions_.rbegin(), directions_.rend(), [time](const StrokeDirection& s) {
            return time >= s.start && time <= s.end;
        });
        if (stroke == directions_.rend())
            return std::nullopt;
        return stroke->direction.at(time);
    }

    std::vector<std::vector<fit::TimedVector>> strokes_;
    std::vector<StrokeDirection> directions_;
    std::vector<MagnitudePoint> magnitude_;
};

// The drawn ω completed by the motion through the keys, at the target's sample times.
fit::AngularVelocityTarget sketchTarget(const MotionTrack& track, const TrackMotion& keyed, const fit::TimeWindow& window)
{
    const DrawnSketch drawn(track);
    std::vector<fit::TimedVector> samples;
    for (const double time : drawn.sampleTimes(window))
        samples.push_back({time, drawn.completedAt(time, keyed.angularVelocity(time))});
    return fit::AngularVelocityTarget::fromSamples(std::move(samples));
}

// The motion through the keys as the fit reads it: orientation, and q′ = ½ω·q from its angular velocity.
fit::InitialMotion initialMotionOf(std::shared_ptr<const TrackMotion> keyed)
{
    return [keyed = std::move(keyed)](double time) {
        const Eigen::Quaterniond value = keyed->at(time).orientation;
        const Eigen::Vector3d omega = keyed->angularVelocity(time);
        const Eigen::Quaterniond halfOmega(0.0, 0.5 * omega.x(), 0.5 * omega.y(), 0.5 * omega.z());
        return OrientationSample{value, halfOmega * value, omega};
    };
}

} // namespace

std::optional<fit::TimeWindow> editWindow(const MotionTrack& track)
{
    if (track.keys.size() < 2)
        return std::nullopt;
    const std::optional<Span> span = track.sketch.window ? track.sketch.window : sketchedSpan(track);
    if (!span)
        return std::nullopt;
    const fit::TimeWindow window{std::max(span->first, track.keys.front().time),
                                 std::min(span->second, track.keys.back().time)};
    if (!(window.end > window.start))
        return std::nullopt;
    return window;
}

std::vector<std::vector<fit::TimedVector>> timedStrokes(const MotionTrack& track)
{
    const std::optional<fit::TimeWindow> window = editWindow(track);
    if (!window)
        return {};
    std::vector<std::vector<fit::TimedVector>> strokes;
    for (const DirectionStroke& stroke : track.sketch.directionStrokes)
        strokes.push_back(withPattern(timedStroke(stroke, *window), track.sketch));
    return strokes;
}

void checkSketchFittable(const MotionTrack& track)
{
    if (track.keys.size() < 2)
        throw SketchFitError(
            SketchFitError::tr("The fit needs at least two keyframes on the selected object.").toStdString());
    const SketchState& sketch = track.sketch;
    if (sketch.directionStrokes.empty() && sketch.magnitude.empty())
        throw SketchFitError(SketchFitError::tr("Nothing is sketched yet: draw the direction of the angular velocity "
                                                "on the sphere, or its magnitude on the plot.")
                                 .toStdString());
    const std::optional<fit::TimeWindow> window = editWindow(track);
    if (!window)
        throw SketchFitError(SketchFitError::tr("The edit window has no length inside the keys' span: widen it, or "
                                                "sketch between the first and the last key.")
                                 .toStdString());

    const double samples = std::ceil((window->end - window->start) * kTargetSamplesPerSecond);
    if (samples > kMaxTargetSamples)
        throw SketchFitError(SketchFitError::tr("The edit window of %1 s needs %2 target samples at %3 a second; the "
                                                "budget is %4: narrow the window.")
                                 .arg(window->end - window->start)
                                 .arg(samples, 0, 'f', 0)
                                 .arg(kTargetSamplesPerSecond)
                                 .arg(kMaxTargetSamples, 0, 'f', 0)
                                 .toStdString());
    if (sketch.pattern.size() >= 2 && sketch.patternRepeat >= 1) {
        try {
            fit::checkPatternPointCount(sketch.pattern.size(), sketch.patternRepeat);
        } catch (const std::invalid_argument& problem) {
            throw SketchFitError(SketchFitError::tr("The pattern cannot be repeated: %1").arg(QString::fromUtf8(problem.what())).toStdString());
        }
    }
}

SketchFitProblem sketchFitProblem(const MotionTrack& track, const MassProperties& body)
{
    checkSketchFittable(track);
    const SketchState& sketch = track.sketch;
    // Checked: the edit window is there.
    const fit::TimeWindow window = *editWindow(track);
    const MotionTrack unfitted = withoutFit(track);
    const auto keyed = std::make_shared<const TrackMotion>(unfitted, EulerConvention{}, body);
    const bool screw = track.interpolation == InterpolationMethod::Screw;
    std::vector<fit::FitKey> keys;
    keys.reserve(unfitted.keys.size());
    for (const Keyframe& key : unfitted.keys)
        keys.push_back({key.time, screw ? keyed->at(key.time).orientation : key.pose.orientation, key.constrained});
    fit::FitSettings settings;
    settings.alpha = sketch.alpha;
    settings.beta = sketch.beta;
    settings.delta = sketch.delta;
    settings.window = window;
    fit::AngularVelocityTarget target = sketchTarget(track, *keyed, window);
    const bool hermite = track.interpolation == InterpolationMethod::Hermite;
    fit::InitialMotion initialMotion = hermite ? fit::InitialMotion{} : initialMotionOf(keyed);
    return {std::move(keys), std::move(target), settings, std::move(initialMotion), keyed};
}

fit::FitResult fitSketch(const SketchFitProblem& problem, const fit::FitHooks& hooks)
{
    return fit::fitAngularVelocity(problem.keys, problem.target, problem.settings, hooks, problem.initialMotion);
}

FitResult appliedFitResult(const MotionTrack& track, const fit::FitResult& result)
{
    if (result.keys.size() != track.keys.size())
        throw std::invalid_argument("the fit's keys are not the track's: " + std::to_string(result.keys.size()) +
                                    " for " + std::to_string(track.keys.size()));
    FitResult applied{result.controlPoints, withoutFit(track).keys};
    if (track.interpolation == InterpolationMethod::Screw)
        return applied;
    for (std::size_t i = 0; i < applied.keys.size(); ++i)
        if (!applied.keys[i].constrained)
            applied.keys[i].pose.orientation = result.keys[i].rotation;
    return applied;
}

double drawnError(const MotionTrack& track, const TrackMotion& motion)
{
    const std::optional<fit::TimeWindow> window = editWindow(track);
    if (!window)
        return 0.0;
    const DrawnSketch drawn(track);
    const std::vector<double> times = drawn.sampleTimes(*window);
    const auto squaredError = [&](double time) { return drawn.squaredErrorAt(time, motion.angularVelocity(time)); };
    double sum = 0.0;
    double previous = squaredError(times.front());
    for (std::size_t k = 1; k < times.size(); ++k) {
        const double current = squaredError(times[k]);
        sum += 0.5 * (previous + current) * (times[k] - times[k - 1]);
        previous = current;
    }
    return sum;
}

DrawnErrors drawnErrors(const MotionTrack& track, const TrackMotion& motionWithoutFit, const FitResult& applied,
                        const MassProperties& body)
{
    return {drawnError(track, motionWithoutFit),
            drawnError(track, TrackMotion(withFitApplied(track, applied), EulerConvention{}, body))};
}

double relativeDelta(const MotionTrack& track, double absoluteDelta)
{
    try {
        // An absolute δ is from a file older than ballistic tracks: no track here flies a body.
        const SketchFitProblem problem = sketchFitProblem(track, MassProperties{});
        return fit::relativeFragmentError(absoluteDelta, fit::targetMeanSquare(problem.target, *problem.settings.window,
                                                                               problem.settings.fragmentSeconds));
    } catch (const std::invalid_argument&) {
        return absoluteDelta; // nothing to fit: no threshold to keep
    }
}

} // namespace gyre::model
