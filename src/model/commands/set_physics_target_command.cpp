#include "model/commands/set_physics_target_command.h"

#include "model/commands/command_checks.h"
#include "model/value_checks.h"

#include <utility>

namespace gyre::model {

namespace {

SketchTargetField::Value checkedTarget(PhysicsTarget target)
{
    for (DirectionStroke& stroke : target.directionStrokes)
        checkStroke(stroke);
    checkMagnitudeCurve(target.magnitude);
    return {std::move(target.directionStrokes), std::move(target.magnitude)};
}

} // namespace

SetPhysicsTargetCommand::SetPhysicsTargetCommand(Document& document, ObjectId object, PhysicsTarget target,
                                                 QUndoCommand* parent)
    : ChangeValueCommand(document, objectTarget(document, object), checkedTarget(std::move(target)),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Set Physics Target")), parent)
{
}

} // namespace gyre::model
