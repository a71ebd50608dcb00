#pragma once
// From a track's sketch to the angular-velocity fit and back (the sketch-editing paper's interface,
// docs/fit.md "In the app").
//
// The edit window is the sketch's own window if it has one, else the span the timed strokes and the
// magnitude curve cover, clipped to the keys' span. Over it the target is ωˢ(t) = m(t)·d(t):
// - d(t), the direction: where a timed stroke covers t, the stroke (the pattern applied along it);
//   where strokes overlap, the later stroke wins, as a redrawn part replaces what was drawn before.
//   Elsewhere the direction of the motion through the keys, so an undrawn part keeps its spin axis.
// - m(t), the magnitude: the sketched magnitude curve where it covers t, else |ω| of the motion
//   through the keys.
// "The motion through the keys" is the track without its fit, the paper's InitCurve: fitting again
// starts from the keys, not from the previous fit, so the same sketch always gives the same result.
//
// A stroke with times keeps them; one without is spread by arc length over the whole edit window.

#include "fit/angular_velocity_fit.h"
#include "fit/angular_velocity_target.h"
#include "model/commands/apply_fit_result_command.h"
#include "model/scene.h"

#include <QCoreApplication>

#include <optional>
#include <stdexcept>
#include <vector>

namespace gyre::model {

// A sketch that cannot be fitted. The message says what the artist should do, as it stands.
class SketchFitError : public std::invalid_argument {
    // The fit panel shows these messages: they are worded in the user's language.
    Q_DECLARE_TR_FUNCTIONS(gyre::SketchFitError)

public:
    using std::invalid_argument::invalid_argument;
};

struct SketchFitProblem {
    std::vector<fit::FitKey> keys;
    fit::AngularVelocityTarget target;
    fit::FitSettings settings;  // α, β, δ and the window from the sketch
};

// The span the fit edits, or nullopt when the track has fewer than two keys or nothing is sketched.
std::optional<fit::TimeWindow> editWindow(const MotionTrack& track);

// Each direction stroke as timed unit directions, in the sketch's order: its own times, or spread
// over the edit window; the sketch's pattern applied when it has one and a repeat count above zero.
// Empty when there is no edit window. A stroke the pattern cannot follow (no length) stays plain.
std::vector<std::vector<fit::TimedVector>> timedStrokes(const MotionTrack& track);

// Throws SketchFitError for fewer than two keys, an interpolation other than Hermite (the fit bends
// the Hermite spline through the keys, so another interpolation would jump at the window's ends),
// nothing sketched, or a window of no length.
SketchFitProblem sketchFitProblem(const MotionTrack& track);

// What ApplyFitResultCommand applies for `result`, a fit of sketchFitProblem(track): the fitted
// control points, and the track's keys with the freed ones turned to their fitted orientation.
// Variable frames stay control points of the curve; they do not become keyframes.
FitResult appliedFitResult(const MotionTrack& track, const fit::FitResult& result);

} // namespace gyre::model
