#pragma once
// Frees a constrained keyframe, or constrains a free one. The angular-velocity fit keeps constrained
// keys exactly and may move free ones.

#include "model/commands/object_fields.h"

namespace gyre::model {

class ToggleKeyframeConstraintCommand final : public ChangeValueCommand<KeyframeConstraintField> {
public:
    // Throws std::invalid_argument unless the object has a keyframe at index `key`.
    ToggleKeyframeConstraintCommand(Document& document, ObjectId object, std::size_t key,
                                    QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
