#include "model/commands/set_keyframe_orientation_command.h"

#include "model/commands/command_checks.h"
#include "model/value_checks.h"

namespace gyre::model {

SetKeyframeOrientationCommand::SetKeyframeOrientationCommand(Document& document, ObjectId object, std::size_t key,
                                                             const Eigen::Quaterniond& orientation,
                                                             QUndoCommand* parent)
    : ChangeValueCommand(document, keyframeTarget(document, object, key),
                         unitQuaternion(orientation),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Rotate Keyframe")), parent)
{
}

} // namespace gyre::model
