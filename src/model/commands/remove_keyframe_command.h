#pragma once
// Removes one keyframe from an object's track.

#include "model/commands/list_entry_command.h"
#include "model/commands/object_fields.h"

namespace gyre::model {

class RemoveKeyframeCommand final : public ListEntryCommand<KeyframeList> {
public:
    // Throws std::invalid_argument unless the object has a keyframe at index `key`.
    RemoveKeyframeCommand(Document& document, ObjectId object, std::size_t key, QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
