#include "model/commands/apply_euler_filter_command.h"

#include "core/euler_filter.h"
#include "core/quaternion_math.h"
#include "model/commands/command_checks.h"

#include <utility>

namespace gyre::model {

ApplyEulerFilterCommand::ApplyEulerFilterCommand(Document& document, ObjectId object, QUndoCommand* parent)
    : ChangeValueCommand(document, objectTarget(document, object), filteredKeys(requireObject(document, object).track),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Apply Euler Filter")), parent)
{
}

std::vector<Keyframe> ApplyEulerFilterCommand::filteredKeys(const MotionTrack& track)
{
    std::vector<Keyframe> keys = track.keys;
    for (std::size_t i = 1; i < keys.size(); ++i)
        keys[i].pose.orientation = alignedWith(keys[i].pose.orientation, keys[i - 1].pose.orientation);
    if (!track.rotationMode.isEuler())
        return keys;
    std::vector<Eigen::Vector3d> angles;
    angles.reserve(keys.size());
    for (const Keyframe& key : keys)
        angles.push_back(key.eulerAngles.value_or(Eigen::Vector3d::Zero())); // present in Euler mode (rotation_mode.h)
    angles = continuousEulerAngles(std::move(angles), track.rotationMode.convention);
    for (std::size_t i = 0; i < keys.size(); ++i)
        keys[i].eulerAngles = angles[i];
    return keys;
}

bool ApplyEulerFilterCommand::changes(const MotionTrack& track)
{
    const std::vector<Keyframe> filtered = filteredKeys(track);
    for (std::size_t i = 0; i < filtered.size(); ++i)
        if (filtered[i].pose.orientation.coeffs() != track.keys[i].pose.orientation.coeffs() ||
            filtered[i].eulerAngles != track.keys[i].eulerAngles)
            return true;
    return false;
}

} // namespace gyre::model
