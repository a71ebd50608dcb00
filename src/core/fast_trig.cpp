#include "core/fast_trig.h"

#include <algorithm>
#include <cmath>

namespace gyre::fast_trig_detail {

namespace {
constexpr long double kPiLong = std::numbers::pi_v<long double>;
} // namespace

// Filled from the long double functions, so that every entry is the double nearest the true value.
const SinCosTable kSinCosTable = [] {
    SinCosTable table{};
    for (std::size_t j = 0; j < kStepsPerTurn; ++j) {
        const long double angle = static_cast<long double>(j) * kPiLong / (kStepsPerTurn / 2);
        table.sin[j] = static_cast<double>(std::sin(angle));
        table.cos[j] = static_cast<double>(std::cos(angle));
    }
    return table;
}();

const std::array<std::uint8_t, kAngleBins * 3 / 4> kAngleIndex = [] {
    std::array<std::uint8_t, kAngleBins * 3 / 4> table{};
    for (std::size_t b = 0; b < table.size(); ++b) {
        const long double lowest = std::min(static_cast<long double>(b) / kAngleBins, 1.0L);
        table[b] = static_cast<std::uint8_t>(std::floor(std::asin(lowest) / kStepLong));
    }
    return table;
}();

} // namespace gyre::fast_trig_detail
