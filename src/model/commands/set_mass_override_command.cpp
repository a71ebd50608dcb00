#include "model/commands/set_mass_override_command.h"

#include "model/commands/command_checks.h"
#include "model/object_mass.h"

namespace gyre::model {

SetMassOverrideCommand::SetMassOverrideCommand(Document& document, ObjectId object,
                                               const std::optional<MassProperties>& properties, QUndoCommand* parent)
    : ChangeValueCommand(document, objectTarget(document, object), checked(properties, [](const auto& typed) {
                             if (typed)
                                 checkMassProperties(*typed);
                         }),
                         properties ? commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Set Mass Properties"))
                                    : commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Mass From Mesh")),
                         parent)
{
}

} // namespace gyre::model
