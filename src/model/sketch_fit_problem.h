#pragma once
// From a track's sketch to the angular-velocity fit and back (the sketch-editing paper's interface,
// docs/fit.md "In the app"), for the app's Fit and gyre-cli fit alike.
//
// The edit window is the sketch's own window if it has one, else the span the timed strokes and the
// magnitude curve cover, clipped to the keys' span. Over it the target is ωˢ(t) = m(t)·d(t):
// - d(t), the direction: where a timed stroke covers t, the stroke (the pattern applied along it);
//   where strokes overlap, the later stroke wins, as a redrawn part replaces what was drawn before.
//   Elsewhere the direction of the motion through the keys, so an undrawn part keeps its spin axis.
// - m(t), the magnitude: the sketched magnitude curve where it covers t, else |ω| of the motion
//   through the keys.
// "The motion through the keys" is the track without its fit (withoutFit, fit_input.h: no fitted
// curve, and the keys an earlier fit moved as they were before it), the paper's InitCurve, for any
// interpolation (a screw track's subdivided, retimed polyscrew too). The fit reads the keys of that
// track, not the track's own, so fitting again starts from the keys the artist set, not from the
// previous fit's curve or orientations, and the same sketch on the same keys gives the same result.
// The fit starts from that motion and keeps it outside the window.
//
// A stroke with times keeps them; one without is spread by arc length over the whole edit window.
//
// A screw track keeps its keys and its positions: the fit holds a constrained key's time at the
// orientation the polyscrew has there (the key's own for an interpolating scheme, not for the
// B-spline's), frees a free key's, and never moves a key, since moving a pose of the polyscrew would
// change its motion and its positions beyond the window. A keyed track of any other interpolation is
// fitted as a Hermite track is: constrained keys kept, free keys turned to their fitted orientation.

#include "fit/angular_velocity_fit.h"
#include "fit/angular_velocity_target.h"
#include "model/commands/apply_fit_result_command.h"
#include "model/scene.h"
#include "model/track_evaluation.h"

#include <QCoreApplication>

#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

namespace gyre::model {

// A sketch that cannot be fitted. The message says what the artist should do, as it stands.
class SketchFitError : public std::invalid_argument {
    // The fit panel shows these messages: they are worded in the user's language.
    Q_DECLARE_TR_FUNCTIONS(gyre::model::SketchFitError)

public:
    using std::invalid_argument::invalid_argument;
};

struct SketchFitProblem {
    std::vector<fit::FitKey> keys;
    fit::AngularVelocityTarget target;
    fit::FitSettings settings;  // α, β, δ and the window from the sketch
    // The motion through the keys, for every interpolation but Hermite, whose motion is the fit's own
    // default (the Hermite spline through the keys).
    fit::InitialMotion initialMotion;
    // The motion of the track without its fit, which the target and the initial motion read; for
    // drawnErrors. Null in a problem not made by sketchFitProblem.
    std::shared_ptr<const TrackMotion> motionWithoutFit;
};

// The fit of `problem`, run as the app and gyre-cli run it.
fit::FitResult fitSketch(const SketchFitProblem& problem, const fit::FitHooks& hooks = {});

// The span the fit edits, or nullopt when the track has fewer than two keys or nothing is sketched.
std::optional<fit::TimeWindow> editWindow(const MotionTrack& track);

// Each direction stroke as timed unit directions, in the sketch's order: its own times, or spread
// over the edit window; the sketch's pattern applied when it has one and a repeat count above zero.
// Empty when there is no edit window. A stroke the pattern cannot follow (no length) stays plain.
std::vector<std::vector<fit::TimedVector>> timedStrokes(const MotionTrack& track);

// Throws SketchFitError for fewer than two keys, nothing sketched, a window of no length or a
// sketch beyond its budgets: the checks that read no motion, quick enough for the UI thread at every
// edit (the fit panel's Fit button). sketchFitProblem makes them first.
void checkSketchFittable(const MotionTrack& track);

// The fit of the track's sketch, from withoutFit(track), `body` the one a ballistic track flies (flightBodyOf,
// track_evaluation.h). The fit reads orientations and angular velocities alone, which gravity does not touch (it
// moves the centre of mass), so the motions built here fall under the default gravity. Throws SketchFitError
// where checkSketchFittable does, and for a direction stroke the fit cannot follow.
SketchFitProblem sketchFitProblem(const MotionTrack& track, const MassProperties& body);

// What ApplyFitResultCommand applies for `result`, a fit of sketchFitProblem(track): the fitted
// control points, and the keys the fit read (withoutFit(track)'s), the freed ones turned to their
// fitted orientation unless the track is a screw track. Variable frames stay control points of the
// curve; they do not become keyframes.
FitResult appliedFitResult(const MotionTrack& track, const fit::FitResult& result);

// How far `motion` is from what the artist drew on `track`, rad²/s: ∫|ω − ω̂ˢ|² dt over the edit
// window, where ω̂ˢ is the sketch completed by the motion itself: the drawn speed along the drawn
// direction, the motion's own speed along a drawn direction where no speed is drawn, the drawn speed
// about the motion's own axis where no direction is, and ω itself where nothing is drawn. The fit's
// target takes the undrawn parts from the motion through the keys instead; this measure leaves them
// out, so that a fit that follows a drawn axis at a speed of its own counts as following the sketch.
// Where the motion stands still it has no axis to carry a drawn speed, which then counts in full.
// Integrated by the trapezoid rule over the target's sample times. Zero without an edit window.
double drawnError(const MotionTrack& track, const TrackMotion& motion);

// drawnError of `motionWithoutFit`, the motion through the keys (sketchFitProblem(track)'s, built
// once for the fit), and of the track with `applied`, appliedFitResult(track, ...), applied: the
// fit's report against what was drawn.
struct DrawnErrors {
    double before = 0.0;
    double after = 0.0;
};
DrawnErrors drawnErrors(const MotionTrack& track, const TrackMotion& motionWithoutFit, const FitResult& applied,
                        const MassProperties& body);

// The relative δ (fit::FitSettings::delta) that puts the fit's threshold for `track` where an
// absolute δ in rad²/s, as project files stored it before they stored a relative one, put it:
// δ_abs/S̄, with S̄ the mean squared speed of the track's target (fit::relativeFragmentError). A track
// that cannot be fitted keeps the number.
double relativeDelta(const MotionTrack& track, double absoluteDelta);

} // namespace gyre::model
