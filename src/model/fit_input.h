#pragma once
// Whether a fit of one track may still be applied to another: the track the fit read, and the track
// the document holds when its result arrives.

#include "model/scene.h"

namespace gyre::model {

// Whether a fit of `fitted` applies unchanged to `current`: the keys' times, positions and constraint
// flags, the constrained keys' orientations, the interpolation and the sketch are equal. Left out is
// what applying a fit changes itself, the sketch's fittedCurve and the free keys' orientations, so a
// track still counts as the fit's input after the fit is applied. Positions count although the fit
// does not read them: the applied keys carry the positions of `fitted`. Values are compared exactly.
bool sameFitInput(const MotionTrack& fitted, const MotionTrack& current);

} // namespace gyre::model
