#pragma once
// Adds a batch of objects, such as the nodes of an imported scene, in one undo step, after the
// objects the scene has.
//
// The batch's ids are its own: each object needs an id other than kNoObject that is unique within the
// batch, and its parent is kNoObject or an object that comes earlier in the batch. The command gives
// every object a fresh scene id and rewrites the parents to match; ids() tells which.

#include "model/commands/object_batch_command.h"

#include <vector>

namespace gyre::model {

class ImportObjectsCommand final : public ObjectBatchCommand {
public:
    // Throws std::invalid_argument for a batch that breaks the rules above or holds a track that
    // value_checks.h refuses (drifted orientations are normalised).
    ImportObjectsCommand(Document& document, std::vector<SceneObject> objects, QUndoCommand* parent = nullptr);

    // The scene ids of the objects, in the batch's order.
    const std::vector<ObjectId>& ids() const { return ids_; }

private:
    ImportObjectsCommand(Document& document, std::vector<PlacedObject> placed, QUndoCommand* parent);

    std::vector<ObjectId> ids_;
};

} // namespace gyre::model
