#pragma once
// Sine, cosine and the angle of a point on the unit circle, for the screw's hot path. glibc's
// versions are correctly rounded but cost about 30 ns (atan2) and 16 ns (sin and cos together) on the
// target machine, most of the 35 ns budget of one screw. These reduce the argument against a table of
// exactly rounded values (filled from the long double functions at start-up) and finish with a short
// Taylor series, with no division. Their absolute error is a few units of 2⁻⁵³, which is what a pose
// needs; unlike glibc's, sin does not keep its relative precision at its zeros far from 0.
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
constexpr int kAngleBins = 256;    // the angle table's bins in sin α, α ≤ π/4

struct SinCosTable {
    std::array<double, kStepsPerTurn> sin;
    std::array<double, kStepsPerTurn> cos;
};
extern const SinCosTable kSinCosTable;
// For sin α in [b/256, (b+1)/256), the largest j with j·π/128 ≤ α.
extern const std::array<std::uint8_t, kAngleBins * 3 / 4> kAngleIndex;

constexpr double kStepsPerRadian = 128.0 / std::numbers::pi;
constexpr double kLargestReduced = 1024.0; // beyond, k·(error of π) exceeds 1e-16
// π/128 in two parts (Cody and Waite): a head of 24 significant bits, so that k·head is exact for every
// k the reduction meets, and the tail, taken from the long double π.
constexpr long double kStepLong = std::numbers::pi_v<long double> / 128;
constexpr double kStepHead = static_cast<float>(kStepLong);
constexpr double kStepTail = static_cast<double>(kStepLong - static_cast<long double>(kStepHead));
// Adding and subtracting 1.5·2^52 rounds a double of magnitude below 2^51 to the nearest integer.
constexpr double kRoundingShift = 6755399441055744.0;

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

// The angle a ∈ [0, π/2] of the point (cos a, sin a) of the unit circle, both coordinates
// non-negative: atan2(sine, cosine), to a few ulp. Measured from the nearer axis, the angle α ≤ π/4
// is θⱼ + asin(sin α·cos θⱼ − cos α·sin θⱼ), with θⱼ = j·π/128 the table angle just below α: the
// series argument lies in [0, 0.028), and the two terms, both positive, cannot cancel.
inline double fastAngleOnUnitCircle(double cosine, double sine)
{
    using namespace fast_trig_detail;
    const bool steep = sine > cosine; // a > π/4: measure from the y axis
    const double u = steep ? cosine : sine;
    const double v = steep ? sine : cosine;
    const std::size_t j = kAngleIndex[static_cast<std::size_t>(u * kAngleBins)];
    const double sigma = u * kSinCosTable.cos[j] - v * kSinCosTable.sin[j];
    // asin σ = σ + σ³/6 + 3σ⁵/40 + 5σ⁷/112 + 35σ⁹/1152 + 63σ¹¹/2816; the first term left out,
    // 231σ¹³/13312, is below 1e-22.
    const double s2 = sigma * sigma;
    const double s4 = s2 * s2;
    const double series = (1.0 / 6 + s2 * (3.0 / 40)) + s4 * (5.0 / 112 + s2 * (35.0 / 1152)) + (s4 * s4) * (63.0 / 2816);
    const double asinSigma = sigma + (sigma * s2) * series;
    const double step = static_cast<double>(j);
    const double alpha = (step * kStepHead + asinSigma) + step * kStepTail;
    return steep ? 0.5 * std::numbers::pi - alpha : alpha;
}

} // namespace gyre
