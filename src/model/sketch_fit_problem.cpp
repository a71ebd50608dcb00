#include "model/sketch_fit_problem.h"

#include "model/track_evaluation.h"

#include <algorithm>
#include <cmath>
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

fit::AngularVelocityTarget sketchTarget(const MotionTrack& track, const fit::TimeWindow& window)
{
    MotionTrack keyed = track;
    keyed.sketch.fittedCurve.clear();
    const TrackMotion motion(keyed);
    const std::vector<std::vector<fit::TimedVector>> strokes = timedStrokes(track);
    const std::vector<StrokeDirection> directions = strokeDirections(strokes);

    std::vector<fit::TimedVector> samples;
    for (const double time : targetTimes(window, strokes, track.sketch.magnitude)) {
        const Eigen::Vector3d omega = motion.angularVelocity(time);
        const double speed = sketchedMagnitude(track.sketch.magnitude, time).value_or(omega.norm());
        // The latest stroke covering this time wins.
        const auto stroke = std::find_if(directions.rbegin(), directions.rend(), [time](const StrokeDirection& s) {
            return time >= s.start && time <= s.end;
        });
        Eigen::Vector3d direction = Eigen::Vector3d::Zero();
        if (stroke != directions.rend())
            direction = stroke->direction.at(time);
        else if (omega.norm() > kStill)
            direction = omega.normalized();
        samples.push_back({time, speed * direction});
    }
    return fit::AngularVelocityTarget::fromSamples(std::move(samples));
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

SketchFitProblem sketchFitProblem(const MotionTrack& track)
{
    if (track.keys.size() < 2)
        throw SketchFitError(
            SketchFitError::tr("The fit needs at least two keyframes on the selected object.").toStdString());
    if (track.interpolation != InterpolationMethod::Hermite)
        throw SketchFitError(SketchFitError::tr("The fit bends the Hermite spline through the keys: choose Hermite "
                                                "interpolation for this object first.")
                                 .toStdString());
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

    std::vector<fit::FitKey> keys;
    keys.reserve(track.keys.size());
    for (const Keyframe& key : track.keys)
        keys.push_back({key.time, key.pose.orientation, key.constrained});
    fit::FitSettings settings;
    settings.alpha = sketch.alpha;
    settings.beta = sketch.beta;
    settings.delta = sketch.delta;
    settings.window = window;
    return {std::move(keys), sketchTarget(track, *window), settings};
}

FitResult appliedFitResult(const MotionTrack& track, const fit::FitResult& result)
{
    if (result.keys.size() != track.keys.size())
        throw std::invalid_argument("the fit's keys are not the track's: " + std::to_string(result.keys.size()) +
                                    " for " + std::to_string(track.keys.size()));
    FitResult applied{result.controlPoints, track.keys};
    for (std::size_t i = 0; i < applied.keys.size(); ++i)
        if (!applied.keys[i].constrained)
            applied.keys[i].pose.orientation = result.keys[i].rotation;
    return applied;
}

} // namespace gyre::model
