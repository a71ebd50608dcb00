#pragma once
// The times a motion through keys is written out at: every frame at a rate, and every key exactly.

#include <cstddef>
#include <optional>
#include <vector>

namespace gyre {

// A frame that falls this close to a key is the key's sample: the key time is written, not a
// near-duplicate a rounding error away.
inline constexpr double kKeyMergeSeconds = 1e-9;

// t₀ + k/fps for k = 0, 1, … up to the last key, merged with the key times (strictly increasing,
// at least one); a frame within kKeyMergeSeconds of a key gives way to it. nullopt if that would be
// more than maxSamples times.
std::optional<std::vector<double>> frameTimes(const std::vector<double>& keyTimes, double fps, std::size_t maxSamples);

} // namespace gyre
