#include "model/commands/apply_fit_result_command.h"

#include "model/commands/command_checks.h"
#include "model/value_checks.h"

namespace gyre::model {

namespace {

KeyframesAndSketchField::Value withFit(const Document& document, ObjectId object, FitResult result)
{
    SketchState sketch = requireObject(document, object).track.sketch;
    checkFittedCurve(result.curve);
    checkKeyframes(result.keys);
    sketch.fittedCurve = std::move(result.curve);
    return {std::move(result.keys), std::move(sketch)};
}

} // namespace

ApplyFitResultCommand::ApplyFitResultCommand(Document& document, ObjectId object, FitResult result,
                                             QUndoCommand* parent)
    : ChangeValueCommand(document, {object, 0}, withFit(document, object, std::move(result)),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Apply angular velocity fit")), parent)
{
}

} // namespace gyre::model
