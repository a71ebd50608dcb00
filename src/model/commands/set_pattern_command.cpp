#include "model/commands/set_pattern_command.h"

#include "model/commands/command_checks.h"
#include "model/value_checks.h"

namespace gyre::model {

namespace {

PatternField::Value checkedPattern(std::vector<Eigen::Vector2d> pattern, int repeat)
{
    checkPattern(pattern, repeat);
    return {std::move(pattern), repeat};
}

} // namespace

SetPatternCommand::SetPatternCommand(Document& document, ObjectId object, std::vector<Eigen::Vector2d> pattern,
                                     int repeat, QUndoCommand* parent)
    : ChangeValueCommand(document, objectTarget(document, object), checkedPattern(std::move(pattern), repeat),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Draw Pattern")), parent)
{
}

} // namespace gyre::model
