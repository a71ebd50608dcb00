#pragma once
// Renames an object. Names need not be unique: they come from the nodes of imported files, which
// allow repeats.

#include "model/commands/object_fields.h"

namespace gyre::model {

class RenameObjectCommand final : public ChangeValueCommand<ObjectNameField> {
public:
    // Throws std::invalid_argument for an unknown object.
    RenameObjectCommand(Document& document, ObjectId object, const QString& name, QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
