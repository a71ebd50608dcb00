#include "model/commands/erase_stroke_command.h"

#include "model/commands/command_checks.h"

namespace gyre::model {

EraseStrokeCommand::EraseStrokeCommand(Document& document, ObjectId object, std::size_t stroke, QUndoCommand* parent)
    : ListEntryCommand(document, object, stroke, requireStroke(document, object, stroke), Direction::Remove,
                       commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Erase Stroke")), parent)
{
}

} // namespace gyre::model
