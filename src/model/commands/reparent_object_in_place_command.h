#pragma once
// Gives an object a new parent, or none, keeping it where it is in the world at each of its keys (as
// Blender's "keep transform"): a key's pose L at time t, relative to the old parent's world frame
// P(t), becomes L′ = P′(t)⁻¹·P(t)·L relative to the new parent's P′(t), so that P′(t)·L′ = P(t)·L.
// The object's descendants, relative to it, stay where they were too. Between keys the motion is
// interpolated in the new frame: where the two frames move differently, the path between keys can
// differ from the old one. An applied fit's curve is relative to the parent and is kept as it is.
// The order of objects changes as ReparentObjectCommand's does.

#include "model/commands/object_fields.h"

namespace gyre::model {

class ReparentObjectInPlaceCommand final : public ChangeValueCommand<ParentAndKeysField> {
public:
    // Throws std::invalid_argument for an unknown object or parent, or a parent that is the object
    // itself or one of its descendants.
    ReparentObjectInPlaceCommand(Document& document, ObjectId object, ObjectId newParent,
                                 QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
