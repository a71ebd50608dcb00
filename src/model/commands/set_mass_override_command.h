#pragma once
// Types an object's mass properties in place of its mesh's, or (none) goes back to the mesh's
// (SceneObject::massOverride).

#include "model/commands/object_fields.h"

namespace gyre::model {

class SetMassOverrideCommand final : public ChangeValueCommand<MassOverrideField> {
public:
    // Throws std::invalid_argument for an unknown object or properties no body has (checkMassProperties).
    SetMassOverrideCommand(Document& document, ObjectId object, const std::optional<MassProperties>& properties,
                           QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
