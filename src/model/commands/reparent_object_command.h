#pragma once
// Gives an object a new parent, or none. The object keeps its track, which holds its transform
// relative to its parent, so it now moves with the new parent: keeping its motion in the world would
// mean baking the old parent's motion into it, which is the track evaluator's work, not an edit.
// When the new parent comes later in the scene, the object and its descendants move to just after
// it, so that parents still come before their children. ReparentObjectInPlaceCommand keeps the
// object where it is in the world instead.

#include "model/commands/object_fields.h"

namespace gyre::model {

// The new parent and the order of objects that puts the object's subtree just after it when the new
// parent comes later. Throws as ReparentObjectCommand's constructor does.
ParentField::Value reparented(const Document& document, ObjectId object, ObjectId newParent);

class ReparentObjectCommand final : public ChangeValueCommand<ParentField> {
public:
    // Throws std::invalid_argument for an unknown object or parent, or a parent that is the object
    // itself or one of its descendants.
    ReparentObjectCommand(Document& document, ObjectId object, ObjectId newParent, QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
