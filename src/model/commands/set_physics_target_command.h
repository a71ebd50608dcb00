#pragma once
// Replaces the sketch's target, its direction strokes and magnitude curve, by the free flight's ω
// (model/physics_target.h): one undo step.

#include "model/commands/object_fields.h"
#include "model/physics_target.h"

namespace gyre::model {

class SetPhysicsTargetCommand final : public ChangeValueCommand<SketchTargetField> {
public:
    // Throws std::invalid_argument for an unknown object or strokes and magnitudes value_checks.h refuses.
    SetPhysicsTargetCommand(Document& document, ObjectId object, PhysicsTarget target, QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
