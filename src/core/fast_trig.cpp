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

const std::array<TableAngle, 2 * kAngleBinsPerHalf> kAngleTable = [] {
    std::array<TableAngle, 2 * kAngleBinsPerHalf> table{};
    const auto entry = [](long double exact) {
        const double angle = static_cast<double>(exact);
        const long double rounded = angle; // sine and cosine of the double actually stored
        return TableAngle{angle, static_cast<double>(std::sin(rounded)), static_cast<double>(std::cos(rounded))};
    };
    for (std::size_t b = 0; b < kAngleBinsPerHalf; ++b) {
        const long double low = static_cast<long double>(b) / kAngleBins;
        const long double high = std::min(static_cast<long double>(b + 1) / kAngleBins, 1.0L);
        table[b] = entry(std::asin(low));
        table[kAngleBinsPerHalf + b] = entry(kPiLong / 2 - std::asin(high));
    }
    return table;
}();

} // namespace gyre::fast_trig_detail
