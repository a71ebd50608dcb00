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

// segmentAt for times that mostly increase, as a quadrature walks a curve: the search starts at the
// segment found last and gallops forward (1, 2, 4, … segments), so it reads only the keys near the
// answer, O(log distance) instead of O(log keys) scattered over a curve of 150,000 samples. A time
// before the last answer falls back to segmentAt; the answer is always segmentAt's.
class SegmentCursor {
public:
    template <class Key>
    std::size_t at(const std::vector<Key>& keys, double time)
    {
        const std::size_t last = keys.size() - 2;
        if (segment_ > last || !(keys[segment_].time <= time)) {
            segment_ = segmentAt(keys, time);
            return segment_;
        }
        std::size_t low = segment_; // keys[low].time ≤ time
        std::size_t step = 1;
        while (low + step <= last && keys[low + step].time <= time) {
            low += step;
            step *= 2;
        }
        // Now keys[low].time ≤ time and time < keys[low + step].time unless past the last segment.
        const std::size_t high = std::min(low + step, last + 1);
        const auto after = std::upper_bound(keys.begin() + static_cast<std::ptrdiff_t>(low) + 1,
                                            keys.begin() + static_cast<std::ptrdiff_t>(high) + 1, time,
                                            [](double t, const Key& key) { return t < key.time; });
        segment_ = std::min(static_cast<std::size_t>(after - keys.begin()) - 1, last);
        return segment_;
    }

private:
    std::size_t segment_ = 0;
};

} // namespace gyre
