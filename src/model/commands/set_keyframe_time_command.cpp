#include "model/commands/set_keyframe_time_command.h"

#include "core/number_text.h"
#include "model/commands/command_checks.h"
#include "model/value_checks.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace gyre::model {

namespace {

double timeBetweenNeighbours(const Document& document, ObjectId object, std::size_t key, double time)
{
    requireKeyframe(document, object, key);
    const std::vector<Keyframe>& keys = document.object(object)->track.keys;
    const double earliest = key > 0 ? keys[key - 1].time : -std::numeric_limits<double>::infinity();
    const double latest = key + 1 < keys.size() ? keys[key + 1].time : std::numeric_limits<double>::infinity();
    if (!(timeValue(time) > earliest && time < latest))
        throw std::invalid_argument("keyframe " + std::to_string(key) + " of object " + std::to_string(object) +
                                    " moves only between its neighbours at " + formatNumber(earliest) + " and " +
                                    formatNumber(latest) + " s, not to " + formatNumber(time) + " s");
    return time;
}

} // namespace

SetKeyframeTimeCommand::SetKeyframeTimeCommand(Document& document, ObjectId object, std::size_t key, double time,
                                               QUndoCommand* parent)
    : ChangeValueCommand(document, {object, key}, timeBetweenNeighbours(document, object, key, time),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Move Keyframe")), parent)
{
}

} // namespace gyre::model
