#pragma once
// Replaces the magnitude curve of an object's sketch, |ω| over time. Consecutive changes to the same
// sketch merge, so drawing the curve is one undo step.

#include "model/commands/object_fields.h"

namespace gyre::model {

class SetMagnitudeCurveCommand final : public ChangeValueCommand<MagnitudeCurveField> {
public:
    // Throws std::invalid_argument for an unknown object, a magnitude that is negative or not finite,
    // or times that do not strictly increase.
    SetMagnitudeCurveCommand(Document& document, ObjectId object, std::vector<MagnitudePoint> curve,
                             QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
