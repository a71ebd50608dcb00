#pragma once
// Replaces one direction stroke of an object's sketch. Consecutive edits of the same stroke merge, so
// dragging its points is one undo step.

#include "model/commands/object_fields.h"

namespace gyre::model {

class EditStrokeCommand final : public ChangeValueCommand<StrokeField> {
public:
    // Throws std::invalid_argument unless the sketch has a stroke at index `stroke` and value_checks.h
    // accepts the new one (drifted directions are normalised).
    EditStrokeCommand(Document& document, ObjectId object, std::size_t stroke, DirectionStroke edited,
                      QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
