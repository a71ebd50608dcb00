#include "model/commands/object_batch_command.h"

#include <utility>

namespace gyre::model {

ObjectBatchCommand::ObjectBatchCommand(Document& document, std::vector<PlacedObject> objects, Direction direction,
                                       const QString& text, QUndoCommand* parent)
    : QUndoCommand(text, parent)
    , document_(document)
    , objects_(std::move(objects))
    , direction_(direction)
{
}

void ObjectBatchCommand::redo() { direction_ == Direction::Insert ? insert() : remove(); }
void ObjectBatchCommand::undo() { direction_ == Direction::Insert ? remove() : insert(); }

void ObjectBatchCommand::insert() { DocumentEditor(document_).insertObjects(objects_); }

void ObjectBatchCommand::remove()
{
    std::vector<ObjectId> ids;
    for (const PlacedObject& placed : objects_)
        ids.push_back(placed.object.id);
    objects_ = DocumentEditor(document_).removeObjects(ids);
}

} // namespace gyre::model
