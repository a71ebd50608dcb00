#include "model/commands/remove_keyframe_command.h"

#include "model/commands/command_checks.h"

namespace gyre::model {

RemoveKeyframeCommand::RemoveKeyframeCommand(Document& document, ObjectId object, std::size_t key,
                                             QUndoCommand* parent)
    : ListEntryCommand(document, object, key, requireKeyframe(document, object, key), Direction::Remove,
                       commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Remove Keyframe")), parent)
{
}

} // namespace gyre::model
