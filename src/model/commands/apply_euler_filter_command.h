#pragma once
// The Euler filter on an object's keys (Motion ▸ Euler Filter, and on import as an option): makes consecutive
// keys continuous, as Blender's. The keys' orientations do not change, only how they are stored:
//
// - In Euler rotation mode the keys store the angles as typed, and a typed 350° after 10°, or an angle that
//   came from a quaternion (an import, a rotate handle), jumps. Each key's angles after the first become their
//   equivalent nearest the key before's (core's continuousEulerAngles: each angle ± 2πk, or the convention's
//   twin solution), so the euler interpolations turn the short way and the curves are ramps, not saw-teeth.
// - In either mode the quaternion's sign can jump: q and −q are the same rotation, and an import or a typed
//   key may store either. Each key is flipped into the hemisphere of the one before (q_i·q_{i−1} ≥ 0), the
//   first as it is. Quaternion interpolation already joins keys along the short arc, so the motion stays;
//   the quaternion channels, the project file and quaternion columns written out change.
//
// On some keys only (the selected ones, as Blender's filter works on selected keyframes), each of them is made
// continuous with the key before it, filtered or not, in increasing order, so a run of selected keys follows
// the one before the run; the other keys stay as they are, bit for bit.

#include "model/commands/object_fields.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace gyre::model {

class ApplyEulerFilterCommand final : public ChangeValueCommand<KeyframesField> {
public:
    // The indices of the keys to filter, increasing (indices past the last key are left out); nullopt: every key.
    using KeySubset = std::optional<std::vector<std::size_t>>;

    // Throws std::invalid_argument for an unknown object.
    ApplyEulerFilterCommand(Document& document, ObjectId object, const KeySubset& keys = std::nullopt,
                            QUndoCommand* parent = nullptr);

    // The track's keys as the filter leaves them.
    static std::vector<Keyframe> filteredKeys(const MotionTrack& track, const KeySubset& keys = std::nullopt);

    // Whether the filter would change the keys: filteredKeys(track, keys) != track.keys, found without a copy of the
    // keys, up to the first key it changes (the menu asks on every key edit).
    static bool changes(const MotionTrack& track, const KeySubset& keys = std::nullopt);
};

} // namespace gyre::model
