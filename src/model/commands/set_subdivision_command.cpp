#include "model/commands/set_subdivision_command.h"

#include "model/commands/command_checks.h"
#include "model/value_checks.h"

namespace gyre::model {

SetSubdivisionCommand::SetSubdivisionCommand(Document& document, ObjectId object, const SubdivisionSettings& settings,
                                             QUndoCommand* parent)
    : ChangeValueCommand(document, objectTarget(document, object), checked(settings, checkSubdivision),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Set Subdivision")), parent)
{
}

} // namespace gyre::model
