#include "model/commands/remove_fit_command.h"

#include "model/commands/command_checks.h"

#include <algorithm>

namespace gyre::model {

namespace {

KeyframesAndSketchField::Value withoutFit(const Document& document, ObjectId object)
{
    MotionTrack track = withFitRemoved(requireObject(document, object).track);
    return {std::move(track.keys), std::move(track.sketch)};
}

} // namespace

MotionTrack withFitRemoved(MotionTrack track)
{
    for (const Keyframe& before : track.sketch.keysBeforeFit) {
        const auto key = std::ranges::find(track.keys, before.time, &Keyframe::time);
        if (key != track.keys.end())
            key->pose = before.pose;
    }
    track.sketch.keysBeforeFit.clear();
    track.sketch.fittedCurve.clear();
    return track;
}

RemoveFitCommand::RemoveFitCommand(Document& document, ObjectId object, QUndoCommand* parent)
    : ChangeValueCommand(document, {object, 0}, withoutFit(document, object),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Remove angular velocity fit")), parent)
{
}

} // namespace gyre::model
