#pragma once
// Deletes an object together with its descendants. Keeping the children would mean giving them the
// grandparent and baking the deleted object's motion into their tracks to keep their motion in the
// world; deleting the subtree is what the hierarchy says and is undone exactly.

#include "model/commands/object_batch_command.h"

namespace gyre::model {

class DeleteObjectCommand final : public ObjectBatchCommand {
public:
    // Throws std::invalid_argument for an unknown object.
    DeleteObjectCommand(Document& document, ObjectId object, QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
