#include "model/key_edits.h"

#include <algorithm>
#include <iterator>

namespace gyre::model {

std::vector<Keyframe> withoutKeys(const std::vector<Keyframe>& keys, const std::vector<std::size_t>& removed)
{
    std::vector<Keyframe> kept;
    kept.reserve(keys.size());
    auto next = removed.begin();
    for (std::size_t index = 0; index < keys.size(); ++index) {
        if (next != removed.end() && *next == index)
            ++next;
        else
            kept.push_back(keys[index]);
    }
    return kept;
}

std::vector<Keyframe> withKeys(const std::vector<Keyframe>& keys, const std::vector<Keyframe>& added)
{
    std::vector<Keyframe> merged;
    merged.reserve(keys.size() + added.size());
    const auto byTime = [](const Keyframe& a, const Keyframe& b) { return a.time < b.time; };
    // std::merge takes from the first range on ties; the added keys come first, so they win.
    std::merge(added.begin(), added.end(), keys.begin(), keys.end(), std::back_inserter(merged), byTime);
    merged.erase(std::unique(merged.begin(), merged.end(),
                             [](const Keyframe& a, const Keyframe& b) { return a.time == b.time; }),
                 merged.end());
    return merged;
}

std::pair<double, double> shiftRange(const std::vector<Keyframe>& keys, const std::vector<std::size_t>& moved,
                                     double gap, double start, double end)
{
    if (moved.empty())
        return {0.0, 0.0};
    double lower = start - keys[moved.front()].time;
    double upper = end - keys[moved.back()].time;
    // Each run of consecutive moved keys is held back by the unmoved keys on either side of it.
    for (std::size_t m = 0; m < moved.size(); ++m) {
        const std::size_t index = moved[m];
        const bool runStarts = m == 0 || moved[m - 1] + 1 != index;
        const bool runEnds = m + 1 == moved.size() || moved[m + 1] != index + 1;
        if (runStarts && index > 0)
            lower = std::max(lower, keys[index - 1].time + gap - keys[index].time);
        if (runEnds && index + 1 < keys.size())
            upper = std::min(upper, keys[index + 1].time - gap - keys[index].time);
    }
    return {lower, upper};
}

std::vector<Keyframe> shiftedKeys(const std::vector<Keyframe>& keys, const std::vector<std::size_t>& moved,
                                  double shift)
{
    std::vector<Keyframe> shifted = keys;
    for (std::size_t index : moved)
        shifted[index].time += shift;
    return shifted;
}

std::optional<std::vector<Keyframe>> retimedKeys(const std::vector<Keyframe>& keys, const std::vector<std::size_t>& moved,
                                                 const std::function<double(double)>& retime, double gap)
{
    std::vector<Keyframe> retimed = keys;
    for (std::size_t index : moved)
        retimed[index].time = retime(keys[index].time);
    for (std::size_t index = 1; index < retimed.size(); ++index)
        if (!(retimed[index].time - retimed[index - 1].time > gap))
            return std::nullopt;
    return retimed;
}

} // namespace gyre::model
