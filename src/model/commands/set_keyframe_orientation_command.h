#pragma once
// Sets the orientation of one keyframe. Consecutive edits of the same key merge, so dragging a
// rotation handle is one undo step.

#include "model/commands/object_fields.h"

namespace gyre::model {

class SetKeyframeOrientationCommand final : public ChangeValueCommand<KeyframeOrientationField> {
public:
    // The orientation alone: a key of an object in Euler mode then gets the angles of `orientation` nearest its
    // old ones (rotation_mode.h). Throws std::invalid_argument unless the object has a keyframe at index `key`
    // and `orientation` is a unit quaternion (a drifted one is normalised).
    SetKeyframeOrientationCommand(Document& document, ObjectId object, std::size_t key,
                                  const Eigen::Quaterniond& orientation, QUndoCommand* parent = nullptr);
    // The angles, radians in the track's convention, as typed (720° stays 720°), and the orientation they give.
    // Throws std::invalid_argument unless the object has a keyframe at index `key`, is in Euler rotation mode and
    // the angles are finite.
    SetKeyframeOrientationCommand(Document& document, ObjectId object, std::size_t key,
                                  const Eigen::Vector3d& eulerAngles, QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
