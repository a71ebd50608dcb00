#pragma once
// Sets an object's rotation mode (scene.h's RotationMode), as Blender's: quaternion, or Euler in a convention.
// One undo step, "Set Rotation Mode". The keys are converted (keysInRotationMode, rotation_mode.h) and the
// interpolation follows the mode (euler-cubic entering Euler mode, hermite leaving it), so the motion is the
// same at the keys. A sketch fit stays as it is: it overrides the orientation in its window whatever the mode.

#include "model/commands/object_fields.h"

namespace gyre::model {

class SetRotationModeCommand final : public ChangeValueCommand<RotationModeField> {
public:
    // Throws std::invalid_argument for an unknown object.
    SetRotationModeCommand(Document& document, ObjectId object, const RotationMode& mode,
                           QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
