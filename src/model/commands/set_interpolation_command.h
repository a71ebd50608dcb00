#pragma once
// Chooses how an object's track interpolates between its keyframes.

#include "model/commands/object_fields.h"

namespace gyre::model {

class SetInterpolationCommand final : public ChangeValueCommand<InterpolationField> {
public:
    // Throws std::invalid_argument for an unknown object, or a method other than euler and euler-cubic for an
    // object in Euler rotation mode.
    SetInterpolationCommand(Document& document, ObjectId object, InterpolationMethod method,
                            QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
