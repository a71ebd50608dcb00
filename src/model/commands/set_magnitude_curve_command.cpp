#include "model/commands/set_magnitude_curve_command.h"

#include "model/commands/command_checks.h"
#include "model/value_checks.h"

namespace gyre::model {

SetMagnitudeCurveCommand::SetMagnitudeCurveCommand(Document& document, ObjectId object,
                                                   std::vector<MagnitudePoint> curve, QUndoCommand* parent)
    : ChangeValueCommand(document, objectTarget(document, object), checked(std::move(curve), checkMagnitudeCurve),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Draw Magnitude Curve")), parent)
{
}

} // namespace gyre::model
