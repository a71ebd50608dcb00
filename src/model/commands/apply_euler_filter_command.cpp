#include "model/commands/apply_euler_filter_command.h"

#include "core/euler_angles.h"
#include "core/euler_filter.h"
#include "core/quaternion_math.h"
#include "model/commands/command_checks.h"

#include <algorithm>
#include <utility>

namespace gyre::model {

namespace {

// The stored angles of a key of an Euler-mode track, present in that mode (rotation_mode.h).
Eigen::Vector3d anglesOf(const Keyframe& key)
{
    return key.eulerAngles.value_or(Eigen::Vector3d::Zero());
}

// Keys [first, end) made continuous, each with the one before it as filtered, the first with keys[first − 1]
// as it is; 1 ≤ first < end ≤ keys.size().
void filterRun(std::vector<Keyframe>& keys, std::size_t first, std::size_t end, const RotationMode& mode)
{
    for (std::size_t i = first; i < end; ++i)
        keys[i].pose.orientation = alignedWith(keys[i].pose.orientation, keys[i - 1].pose.orientation);
    if (!mode.isEuler())
        return;
    std::vector<Eigen::Vector3d> angles;
    angles.reserve(end - first);
    for (std::size_t i = first; i < end; ++i)
        angles.push_back(anglesOf(keys[i]));
    angles = continuousEulerAngles(std::move(angles), mode.convention, anglesOf(keys[first - 1]));
    for (std::size_t i = first; i < end; ++i)
        keys[i].eulerAngles = angles[i - first];
}

} // namespace

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
    if (!subset) {
        if (keys.size() > 1)
            filterRun(keys, 1, keys.size(), track.rotationMode);
        return keys;
    }
    // Runs of consecutive indices, in increasing order, so that each run follows the key before it as that one
    // is once filtered. The first key has none before it and stays.
    const std::vector<std::size_t>& indices = *subset;
    for (auto run = indices.begin(); run != indices.end();) {
        auto runEnd = std::next(run);
        while (runEnd != indices.end() && *runEnd == *std::prev(runEnd) + 1)
            ++runEnd;
        const std::size_t first = std::max<std::size_t>(*run, 1);
        const std::size_t end = std::min(*std::prev(runEnd) + 1, keys.size());
        if (first < end)
            filterRun(keys, first, end, track.rotationMode);
        run = runEnd;
    }
    return keys;
}

bool ApplyEulerFilterCommand::changes(const MotionTrack& track, const KeySubset& subset)
{
    // Up to the first key the filter changes, each filtered key is the key as it is; so the first change is at the
    // first key that differs from its filtering against the key before it as it is, found without filtering a copy
    // of the keys. Each key is filtered as filterRun does (continuousEulerAngles is nearestEquivalentAngles key
    // after key), so that the two agree to the bit.
    const std::vector<Keyframe>& keys = track.keys;
    const auto changesKey = [&](std::size_t i) {
        if (i == 0 || i >= keys.size())
            return false;
        const Keyframe& key = keys[i];
        const Keyframe& before = keys[i - 1];
        if (alignedWith(key.pose.orientation, before.pose.orientation).coeffs() != key.pose.orientation.coeffs())
            return true;
        if (!track.rotationMode.isEuler())
            return false;
        return key.eulerAngles != nearestEquivalentAngles(anglesOf(key), anglesOf(before), track.rotationMode.convention);
    };
    if (subset)
        return std::ranges::any_of(*subset, changesKey);
    for (std::size_t i = 1; i < keys.size(); ++i)
        if (changesKey(i))
            return true;
    return false;
}

} // namespace gyre::model
