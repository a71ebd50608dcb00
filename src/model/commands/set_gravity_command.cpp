#include "model/commands/set_gravity_command.h"

#include "model/commands/command_checks.h"
#include "model/gravity.h"

namespace gyre::model {

SetGravityCommand::SetGravityCommand(Document& document, const Gravity& gravity, QUndoCommand* parent)
    : ChangeValueCommand(document, {kNoObject, 0}, checked(gravity, checkGravity),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Set Gravity")), parent)
{
}

} // namespace gyre::model
