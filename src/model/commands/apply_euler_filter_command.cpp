#include "model/commands/apply_euler_filter_command.h"

#include "core/quaternion_math.h"
#include "model/commands/command_checks.h"

namespace gyre::model {

namespace {

SharedVector<Keyframe> filtered(const Document& document, ObjectId object)
{
    std::vector<Keyframe> keys = requireObject(document, object).track.keys;
    for (std::size_t i = 1; i < keys.size(); ++i)
        keys[i].pose.orientation = alignedWith(keys[i].pose.orientation, keys[i - 1].pose.orientation);
    return keys;
}

} // namespace

ApplyEulerFilterCommand::ApplyEulerFilterCommand(Document& document, ObjectId object, QUndoCommand* parent)
    : ChangeValueCommand(document, objectTarget(document, object), filtered(document, object),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Apply Euler Filter")), parent)
{
}

bool ApplyEulerFilterCommand::changes(const MotionTrack& track)
{
    const auto& keys = track.keys;
    for (std::size_t i = 1; i < keys.size(); ++i)
        if (keys[i].pose.orientation.coeffs().dot(keys[i - 1].pose.orientation.coeffs()) < 0.0)
            return true;
    return false;
}

} // namespace gyre::model
