#pragma once
// The Euler filter on an object's keys (Motion ▸ Euler Filter): makes consecutive keys continuous.
//
// Gyre's keys store orientations as quaternions, not angles, so there are no stored angles to
// unwrap: the Euler angles the graph editor shows are already the unwrapped ones, chosen along the
// curve (motion_channels.h). What can jump from key to key is the quaternion's sign: q and −q are
// the same rotation, and an import or a typed key may store either. The filter flips each key into
// the hemisphere of the one before (q_i·q_{i−1} ≥ 0), the first key as it is. The motion does not
// change (every interpolation already joins keys along the short arc), but the stored components do,
// and with them the quaternion channels, the project file, and quaternion columns written out.

#include "model/commands/object_fields.h"

namespace gyre::model {

class ApplyEulerFilterCommand final : public ChangeValueCommand<KeyframesField> {
public:
    // Throws std::invalid_argument for an unknown object.
    ApplyEulerFilterCommand(Document& document, ObjectId object, QUndoCommand* parent = nullptr);

    // Whether the filter would change the keys: some key is stored in the hemisphere opposite the
    // key before it.
    static bool changes(const MotionTrack& track);
};

} // namespace gyre::model
