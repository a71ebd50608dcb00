#pragma once
// Sets the orientation of one keyframe. Consecutive edits of the same key merge, so dragging a
// rotation handle is one undo step.

#include "model/commands/object_fields.h"

namespace gyre::model {

class SetKeyframeOrientationCommand final : public ChangeValueCommand<KeyframeOrientationField> {
public:
    // Throws std::invalid_argument unless the object has a keyframe at index `key` and `orientation`
    // is a unit quaternion (a drifted one is normalised).
    SetKeyframeOrientationCommand(Document& document, ObjectId object, std::size_t key,
                                  const Eigen::Quaterniond& orientation, QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
