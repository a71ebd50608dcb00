#include "core/fast_trig.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gyre::fast_trig_detail {

namespace {
// The tables' tails are differences of long doubles and doubles: they need its 64 significant bits.
static_assert(std::numeric_limits<long double>::digits >= 64);
constexpr long double kPiLong = std::numbers::pi_v<long double>;

// The lowest angle of bin b: asin(b/256) in the first half (half 0), π/2 − asin((b+1)/256) in the second.
long double lowestAngleOfBin(std::size_t b, std::size_t half)
{
    if (half == 0)
        return std::asin(static_cast<long double>(b) / kAngleBins);
    return kPiLong / 2 - std::asin(std::min(static_cast<long double>(b + 1) / kAngleBins, 1.0L));
}
} // namespace

// Filled from the long double functions, so that every entry is the double nearest the true value.
const std::array<TableSinCos, kStepsPerTurn> kSinCosTable = [] {
    std::array<TableSinCos, kStepsPerTurn> table{};
    for (std::size_t j = 0; j < kStepsPerTurn; ++j) {
        const long double angle = static_cast<long double>(j) * kPiLong / (kStepsPerTurn / 2);
        table[j] = {static_cast<double>(std::sin(angle)), static_cast<double>(std::cos(angle))};
    }
    return table;
}();

const std::array<TableAngle, 2 * kAngleBinsPerHalf> kAngleTable = [] {
    std::array<TableAngle, 2 * kAngleBinsPerHalf> table{};
    const auto entry = [](long double exact) {
        const double angle = static_cast<double>(exact);
        const long double rounded = angle; // sine and cosine of the double actually stored
        return TableAngle{.angle = angle,
                          .sin = static_cast<double>(std::sin(rounded)),
                          .cos = static_cast<double>(std::cos(rounded))};
    };
    for (std::size_t b = 0; b < kAngleBinsPerHalf; ++b)
        for (std::size_t half : {0, 1})
            table[half * kAngleBinsPerHalf + b] = entry(lowestAngleOfBin(b, half));
    return table;
}();

const std::array<ShortTableAngle, 2 * kAngleBinsPerHalf> kShortAngleTable = [] {
    std::array<ShortTableAngle, 2 * kAngleBinsPerHalf> table{};
    const auto entry = [](long double exact) {
        const long double sin = halves(static_cast<double>(std::sin(exact))).high;
        const long double cos = halves(static_cast<double>(std::cos(exact))).high;
        const long double angle = std::atan2(sin, cos);
        const auto head = static_cast<double>(angle);
        return ShortTableAngle{head, static_cast<double>(angle - head), static_cast<double>(sin), static_cast<double>(cos),
                               static_cast<double>(1.0L / std::sqrt(sin * sin + cos * cos))};
    };
    for (std::size_t b = 0; b < kAngleBinsPerHalf; ++b)
        for (std::size_t half : {0, 1})
            table[half * kAngleBinsPerHalf + b] = entry(lowestAngleOfBin(b, half));
    return table;
}();

} // namespace gyre::fast_trig_detail
