#include "model/commands/set_interpolation_command.h"

#include "model/commands/command_checks.h"

namespace gyre::model {

SetInterpolationCommand::SetInterpolationCommand(Document& document, ObjectId object, InterpolationMethod method,
                                                 QUndoCommand* parent)
    : ChangeValueCommand(document, objectTarget(document, object), method,
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Set Interpolation")), parent)
{
}

} // namespace gyre::model
