#include "model/commands/step_ballistic_solution_command.h"

#include "model/commands/command_checks.h"
#include "model/motion_cache.h"

#include <algorithm>

namespace gyre::model {

std::optional<SharedVector<Keyframe>> StepBallisticSolutionCommand::stepped(const Document& document, ObjectId object,
                                                                            double time, int direction)
{
    const MotionTrack& track = requireObject(document, object).track;
    if (track.interpolation != InterpolationMethod::Ballistic || track.keys.size() < 2)
        return std::nullopt;
    const std::vector<TrackMotion::FlightChoice>& choices = document.motion(object)->motion().flightChoices();
    const auto after = std::upper_bound(track.keys.begin() + 1, track.keys.end() - 1, time,
                                        [](double t, const Keyframe& key) { return t < key.time; });
    const auto span = static_cast<std::size_t>(after - track.keys.begin()) - 1;
    if (span >= choices.size() || choices[span].count < 2)
        return std::nullopt;
    SharedVector<Keyframe> keys = track.keys;
    const auto count = static_cast<int>(choices[span].count);
    keys.edit()[span].flightSolution = ((static_cast<int>(choices[span].chosen) + direction) % count + count) % count;
    return keys;
}

StepBallisticSolutionCommand::StepBallisticSolutionCommand(Document& document, ObjectId object,
                                                           SharedVector<Keyframe> keys, QUndoCommand* parent)
    : ChangeValueCommand(document, objectTarget(document, object), std::move(keys),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Step Flight Solution")), parent)
{
}

} // namespace gyre::model
