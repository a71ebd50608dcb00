#pragma once
// Adds a keyframe to an object's track, in time order.

#include "model/commands/list_entry_command.h"
#include "model/commands/object_fields.h"

#include <cstddef>
#include <utility>

namespace gyre::model {

class AddKeyframeCommand final : public ListEntryCommand<KeyframeList> {
public:
    // Throws std::invalid_argument for an unknown object, a key value_checks.h refuses (a drifted
    // orientation is normalised), or a time at which the track has a key already.
    AddKeyframeCommand(Document& document, ObjectId object, Keyframe key, QUndoCommand* parent = nullptr);

private:
    AddKeyframeCommand(Document& document, ObjectId object, std::pair<std::size_t, Keyframe> placed,
                       QUndoCommand* parent);
};

} // namespace gyre::model
