#include "model/commands/set_fit_parameter_command.h"

#include "model/commands/command_checks.h"
#include "model/value_checks.h"

namespace gyre::model {

namespace {

double checkedParameter(FitParameter parameter, double value)
{
    return parameter == FitParameter::Delta ? positiveNumber(value) : nonNegativeNumber(value);
}

FieldTarget parameterTarget(const Document& document, ObjectId object, FitParameter parameter)
{
    return {objectTarget(document, object).object, static_cast<std::size_t>(parameter)};
}

} // namespace

SetFitParameterCommand::SetFitParameterCommand(Document& document, ObjectId object, FitParameter parameter,
                                               double value, QUndoCommand* parent)
    : ChangeValueCommand(document, parameterTarget(document, object, parameter), checkedParameter(parameter, value),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Set Fit Parameter")), parent)
{
}

} // namespace gyre::model
