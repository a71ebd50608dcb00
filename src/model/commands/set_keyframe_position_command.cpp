#include "model/commands/set_keyframe_position_command.h"

#include "model/commands/command_checks.h"
#include "model/value_checks.h"

namespace gyre::model {

SetKeyframePositionCommand::SetKeyframePositionCommand(Document& document, ObjectId object, std::size_t key,
                                                       const Eigen::Vector3d& position, QUndoCommand* parent)
    : ChangeValueCommand(document, keyframeTarget(document, object, key), finiteVector(position),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Move Keyframe Position")), parent)
{
}

} // namespace gyre::model
