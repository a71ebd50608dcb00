#pragma once
// Retimes an object's whole track by t′ = scale·t + offset: its keyframes and every time in its
// sketch (stroke times, magnitude curve, window, fitted curve), so the sketch stays over the motion it
// was drawn for. The fitted curve's derivatives scale by 1/scale, since dq/dt′ = (dq/dt)/scale.

#include "model/commands/object_fields.h"

namespace gyre::model {

class RetimeKeyframesCommand final : public ChangeValueCommand<KeyframesAndSketchField> {
public:
    // Throws std::invalid_argument for an unknown object, a scale that is not finite and positive
    // (a positive scale keeps the order of keys), an offset that is not finite, or times that would
    // not be finite.
    RetimeKeyframesCommand(Document& document, ObjectId object, double scale, double offset,
                           QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
