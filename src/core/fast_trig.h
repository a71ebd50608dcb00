#pragma once
// Sine, cosine and arctangent for the screw's hot path. glibc's versions are correctly rounded but
// cost about 30 ns (atan2) and 16 ns (sin and cos together) on the target machine, most of the 35 ns
// budget of one screw. These reduce the argument against a table of exactly rounded values (filled by
// the standard library at start-up) and finish with a short Taylor series. Their absolute error is a
// few units of 2⁻⁵³, which is what a pose needs; unlike glibc's they do not keep the relative
// precision of sin x at its zeros far from 0.
// Inline, so that the screw's code keeps its values in registers.

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace gyre {

struct SinCos {
    double sin;
    double cos;
};

namespace fast_trig_detail {

constexpr int kStepsPerTurn = 256; // sin and cos tabulated at k·π/128
constexpr int kAtanSteps = 64;     // atan tabulated at m/64, m = 0 … 64

struct SinCosTable {
    std::array<double, kStepsPerTurn> sin;
    std::array<double, kStepsPerTurn> cos;
};
extern const SinCosTable kSinCosTable;
extern const std::array<double, kAtanSteps + 1> kAtanTable;

constexpr double kStepsPerRadian = 128.0 / std::numbers::pi;
constexpr double kLargestReduced = 1024.0; // beyond, k·(error of π) exceeds 1e-16
// π/128 in two parts (Cody and Waite): a head of 24 significant bits, so that k·head is exact for every
// k the reduction meets, and the tail, taken from the long double π.
constexpr long double kStepLong = std::numbers::pi_v<long double> / 128;
constexpr double kStepHead = static_cast<float>(kStepLong);
constexpr double kStepTail = static_cast<double>(kStepLong - static_cast<long double>(kStepHead));
// Adding and subtracting 1.5·2^52 rounds a double of magnitude below 2^51 to the nearest integer.
constexpr double kRoundingShift = 6755399441055744.0;

// atan z for z ∈ [0, 1]: atan(m/64) + atan(r) with r = (z − m/64)/(1 + z·m/64), |r| ≤ 1/128.
inline double atanUnit(double z)
{
    const int m = static_cast<int>(z * kAtanSteps + 0.5);
    const double c = static_cast<double>(m) / kAtanSteps;
    const double r = (z - c) / (1.0 + z * c);
    // r − r³/3 + r⁵/5 − r⁷/7; the first term left out, r⁹/9, is below 2e-20. Grouped as Estrin's
    // scheme, so that the powers are formed side by side rather than in one long chain.
    constexpr double a3 = -1.0 / 3, a5 = 1.0 / 5, a7 = -1.0 / 7;
    const double r2 = r * r;
    const double r3 = r2 * r;
    return kAtanTable[static_cast<std::size_t>(m)] + (r + r3 * (a3 + r2 * a5) + (r3 * r2 * r2) * a7);
}

} // namespace fast_trig_detail

// sin x and cos x, with an absolute error of a few 1e-16 for |x| ≤ 1024; beyond, the standard library's.
inline SinCos fastSinCos(double x)
{
    using namespace fast_trig_detail;
    if (!(std::abs(x) <= kLargestReduced))
        return {std::sin(x), std::cos(x)};
    const double k = (x * kStepsPerRadian + kRoundingShift) - kRoundingShift;
    const double r = (x - k * kStepHead) - k * kStepTail; // |r| ≤ π/256
    // Taylor series to r⁷ and r⁶; the first terms left out, r⁹/9! and r⁸/8!, are below 2e-20.
    constexpr double s3 = -1.0 / 6, s5 = 1.0 / 120, s7 = -1.0 / 5040;
    constexpr double c2 = -1.0 / 2, c4 = 1.0 / 24, c6 = -1.0 / 720;
    const double r2 = r * r;
    const double r4 = r2 * r2;
    const double sinR = r + (r * r2) * ((s3 + r2 * s5) + r4 * s7);
    const double cosR = 1.0 + r2 * ((c2 + r2 * c4) + r4 * c6);
    const auto j = static_cast<std::size_t>(static_cast<std::int64_t>(k) & (kStepsPerTurn - 1));
    const double sinK = kSinCosTable.sin[j];
    const double cosK = kSinCosTable.cos[j];
    return {sinK * cosR + cosK * sinR, cosK * cosR - sinK * sinR};
}

// atan2(y, x) for y ≥ 0, x ≥ 0, not both zero: the angle in [0, π/2], to a few ulp.
inline double fastAtan2FirstQuadrant(double y, double x)
{
    using fast_trig_detail::atanUnit;
    return y <= x ? atanUnit(y / x) : 0.5 * std::numbers::pi - atanUnit(x / y);
}

} // namespace gyre
