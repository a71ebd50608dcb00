#pragma once
// Takes the applied angular-velocity fit away, as if it had not been applied: the fitted curve goes,
// and every key the fit moved gets back the pose it had before (sketch.keysBeforeFit), one undo step:
// the track becomes model::withoutFit of itself (fit_input.h).

#include "model/commands/object_fields.h"

namespace gyre::model {

class RemoveFitCommand final : public ChangeValueCommand<KeyframesAndSketchField> {
public:
    // Throws std::invalid_argument for an unknown object.
    RemoveFitCommand(Document& document, ObjectId object, QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
