#pragma once
// Sets the scene's frame rate and time range. Consecutive changes merge, so dragging the end of the
// range is one undo step.

#include "model/commands/object_fields.h"

namespace gyre::model {

class SetTimeRangeCommand final : public ChangeValueCommand<TimeRangeField> {
public:
    // Throws std::invalid_argument for a frame rate outside (0, kMaxFps] or an end that does not come
    // after the start.
    SetTimeRangeCommand(Document& document, const TimeRange& range, QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
