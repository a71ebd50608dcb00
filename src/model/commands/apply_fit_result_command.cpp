#include "model/commands/apply_fit_result_command.h"

#include "model/commands/command_checks.h"
#include "model/value_checks.h"

#include <algorithm>

namespace gyre::model {

namespace {

bool samePose(const Keyframe& a, const Keyframe& b)
{
    return a.pose.orientation.coeffs() == b.pose.orientation.coeffs() && a.pose.position == b.pose.position;
}

const Keyframe* keyAt(const std::vector<Keyframe>& keys, double time)
{
    const auto found = std::ranges::find(keys, time, &Keyframe::time);
    return found == keys.end() ? nullptr : &*found;
}

KeyframesAndSketchField::Value withFit(const Document& document, ObjectId object, FitResult result)
{
    MotionTrack track = withFitApplied(requireObject(document, object).track, std::move(result));
    return {std::move(track.keys), std::move(track.sketch)};
}

} // namespace

MotionTrack withFitApplied(MotionTrack track, FitResult result)
{
    checkFittedCurve(result.curve);
    checkKeyframes(result.keys);
    std::vector<Keyframe> before = std::move(track.sketch.keysBeforeFit);
    if (result.curve.empty())
        before.clear();
    for (const Keyframe& replaced : result.curve.empty() ? std::vector<Keyframe>{} : track.keys.vector()) {
        const Keyframe* fitted = keyAt(result.keys, replaced.time);
        if (fitted != nullptr && !samePose(*fitted, replaced) && keyAt(before, replaced.time) == nullptr)
            before.push_back(replaced);
    }
    std::ranges::sort(before, {}, &Keyframe::time);
    track.keys = std::move(result.keys);
    track.sketch.fittedCurve = std::move(result.curve);
    track.sketch.keysBeforeFit = std::move(before);
    return track;
}

ApplyFitResultCommand::ApplyFitResultCommand(Document& document, ObjectId object, FitResult result,
                                             QUndoCommand* parent)
    : ChangeValueCommand(document, {object, 0}, withFit(document, object, std::move(result)),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Apply angular velocity fit")), parent)
{
}

} // namespace gyre::model
