#include "model/commands/delete_object_command.h"

#include "model/commands/command_checks.h"
#include "model/scene_queries.h"

namespace gyre::model {

namespace {

std::vector<PlacedObject> placedSubtree(const Document& document, ObjectId object)
{
    requireObject(document, object);
    std::vector<PlacedObject> placed;
    for (ObjectId id : subtreeOf(document.scene(), object)) {
        const std::size_t index = *objectIndex(document.scene(), id);
        placed.push_back({index, document.scene().objects[index]});
    }
    return placed;
}

} // namespace

DeleteObjectCommand::DeleteObjectCommand(Document& document, ObjectId object, QUndoCommand* parent)
    : ObjectBatchCommand(document, placedSubtree(document, object), Direction::Remove,
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Delete Object")),
                         parent)
{
}

} // namespace gyre::model
