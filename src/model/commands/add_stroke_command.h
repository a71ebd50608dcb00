#pragma once
// Adds a direction stroke to an object's sketch, after the strokes it has.

#include "model/commands/list_entry_command.h"
#include "model/commands/object_fields.h"

namespace gyre::model {

class AddStrokeCommand final : public ListEntryCommand<StrokeList> {
public:
    // Throws std::invalid_argument for an unknown object or a stroke value_checks.h refuses (drifted
    // directions are normalised).
    AddStrokeCommand(Document& document, ObjectId object, DirectionStroke stroke, QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
