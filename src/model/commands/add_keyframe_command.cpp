#include "model/commands/add_keyframe_command.h"

#include "core/number_text.h"
#include "model/commands/command_checks.h"
#include "model/value_checks.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace gyre::model {

namespace {

// The checked key and the index that keeps the keys in time order.
std::pair<std::size_t, Keyframe> placeKey(const Document& document, ObjectId object, Keyframe key)
{
    checkKeyframe(key);
    const MotionTrack& track = requireObject(document, object).track;
    const std::vector<Keyframe>& keys = track.keys;
    checkPoseBudget(keys.size() + 1, track.interpolation, track.subdivision);
    const auto at = std::lower_bound(keys.begin(), keys.end(), key.time,
                                     [](const Keyframe& existing, double time) { return existing.time < time; });
    if (at != keys.end() && at->time == key.time)
        throw std::invalid_argument("object " + std::to_string(object) + " has a keyframe at " +
                                    formatNumber(key.time) + " s already");
    return {static_cast<std::size_t>(at - keys.begin()), key};
}

} // namespace

AddKeyframeCommand::AddKeyframeCommand(Document& document, ObjectId object, Keyframe key, QUndoCommand* parent)
    : AddKeyframeCommand(document, object, placeKey(document, object, key), parent)
{
}

AddKeyframeCommand::AddKeyframeCommand(Document& document, ObjectId object, std::pair<std::size_t, Keyframe> placed,
                                       QUndoCommand* parent)
    : ListEntryCommand(document, object, placed.first, placed.second, Direction::Insert,
                       commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Add Keyframe")),
                       parent)
{
}

} // namespace gyre::model
