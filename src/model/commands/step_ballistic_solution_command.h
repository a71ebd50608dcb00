#pragma once
// Steps the free flight of one span of a ballistic track (Motion ▸ Next Flight Solution, Previous Flight
// Solution): the span that contains `time` takes the next (or previous) of its solutions by kinetic energy,
// wrapping around; the other spans keep theirs. The choice is kept on the span's first key
// (Keyframe::flightSolution).

#include "model/commands/object_fields.h"

#include <optional>

namespace gyre::model {

class StepBallisticSolutionCommand final : public ChangeValueCommand<KeyframesField> {
public:
    // The keys after the step: the first key of span i (t_i ≤ time < t_i+1; the last span to its end key) with
    // its flight at (chosen + direction) modulo its count, the others as they were. None when the object's track
    // is not ballistic, has fewer than two keys, or its span offers a single flight. Builds the track's motion
    // (document.motion) if no view has yet. Throws std::invalid_argument for an unknown object, and where the
    // motion cannot be built.
    static std::optional<SharedVector<Keyframe>> stepped(const Document& document, ObjectId object, double time,
                                                         int direction);

    // `keys` as stepped() gives them.
    StepBallisticSolutionCommand(Document& document, ObjectId object, SharedVector<Keyframe> keys,
                                 QUndoCommand* parent = nullptr);
};

} // namespace gyre::model
