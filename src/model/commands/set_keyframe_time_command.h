#pragma once
// Sets the time of one keyframe. Consecutive moves of the same key merge, so a drag is one undo step.

#include "model/commands/object_fields.h"

namespace gyre::model {

class SetKeyframeTimeCommand final : public ChangeValueCommand<KeyframeTimeField> {
public:
    // Throws std::invalid_argument unless the object has a keyframe at index `key` and `time` lies
    // strictly between the times of its neighbours. Moving never reorders keys, so a key's index
    // stays its identity through a drag; the view stops a drag at the neighbours.
    SetKeyframeTimeCommand(Document& document, ObjectId object, std::size_t key, double time,
                           QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
