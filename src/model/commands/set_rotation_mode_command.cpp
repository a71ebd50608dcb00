#include "model/commands/set_rotation_mode_command.h"

#include "model/commands/command_checks.h"
#include "model/rotation_mode.h"

namespace gyre::model {

namespace {

RotationModeField::Value inMode(const Document& document, ObjectId object, const RotationMode& mode)
{
    const MotionTrack& track = requireObject(document, object).track;
    return {mode, keysInRotationMode(track, mode),
            interpolationInRotationMode(track.interpolation, track.rotationMode, mode)};
}

} // namespace

SetRotationModeCommand::SetRotationModeCommand(Document& document, ObjectId object, const RotationMode& mode,
                                               QUndoCommand* parent)
    : ChangeValueCommand(document, objectTarget(document, object), inMode(document, object, mode),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Set Rotation Mode")), parent)
{
}

} // namespace gyre::model
