#include "core/key_time_map.h"

#include "core/position_curve.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gyre {

KeyTimeMap::KeyTimeMap(const std::vector<double>& keyTimes, bool cyclic)
    : knots_(keyTimes)
    , cyclic_(cyclic)
{
    if (knots_.empty())
        throw std::invalid_argument("a time map needs at least one key");
    for (std::size_t i = 0; i < knots_.size(); ++i)
        if (!std::isfinite(knots_[i]) || (i > 0 && !(knots_[i] > knots_[i - 1])))
            throw std::invalid_argument("key times must be finite and strictly increase");
    const std::size_t keys = knots_.size();
    if (keys == 1)
        return;
    if (cyclic_)
        knots_.push_back(knots_.back() + (knots_.back() - knots_.front()) / static_cast<double>(keys - 1));
    const std::size_t last = knots_.size() - 1;
    rates_.resize(knots_.size());
    for (std::size_t i = 1; i < last; ++i)
        rates_[i] = 2.0 / (knots_[i + 1] - knots_[i - 1]);
    if (cyclic_) {
        // The first key's neighbours are the last key, one closing span back, and the second key.
        rates_[0] = rates_[last] = 2.0 / (spanLength(last - 1) + spanLength(0));
    } else {
        rates_[0] = 1.0 / spanLength(0);
        rates_[last] = 1.0 / spanLength(last - 1);
    }
}

KeyTimeMap::SpanPoint KeyTimeMap::spanAt(double time) const
{
    const double first = knots_.front();
    if (cyclic_) {
        time = first + std::fmod(time - first, period());
        if (time < first)
            time += period();
    }
    const auto after = std::upper_bound(knots_.begin(), knots_.end(), time);
    const auto index = static_cast<std::size_t>(std::max<std::ptrdiff_t>(after - knots_.begin() - 1, 0));
    const std::size_t span = std::min(index, knots_.size() - 2);
    return {span, std::clamp((time - knots_[span]) / spanLength(span), 0.0, 1.0)};
}

double KeyTimeMap::spanValue(std::size_t span, double u) const
{
    // Start value 0, end value 1; slopes in u are the rates times the span's length.
    const HermiteBasis basis = hermiteBasis(u);
    const double length = spanLength(span);
    return basis.value[1] * length * rates_[span] + basis.value[2] + basis.value[3] * length * rates_[span + 1];
}

double KeyTimeMap::spanSlope(std::size_t span, double u) const
{
    const HermiteBasis basis = hermiteBasis(u);
    const double length = spanLength(span);
    return basis.first[1] * length * rates_[span] + basis.first[2] + basis.first[3] * length * rates_[span + 1];
}

double KeyTimeMap::parameterAt(double time) const
{
    if (knots_.size() == 1)
        return 0.0;
    const SpanPoint point = spanAt(time);
    return static_cast<double>(point.span) + spanValue(point.span, point.u);
}

double KeyTimeMap::rateAt(double time) const
{
    if (knots_.size() == 1 || (!cyclic_ && (time < knots_.front() || time > knots_.back())))
        return 0.0;
    const SpanPoint point = spanAt(time);
    return spanSlope(point.span, point.u) / spanLength(point.span);
}

double KeyTimeMap::timeAt(double parameter) const
{
    if (knots_.size() == 1)
        return knots_.front();
    const double spans = static_cast<double>(knots_.size() - 1);
    parameter = std::clamp(parameter, 0.0, spans);
    const auto span = static_cast<std::size_t>(std::min(std::floor(parameter), spans - 1.0));
    const double target = parameter - static_cast<double>(span);
    // The span's cubic increases from 0 to 1 on [0, 1]: Newton's steps, kept inside a bracket that
    // halves whenever a step would leave it.
    double low = 0.0;
    double high = 1.0;
    double u = target;
    for (int step = 0; step < 60; ++step) {
        const double error = spanValue(span, u) - target;
        if (std::abs(error) <= 1e-15)
            break;
        (error > 0.0 ? high : low) = u;
        const double slope = spanSlope(span, u);
        const double next = slope > 0.0 ? u - error / slope : low;
        u = next > low && next < high ? next : 0.5 * (low + high);
    }
    return knots_[span] + u * spanLength(span);
}

} // namespace gyre
