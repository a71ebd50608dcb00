#include "model/commands/rename_object_command.h"

#include "model/commands/command_checks.h"

namespace gyre::model {

RenameObjectCommand::RenameObjectCommand(Document& document, ObjectId object, const QString& name,
                                         QUndoCommand* parent)
    : ChangeValueCommand(document, objectTarget(document, object), name,
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Rename Object")), parent)
{
}

} // namespace gyre::model
