#pragma once
// Sets one parameter of the angular-velocity fit: α or β, the weights of its energy E = αW_T + βW_A,
// or δ, the error above which it inserts variable frames. Consecutive changes to the same parameter
// merge, so dragging a slider is one undo step.

#include "model/commands/object_fields.h"

namespace gyre::model {

class SetFitParameterCommand final : public ChangeValueCommand<FitParameterField> {
public:
    // Throws std::invalid_argument for an unknown object, a negative or non-finite α or β, or a δ
    // that is not finite and positive.
    SetFitParameterCommand(Document& document, ObjectId object, FitParameter parameter, double value,
                           QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
