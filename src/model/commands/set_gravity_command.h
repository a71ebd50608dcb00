#pragma once
// Sets the scene's gravity: how fast and along which axis a ballistic track's centre of mass falls.
// Consecutive changes within a gesture merge.

#include "model/commands/object_fields.h"

namespace gyre::model {

class SetGravityCommand final : public ChangeValueCommand<GravityField> {
public:
    // Throws std::invalid_argument for an acceleration that is not finite and ≥ 0.
    SetGravityCommand(Document& document, const Gravity& gravity, QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
