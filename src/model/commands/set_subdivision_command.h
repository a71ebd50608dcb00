#pragma once
// Sets the ScrewBender subdivision settings of an object's track: scheme, levels, cyclic or open.
// Consecutive changes to the same track merge, so sliding the level is one undo step.

#include "model/commands/object_fields.h"

namespace gyre::model {

class SetSubdivisionCommand final : public ChangeValueCommand<SubdivisionField> {
public:
    // Throws std::invalid_argument for an unknown object or levels outside 0 to kMaxSubdivisionLevels.
    SetSubdivisionCommand(Document& document, ObjectId object, const SubdivisionSettings& settings,
                          QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
