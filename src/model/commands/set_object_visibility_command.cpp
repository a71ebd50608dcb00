#include "model/commands/set_object_visibility_command.h"

#include "model/commands/command_checks.h"

namespace gyre::model {

SetObjectVisibilityCommand::SetObjectVisibilityCommand(Document& document, ObjectId object, bool visible,
                                                       QUndoCommand* parent)
    : ChangeValueCommand(document, objectTarget(document, object), visible,
                         visible ? commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Show Object"))
                                 : commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Hide Object")),
                         parent)
{
}

} // namespace gyre::model
