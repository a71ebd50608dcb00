#include "model/commands/set_subdivision_command.h"

#include "model/commands/command_checks.h"
#include "model/value_checks.h"

namespace gyre::model {

namespace {

// The settings, if the object's keys subdivided with them stay within the pose budget.
SubdivisionSettings checkedSettings(const Document& document, ObjectId object, const SubdivisionSettings& settings)
{
    checkSubdivision(settings);
    const MotionTrack& track = requireObject(document, object).track;
    checkPoseBudget(track.keys.size(), track.interpolation, settings);
    return settings;
}

} // namespace

SetSubdivisionCommand::SetSubdivisionCommand(Document& document, ObjectId object, const SubdivisionSettings& settings,
                                             QUndoCommand* parent)
    : ChangeValueCommand(document, objectTarget(document, object), checkedSettings(document, object, settings),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Set Subdivision")), parent)
{
}

} // namespace gyre::model
