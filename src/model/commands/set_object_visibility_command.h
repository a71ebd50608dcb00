#pragma once
// Shows or hides an object in the viewport (SceneObject::visible).

#include "model/commands/object_fields.h"

namespace gyre::model {

class SetObjectVisibilityCommand final : public ChangeValueCommand<ObjectVisibilityField> {
public:
    // Throws std::invalid_argument for an unknown object.
    SetObjectVisibilityCommand(Document& document, ObjectId object, bool visible, QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
