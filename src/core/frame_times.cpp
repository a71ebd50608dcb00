#include "core/frame_times.h"

#include <cmath>
#include <cstddef>

namespace gyre {

std::optional<std::vector<double>> frameTimes(const std::vector<double>& keyTimes, double fps, std::size_t maxSamples)
{
    const double first = keyTimes.front();
    const double last = keyTimes.back();
    // One frame more than the product promises, in case rounding put it just below a whole number;
    // frames past the last key are dropped below.
    const double frames = std::floor((last - first) * fps) + 2.0;
    if (!(frames + static_cast<double>(keyTimes.size()) <= static_cast<double>(maxSamples)))
        return std::nullopt;
    std::vector<double> times;
    std::size_t key = 0;
    for (std::size_t k = 0; k < static_cast<std::size_t>(frames); ++k) {
        const double time = first + static_cast<double>(k) / fps;
        while (key < keyTimes.size() && keyTimes[key] < time - kKeyMergeSeconds)
            times.push_back(keyTimes[key++]);
        const bool atKey = key < keyTimes.size() && std::abs(keyTimes[key] - time) <= kKeyMergeSeconds;
        if (!atKey && time <= last)
            times.push_back(time);
    }
    times.insert(times.end(), keyTimes.begin() + static_cast<std::ptrdiff_t>(key), keyTimes.end());
    return times;
}

} // namespace gyre
