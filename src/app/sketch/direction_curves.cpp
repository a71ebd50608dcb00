#include "app/sketch/direction_curves.h"

#include "model/sketch_fit_problem.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace gyre::app {

std::vector<DirectionRun> sampleDirections(const model::TrackMotion& motion, double start, double end, int sampleCount)
{
    std::vector<DirectionRun> runs;
    bool inRun = false;
    for (int i = 0; i < sampleCount; ++i) {
        const double time = i + 1 == sampleCount ? end : start + (end - start) * i / (sampleCount - 1);
        const Eigen::Vector3d omega = motion.angularVelocity(time);
        const double speed = omega.norm();
        if (!(speed >= kStillAngularSpeed)) {
            inRun = false;
            continue;
        }
        if (!inRun)
            runs.emplace_back();
        runs.back().push_back({time, omega / speed});
        inRun = true;
    }
    return runs;
}

std::optional<Eigen::Vector3d> directionAt(const std::vector<DirectionRun>& runs, double time)
{
    for (const DirectionRun& run : runs) {
        if (run.empty() || time < run.front().time || time > run.back().time)
            continue;
        const auto after = std::lower_bound(run.begin(), run.end(), time,
                                            [](const fit::TimedVector& sample, double t) { return sample.time < t; });
        if (after == run.begin())
            return after->value;
        const auto before = std::prev(after);
        // Samples are dense (kSamplesPerSecond), so the normalised chord is the great arc to well
        // within a pixel.
        const double u = (time - before->time) / (after->time - before->time);
        return ((1.0 - u) * before->value + u * after->value).normalized();
    }
    return std::nullopt;
}

std::optional<double> nearestSampleTime(const std::vector<DirectionRun>& runs, const Eigen::Vector3d& direction)
{
    std::optional<double> nearestTime;
    double largestDot = -2.0;
    for (const DirectionRun& run : runs)
        for (const fit::TimedVector& sample : run) {
            const double dot = sample.value.dot(direction);
            if (dot > largestDot) {
                largestDot = dot;
                nearestTime = sample.time;
            }
        }
    return nearestTime;
}

bool sameCurves(const SphereCurves& a, const SphereCurves& b)
{
    const auto sameRuns = [](const std::vector<DirectionRun>& first, const std::vector<DirectionRun>& second) {
        const auto sameSample = [](const fit::TimedVector& p, const fit::TimedVector& q) {
            return p.time == q.time && p.value == q.value;
        };
        return std::equal(first.begin(), first.end(), second.begin(), second.end(),
                          [&](const DirectionRun& p, const DirectionRun& q) {
                              return std::equal(p.begin(), p.end(), q.begin(), q.end(), sameSample);
                          });
    };
    return a.fitSpan == b.fitSpan && sameRuns(a.motion, b.motion) && sameRuns(a.beforeFit, b.beforeFit)
        && sameRuns(a.targetStrokes, b.targetStrokes);
}

SphereCurves sphereCurves(const model::SharedTrackMotion& motion, double start, double end)
{
    const model::MotionTrack& track = motion.track();
    const int sampleCount = std::clamp(static_cast<int>(std::ceil((end - start) * kSamplesPerSecond)) + 1, 2, kMaxSamples);
    SphereCurves curves;
    curves.motion = sampleDirections(motion.motion(), start, end, sampleCount);
    const std::vector<HermiteControlPoint>& fitted = track.sketch.fittedCurve;
    if (!fitted.empty()) {
        curves.fitSpan = std::pair(fitted.front().time, fitted.back().time);
        const double spanSeconds = fitted.back().time - fitted.front().time;
        const int spanSamples = std::clamp(static_cast<int>(std::ceil(spanSeconds * kSamplesPerSecond)) + 1, 2, kMaxSamples);
        curves.beforeFit = sampleDirections(motion.motionWithoutFit(), fitted.front().time, fitted.back().time, spanSamples);
    }
    curves.targetStrokes = model::timedStrokes(track);
    return curves;
}

std::vector<double> strokeTimes(const std::vector<Eigen::Vector3d>& points, const std::vector<DirectionRun>& motion,
                                double fps)
{
    if (points.size() < 2)
        return {};
    const std::optional<double> first = nearestSampleTime(motion, points.front());
    const std::optional<double> last = nearestSampleTime(motion, points.back());
    if (!first || !last || !(*last - *first >= 1.0 / fps))
        return {};
    const std::vector<fit::TimedVector> spread = fit::spreadByArcLength(points, *first, *last);
    // spreadByArcLength drops a point that repeats the one before; such a stroke cannot be timed
    // point by point.
    if (spread.size() != points.size())
        return {};
    std::vector<double> times;
    times.reserve(spread.size());
    for (const fit::TimedVector& point : spread)
        times.push_back(point.time);
    return times;
}

std::optional<std::vector<model::DirectionStroke>> eraseStrokePoints(
    const model::DirectionStroke& stroke, const std::function<bool(const Eigen::Vector3d&)>& erased)
{
    const bool timed = !stroke.times.empty();
    std::vector<model::DirectionStroke> pieces;
    model::DirectionStroke piece;
    bool anyErased = false;
    auto endPiece = [&] {
        if (piece.points.size() >= 2)
            pieces.push_back(std::move(piece));
        piece = {};
    };
    for (std::size_t i = 0; i < stroke.points.size(); ++i) {
        if (erased(stroke.points[i])) {
            anyErased = true;
            endPiece();
            continue;
        }
        piece.points.push_back(stroke.points[i]);
        if (timed)
            piece.times.push_back(stroke.times[i]);
    }
    endPiece();
    if (!anyErased)
        return std::nullopt;
    return pieces;
}

} // namespace gyre::app
