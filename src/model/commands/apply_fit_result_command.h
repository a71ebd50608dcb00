#pragma once
// Applies what the angular-velocity fit produced: the Hermite control points of the new orientation
// over the window, and the keyframes, whose free keys the fit may have moved. The keys it moves are
// kept in the sketch as they were before any fit moved them, for RemoveFitCommand to put back.

#include "model/commands/object_fields.h"

namespace gyre::model {

struct FitResult {
    std::vector<HermiteControlPoint> curve;  // empty: no fit applied, nothing to restore
    std::vector<Keyframe> keys;              // the track's keys with the fit's orientations
};

// The track with the fit applied: `result.keys` replace the keys, the curve becomes the fitted curve,
// and every key whose pose the fit changes joins sketch.keysBeforeFit unless a key at its time is there
// already (an earlier fit moved it first; what it was before that fit is what to restore).
// An empty curve leaves no fit applied and nothing to restore.
// Throws std::invalid_argument for a curve or keys value_checks.h refuses.
MotionTrack withFitApplied(MotionTrack track, FitResult result);

class ApplyFitResultCommand final : public ChangeValueCommand<KeyframesAndSketchField> {
public:
    // Throws std::invalid_argument for an unknown object or a result withFitApplied refuses.
    ApplyFitResultCommand(Document& document, ObjectId object, FitResult result, QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
