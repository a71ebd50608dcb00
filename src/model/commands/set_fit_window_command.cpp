#include "model/commands/set_fit_window_command.h"

#include "model/commands/command_checks.h"
#include "model/value_checks.h"

namespace gyre::model {

SetFitWindowCommand::SetFitWindowCommand(Document& document, ObjectId object,
                                         std::optional<std::pair<double, double>> window, QUndoCommand* parent)
    : ChangeValueCommand(document, objectTarget(document, object), checked(window, checkWindow),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Set Fit Window")), parent)
{
}

} // namespace gyre::model
