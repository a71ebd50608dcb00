#pragma once
// Takes the applied angular-velocity fit away, as if it had not been applied: the fitted curve goes,
// and every key the fit moved gets back the pose it had before (sketch.keysBeforeFit), one undo step.

#include "model/commands/object_fields.h"

namespace gyre::model {

// The track without its fit: no fitted curve, and each key in sketch.keysBeforeFit restored onto the
// key still at its time (a key since removed or moved in time stays as it is).
MotionTrack withFitRemoved(MotionTrack track);

class RemoveFitCommand final : public ChangeValueCommand<KeyframesAndSketchField> {
public:
    // Throws std::invalid_argument for an unknown object.
    RemoveFitCommand(Document& document, ObjectId object, QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
