#include "model/commands/edit_stroke_command.h"

#include "model/commands/command_checks.h"
#include "model/value_checks.h"

namespace gyre::model {

EditStrokeCommand::EditStrokeCommand(Document& document, ObjectId object, std::size_t stroke, DirectionStroke edited,
                                     QUndoCommand* parent)
    : ChangeValueCommand(document, strokeTarget(document, object, stroke), checked(std::move(edited), checkStroke),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Edit Stroke")), parent)
{
}

} // namespace gyre::model
