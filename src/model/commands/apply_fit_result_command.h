#pragma once
// Applies what the angular-velocity fit produced: the Hermite control points of the new orientation
// over the window, and the keyframes, whose free keys the fit may have moved and to which it may have
// added variable frames. An empty curve takes the fit away again.

#include "model/commands/object_fields.h"

namespace gyre::model {

struct FitResult {
    std::vector<HermiteControlPoint> curve;
    std::vector<Keyframe> keys;
};

class ApplyFitResultCommand final : public ChangeValueCommand<KeyframesAndSketchField> {
public:
    // Throws std::invalid_argument for an unknown object or a curve or keys value_checks.h refuses.
    ApplyFitResultCommand(Document& document, ObjectId object, FitResult result, QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
