#include "model/commands/set_interpolation_command.h"

#include "model/commands/command_checks.h"
#include "model/value_checks.h"

#include <stdexcept>

namespace gyre::model {

namespace {

// The method, if the object's keys and subdivision with it stay within the pose budget.
InterpolationMethod checkedMethod(const Document& document, ObjectId object, InterpolationMethod method)
{
    const MotionTrack& track = requireObject(document, object).track;
    // The quaternion methods would lose the turns the angles hold.
    if (track.rotationMode.isEuler() && !interpolatesAngles(method))
        throw std::invalid_argument("an object in Euler rotation mode interpolates its angles: euler or euler-cubic");
    checkPoseBudget(track.keys.size(), method, track.subdivision);
    return method;
}

} // namespace

SetInterpolationCommand::SetInterpolationCommand(Document& document, ObjectId object, InterpolationMethod method,
                                                 QUndoCommand* parent)
    : ChangeValueCommand(document, objectTarget(document, object), checkedMethod(document, object, method),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Set Interpolation")), parent)
{
}

} // namespace gyre::model
