#pragma once
// What the angular-velocity fit reads of a track, and whether a fit of one track may still be applied
// to another: the track the fit read, and the track the document holds when its result arrives.

#include "model/commands/apply_fit_result_command.h"
#include "model/scene.h"

namespace gyre::model {

// The track as it was before its applied fit: no fitted curve, and each key in sketch.keysBeforeFit
// put back onto the key still at its time (a key since removed or moved in time stays as it is).
// The fit reads this, not the track (sketchFitProblem), so that fitting again starts from the keys
// the artist set rather than from the previous fit's orientations, and the same sketch gives the
// same result; RemoveFitCommand applies it.
MotionTrack withoutFit(MotionTrack track);

// Whether a fit of `fitted` reads the same as a fit of `current`: of withoutFit of each, the keys'
// times, orientations, positions and constraint flags, the interpolation (and a screw track's
// subdivision) and the sketch are equal. A fit's own result, its curve and the keys it moved, is
// thereby left out, so a track still counts as the fit's input after the fit is applied. Positions
// count although the fit does not read them: the applied keys carry them. Values are compared exactly.
bool sameFitInput(const MotionTrack& fitted, const MotionTrack& current);

// Whether `applied`, appliedFitResult of a fit of `fitted`, may be applied to `current`: the fit reads
// the same (sameFitInput), and the keys of `current` are those of `fitted` or those `applied` puts
// there, so that applying it overwrites no key edited since. The second half catches an edit that
// sameFitInput does not see: a key an earlier fit moved is read as it was before that fit.
bool fitResultApplies(const MotionTrack& fitted, const MotionTrack& current, const FitResult& applied);

} // namespace gyre::model
