#include "model/commands/remove_fit_command.h"

#include "model/commands/command_checks.h"
#include "model/fit_input.h"

namespace gyre::model {

namespace {

KeyframesAndSketchField::Value keysAndSketchWithoutFit(const Document& document, ObjectId object)
{
    MotionTrack track = withoutFit(requireObject(document, object).track);
    return {std::move(track.keys), std::move(track.sketch)};
}

} // namespace

RemoveFitCommand::RemoveFitCommand(Document& document, ObjectId object, QUndoCommand* parent)
    : ChangeValueCommand(document, {object, 0}, keysAndSketchWithoutFit(document, object),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Remove angular velocity fit")), parent)
{
}

} // namespace gyre::model
