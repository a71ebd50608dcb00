#pragma once
// The shape of commands that add or remove whole objects: one direction inserts a batch of objects
// at the indices they are placed at, the other removes them again.

#include "model/document_editor.h"

#include <QUndoCommand>

#include <vector>

namespace gyre::model {

class ObjectBatchCommand : public QUndoCommand {
public:
    enum class Direction { Insert, Remove };

    void redo() override;
    void undo() override;

protected:
    // `objects` are the objects to insert, or those to remove, with the indices they have; indices
    // increase.
    ObjectBatchCommand(Document& document, std::vector<PlacedObject> objects, Direction direction,
                       const QString& text, QUndoCommand* parent);

private:
    void insert();
    void remove();

    Document& document_;
    std::vector<PlacedObject> objects_;
    Direction direction_;
};

} // namespace gyre::model
