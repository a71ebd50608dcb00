#pragma once
// What the sphere view draws and how it times and erases strokes, apart from the widget: the direction
// ω(t)/|ω(t)| of a track's angular velocity sampled over time, lookups along it, the timing rule for a
// drawn stroke and the erasing of a stroke's points.

#include "fit/angular_velocity_target.h"
#include "model/motion_cache.h"
#include "model/scene.h"
#include "model/track_evaluation.h"

#include <Eigen/Core>

#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace gyre::app {

// Consecutive samples of the direction of ω, time increasing; a curve breaks where the motion stops
// turning, so a direction curve is a list of runs.
using DirectionRun = std::vector<fit::TimedVector>;

// Below this |ω|, in rad/s, the motion does not turn and ω has no direction to show.
inline constexpr double kStillAngularSpeed = 1e-6;

// ω(t)/|ω(t)| at `sampleCount` (≥ 2) times evenly spread over [start, end], both included, skipping
// the times where |ω| < kStillAngularSpeed.
std::vector<DirectionRun> sampleDirections(const model::TrackMotion& motion, double start, double end, int sampleCount);

// The direction at `time`, along the great arc between the samples either side; none outside the
// runs or in a gap between them.
std::optional<Eigen::Vector3d> directionAt(const std::vector<DirectionRun>& runs, double time);

// The time of the sample nearest `direction` on the sphere (largest dot product), the earliest of
// equally near ones; none without samples.
std::optional<double> nearestSampleTime(const std::vector<DirectionRun>& runs, const Eigen::Vector3d& direction);

// Everything the sphere view shows for one track over the scene's range, made off the UI thread.
struct SphereCurves {
    std::vector<DirectionRun> motion;     // the track's motion, its fit included
    std::optional<std::pair<double, double>> fitSpan; // the span of the applied fit, if any
    std::vector<DirectionRun> beforeFit;  // the motion without its fit, over fitSpan only
    // The strokes as the fit reads them: timed, the pattern applied (model::timedStrokes).
    std::vector<std::vector<fit::TimedVector>> targetStrokes;
};

// Whether `a` and `b` draw the same, sample for sample. A key moved but not turned, at every move of a
// drag, leaves the direction of ω as it was: the view then redraws nothing (issue 18).
bool sameCurves(const SphereCurves& a, const SphereCurves& b);

// Samples per second of scene time, and the most samples of one curve.
inline constexpr double kSamplesPerSecond = 240.0;
inline constexpr int kMaxSamples = 20000;

// The curves of the track's shared motion. Throws std::invalid_argument where TrackMotion does (a
// subdivision too large to hold).
SphereCurves sphereCurves(const model::SharedTrackMotion& motion, double start, double end);

// The timing rule for a stroke drawn over the motion's direction curve, which it replaces there: its
// first point takes the time of the motion sample nearest it on the sphere, its last point the time
// of the sample nearest that, and the points between are spread over those two times in proportion
// to arc length along the great arcs joining them. When the two times are less than one frame
// (1/fps) apart or run backwards, or the stroke has fewer than two points or there are no samples,
// the stroke stays untimed (no times), and the fit spreads it over the whole edit window.
std::vector<double> strokeTimes(const std::vector<Eigen::Vector3d>& points, const std::vector<DirectionRun>& motion,
                                double fps);

// What is left of `stroke` once the points `erased` picks are taken out: nothing erased gives none;
// otherwise the runs of consecutive remaining points (each with its own times), in order, of at
// least two points each, for a lone point is no curve. An empty list: the stroke goes.
std::optional<std::vector<model::DirectionStroke>> eraseStrokePoints(
    const model::DirectionStroke& stroke, const std::function<bool(const Eigen::Vector3d&)>& erased);

} // namespace gyre::app
