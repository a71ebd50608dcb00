#include "core/fast_trig.h"

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

const std::array<double, kAtanSteps + 1> kAtanTable = [] {
    std::array<double, kAtanSteps + 1> table{};
    for (std::size_t m = 0; m <= kAtanSteps; ++m)
        table[m] = static_cast<double>(std::atan(static_cast<long double>(m) / kAtanSteps));
    return table;
}();

} // namespace gyre::fast_trig_detail
