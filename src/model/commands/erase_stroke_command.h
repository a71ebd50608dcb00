#pragma once
// Erases one direction stroke from an object's sketch.

#include "model/commands/list_entry_command.h"
#include "model/commands/object_fields.h"

namespace gyre::model {

class EraseStrokeCommand final : public ListEntryCommand<StrokeList> {
public:
    // Throws std::invalid_argument unless the object's sketch has a stroke at index `stroke`.
    EraseStrokeCommand(Document& document, ObjectId object, std::size_t stroke, QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
