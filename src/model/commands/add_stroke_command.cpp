#include "model/commands/add_stroke_command.h"

#include "model/commands/command_checks.h"
#include "model/value_checks.h"

namespace gyre::model {

AddStrokeCommand::AddStrokeCommand(Document& document, ObjectId object, DirectionStroke stroke, QUndoCommand* parent)
    : ListEntryCommand(document, object, requireObject(document, object).track.sketch.directionStrokes.size(),
                       checked(std::move(stroke), checkStroke), Direction::Insert,
                       commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Add Stroke")), parent)
{
}

} // namespace gyre::model
