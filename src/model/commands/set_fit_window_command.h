#pragma once
// Sets the span of time the angular-velocity fit edits, or (nullopt) the whole track. Consecutive
// changes to the same sketch merge, so dragging the window's ends is one undo step.

#include "model/commands/object_fields.h"

namespace gyre::model {

class SetFitWindowCommand final : public ChangeValueCommand<FitWindowField> {
public:
    // Throws std::invalid_argument for an unknown object or a window whose end does not come after
    // its start.
    SetFitWindowCommand(Document& document, ObjectId object, std::optional<std::pair<double, double>> window,
                        QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
