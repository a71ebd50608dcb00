#pragma once
// What every curve through timed keys needs: a check of its keys and the segment a time falls in.
// Key is any type with a `double time` member.

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace gyre {

// Throws std::invalid_argument unless there is at least one key and the times strictly increase.
template <class Key>
void requireIncreasingTimes(const std::vector<Key>& keys)
{
    if (keys.empty())
        throw std::invalid_argument("a curve needs at least one key");
    for (std::size_t i = 1; i < keys.size(); ++i)
        if (!(keys[i].time > keys[i - 1].time))
            throw std::invalid_argument("key times must strictly increase");
}

// The i with keys[i].time ≤ time < keys[i + 1].time, clamped to the first and last segment; at
// least two keys.
template <class Key>
std::size_t segmentAt(const std::vector<Key>& keys, double time)
{
    const auto after = std::upper_bound(keys.begin(), keys.end(), time,
                                        [](double t, const Key& key) { return t < key.time; });
    const auto index = static_cast<std::size_t>(std::max<std::ptrdiff_t>(after - keys.begin() - 1, 0));
    return std::min(index, keys.size() - 2);
}

} // namespace gyre
