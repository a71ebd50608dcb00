#include "model/commands/apply_euler_filter_command.h"

#include "core/euler_angles.h"
#include "core/quaternion_math.h"
#include "model/commands/command_checks.h"

#include <utility>

namespace gyre::model {

ApplyEulerFilterCommand::ApplyEulerFilterCommand(Document& document, ObjectId object, const KeySubset& keys,
                                                 QUndoCommand* parent)
    : ChangeValueCommand(document, objectTarget(document, object),
                         filteredKeys(requireObject(document, object).track, keys),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Apply Euler Filter")), parent)
{
}

std::vector<Keyframe> ApplyEulerFilterCommand::filteredKeys(const MotionTrack& track, const KeySubset& subset)
{
    std::vector<Keyframe> keys = track.keys;
    std::vector<std::size_t> filtered;
    if (subset) {
        filtered = *subset;
    } else {
        for (std::size_t i = 1; i < keys.size(); ++i)
            filtered.push_back(i);
    }
    const bool euler = track.rotationMode.isEuler();
    // Increasing, so that each key is compared with the one before as that one is once filtered. The first key
    // has none before it and stays.
    for (const std::size_t i : filtered) {
        if (i == 0 || i >= keys.size())
            continue;
        Keyframe& key = keys[i];
        const Keyframe& before = keys[i - 1];
        key.pose.orientation = alignedWith(key.pose.orientation, before.pose.orientation);
        // Angles are present in Euler mode (rotation_mode.h).
        if (euler)
            key.eulerAngles = nearestEquivalentAngles(key.eulerAngles.value_or(Eigen::Vector3d::Zero()),
                                                      before.eulerAngles.value_or(Eigen::Vector3d::Zero()),
                                                      track.rotationMode.convention);
    }
    return keys;
}

bool ApplyEulerFilterCommand::changes(const MotionTrack& track, const KeySubset& keys)
{
    const std::vector<Keyframe> filtered = filteredKeys(track, keys);
    for (std::size_t i = 0; i < filtered.size(); ++i)
        if (filtered[i].pose.orientation.coeffs() != track.keys[i].pose.orientation.coeffs() ||
            filtered[i].eulerAngles != track.keys[i].eulerAngles)
            return true;
    return false;
}

} // namespace gyre::model
