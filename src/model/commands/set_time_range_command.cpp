#include "model/commands/set_time_range_command.h"

#include "model/commands/command_checks.h"
#include "model/value_checks.h"

namespace gyre::model {

namespace {

TimeRange checkedRange(const TimeRange& range)
{
    checkTimeRange(range.fps, range.startTime, range.endTime);
    return range;
}

} // namespace

SetTimeRangeCommand::SetTimeRangeCommand(Document& document, const TimeRange& range, QUndoCommand* parent)
    : ChangeValueCommand(document, {kNoObject, 0}, checkedRange(range),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Set Time Range")), parent)
{
}

} // namespace gyre::model
