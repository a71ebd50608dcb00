#pragma once
// New key lists for the edits of selected keys (ReplaceKeyframesCommand carries them to the
// document): without some keys, with keys put in, with some keys moved in time. Indices are into
// `keys`, increasing, and name existing keys.

#include "model/scene.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace gyre::model {

std::vector<Keyframe> withoutKeys(const std::vector<Keyframe>& keys, const std::vector<std::size_t>& removed);

// `keys` with `added` put in time order; an added key replaces a key at the same time.
std::vector<Keyframe> withKeys(const std::vector<Keyframe>& keys, const std::vector<Keyframe>& added);

// The shifts Δ, as [lower, upper], by which the keys at `moved` may all move together while staying
// at least `gap` seconds from every other key (so they never pass or land on one) and within
// [start, end]. Contains 0 when the keys are apart by `gap` already.
std::pair<double, double> shiftRange(const std::vector<Keyframe>& keys, const std::vector<std::size_t>& moved,
                                     double gap, double start, double end);

// `keys` with those at `moved` later by `shift` seconds, `shift` within shiftRange.
std::vector<Keyframe> shiftedKeys(const std::vector<Keyframe>& keys, const std::vector<std::size_t>& moved,
                                  double shift);

// `keys` with the time of each key at `moved` mapped by `retime`, or none if the times would then not
// increase by more than `gap` from key to key: a retiming may not cross or join keys.
std::optional<std::vector<Keyframe>> retimedKeys(const std::vector<Keyframe>& keys, const std::vector<std::size_t>& moved,
                                                 const std::function<double(double)>& retime, double gap);

} // namespace gyre::model
