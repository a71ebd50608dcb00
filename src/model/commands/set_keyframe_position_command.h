#pragma once
// Sets the position of one keyframe. Consecutive edits of the same key merge, so dragging a move
// handle is one undo step.

#include "model/commands/object_fields.h"

namespace gyre::model {

class SetKeyframePositionCommand final : public ChangeValueCommand<KeyframePositionField> {
public:
    // Throws std::invalid_argument unless the object has a keyframe at index `key` and `position` is
    // finite.
    SetKeyframePositionCommand(Document& document, ObjectId object, std::size_t key, const Eigen::Vector3d& position,
                               QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
