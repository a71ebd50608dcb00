#pragma once
// Sets the pattern of an object's sketch and how often it repeats along the direction curve.
// Consecutive changes to the same sketch merge, so drawing the pattern is one undo step.

#include "model/commands/object_fields.h"

namespace gyre::model {

class SetPatternCommand final : public ChangeValueCommand<PatternField> {
public:
    // Throws std::invalid_argument for an unknown object, a point that is not finite or a negative
    // repeat count.
    SetPatternCommand(Document& document, ObjectId object, std::vector<Eigen::Vector2d> pattern, int repeat,
                      QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
