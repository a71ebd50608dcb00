#include "model/commands/set_keyframe_orientation_command.h"

#include "model/commands/command_checks.h"
#include "model/value_checks.h"

#include <stdexcept>

namespace gyre::model {

namespace {

KeyRotation orientationAlone(const Document& document, ObjectId object, std::size_t key,
                             const Eigen::Quaterniond& orientation)
{
    // The old angles stay until the document finds they no longer give the orientation.
    return {unitQuaternion(orientation), requireKeyframe(document, object, key).eulerAngles};
}

KeyRotation fromAngles(const Document& document, ObjectId object, std::size_t key, const Eigen::Vector3d& angles)
{
    requireKeyframe(document, object, key);
    const RotationMode& mode = requireObject(document, object).track.rotationMode;
    if (!mode.isEuler())
        throw std::invalid_argument("the object stores quaternions, not Euler angles");
    if (!angles.allFinite())
        throw std::invalid_argument("Euler angles must be finite");
    return {quaternionFromEulerAngles(angles, mode.convention), angles};
}

} // namespace

SetKeyframeOrientationCommand::SetKeyframeOrientationCommand(Document& document, ObjectId object, std::size_t key,
                                                             const Eigen::Quaterniond& orientation,
                                                             QUndoCommand* parent)
    : ChangeValueCommand(document, keyframeTarget(document, object, key),
                         orientationAlone(document, object, key, orientation),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Rotate Keyframe")), parent)
{
}

SetKeyframeOrientationCommand::SetKeyframeOrientationCommand(Document& document, ObjectId object, std::size_t key,
                                                             const Eigen::Vector3d& eulerAngles, QUndoCommand* parent)
    : ChangeValueCommand(document, keyframeTarget(document, object, key),
                         fromAngles(document, object, key, eulerAngles),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Rotate Keyframe")), parent)
{
}

} // namespace gyre::model
