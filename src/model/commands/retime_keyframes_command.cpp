#include "model/commands/retime_keyframes_command.h"

#include "model/commands/command_checks.h"
#include "model/value_checks.h"

namespace gyre::model {

namespace {

KeyframesAndSketchField::Value retimed(const Document& document, ObjectId object, double scale, double offset)
{
    positiveNumber(scale);
    finiteNumber(offset);
    const MotionTrack& track = requireObject(document, object).track;
    std::vector<Keyframe> keys = track.keys;
    SketchState sketch = track.sketch;
    const auto map = [scale, offset](double& time) { time = scale * time + offset; };
    for (Keyframe& key : keys)
        map(key.time);
    for (DirectionStroke& stroke : sketch.directionStrokes)
        for (double& time : stroke.times)
            map(time);
    for (MagnitudePoint& point : sketch.magnitude)
        map(point.time);
    if (sketch.window) {
        map(sketch.window->first);
        map(sketch.window->second);
    }
    for (HermiteControlPoint& point : sketch.fittedCurve) {
        map(point.time);
        point.derivative.coeffs() /= scale;
    }
    checkKeyframes(keys);
    checkSketch(sketch);
    return {std::move(keys), std::move(sketch)};
}

} // namespace

RetimeKeyframesCommand::RetimeKeyframesCommand(Document& document, ObjectId object, double scale, double offset,
                                               QUndoCommand* parent)
    : ChangeValueCommand(document, {object, 0}, retimed(document, object, scale, offset),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Retime Keyframes")), parent)
{
}

} // namespace gyre::model
