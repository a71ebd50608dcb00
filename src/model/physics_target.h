#pragma once
// Physics as a sketch target (issue 24): the angular velocity a body would have if it flew free from where the
// current motion is at the start of the edit window. The torque-free motion (core/torque_free.h) of the object's
// body (objectMassProperties) starts from the motion's orientation and angular velocity at the window's start and
// flies over the window; its ω, sampled, becomes the sketch's target: its direction one timed direction stroke,
// its magnitude the magnitude curve. The fit then bends the motion toward the free flight while it keeps the
// constrained keys.

#include "core/mass_properties.h"
#include "model/scene.h"
#include "model/track_evaluation.h"

#include <optional>
#include <utility>
#include <vector>

namespace gyre::model {

struct PhysicsTarget {
    std::vector<DirectionStroke> directionStrokes;  // one, timed
    std::vector<MagnitudePoint> magnitude;
};

// The fewest and most intervals the window is sampled in; between, one per frame.
inline constexpr int kFewestPhysicsSamples = 16;
inline constexpr int kMostPhysicsSamples = 4096;

// The span the target covers: the track's edit window (editWindow, sketch_fit_problem.h), or without a sketch
// its keys' span; none for fewer than two keys.
std::optional<std::pair<double, double>> physicsTargetWindow(const MotionTrack& track);

// The target of a track that moves as `motion` (its orientation and the angular velocity in the parent's frame),
// for a body of `body`'s inertia, sampled at `fps` within the interval limits above. Throws SketchFitError (a
// translated std::invalid_argument) for fewer than two keys or a body at rest at the window's start (its ω has
// no direction).
PhysicsTarget physicsTarget(const MotionTrack& track, const TrackMotion& motion, const MassProperties& body,
                            double fps);

} // namespace gyre::model
