#include "model/commands/toggle_keyframe_constraint_command.h"

#include "model/commands/command_checks.h"

namespace gyre::model {

ToggleKeyframeConstraintCommand::ToggleKeyframeConstraintCommand(Document& document, ObjectId object,
                                                                 std::size_t key, QUndoCommand* parent)
    : ChangeValueCommand(document, {object, key}, !requireKeyframe(document, object, key).constrained,
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Toggle Keyframe Constraint")), parent)
{
}

} // namespace gyre::model
