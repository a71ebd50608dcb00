#pragma once
// Sine, cosine and the angle of a point on the unit circle, for the screw's hot path. glibc's
// versions are correctly rounded but cost about 30 ns (atan2) and 16 ns (sin and cos together) on the
// target machine, most of the 35 ns budget of one screw. These reduce the argument against a table of
// exactly rounded values (filled from the long double functions at start-up) and finish with a short
// Taylor series, with no division. Their absolute error is a few units of 2⁻⁵³, which is what a pose
// needs; unlike glibc's, sin does not keep its relative precision at its zeros far from 0. The
// precise angle, for the Euler decomposition's outer angles, is left unrounded, within 4e-18.
// Inline, so that the screw's code keeps its values in registers.

#include <algorithm>
#include <array>
#include <bit>
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
constexpr int kAngleBins = 256;    // bins of width 1/256 in sin a (a ≤ π/4) or in cos a (a > π/4)
constexpr int kAngleBinsPerHalf = kAngleBins * 3 / 4; // up to 0.75, past 1/√2 for a little drift

// sin and cos of one step side by side, aligned to their 16 bytes: the batch screw
// (screw_batch.cpp) reads an entry with one load, which never splits a cache line.
struct alignas(2 * sizeof(double)) TableSinCos {
    double sin;
    double cos;
};
extern const std::array<TableSinCos, kStepsPerTurn> kSinCosTable;

// An angle θ of the unit circle, a double, with the doubles nearest its sine and cosine; padded and
// aligned to 32 bytes, which the batch screw reads in one AVX load, or two SSE2 ones.
struct alignas(4 * sizeof(double)) TableAngle {
    double angle;
    double sin;
    double cos;
    double padding = 0.0;
};
// For bin b of the first half, θ = asin(b/256): the lowest angle whose sine falls in the bin. For bin
// b of the second half, θ = π/2 − asin((b+1)/256): the lowest angle whose cosine falls in bin b.
extern const std::array<TableAngle, 2 * kAngleBinsPerHalf> kAngleTable;

// For preciseAngleInFirstQuadrant, the same bins' angles moved to a point (cos, sin) whose two
// coordinates have 26 significant bits, so that their products with 26-bit halves of a double are
// exact. The point is off the unit circle by about 2⁻²⁷: its exact angle is angle + tail, and its
// length 1/inverseLength.
struct ShortTableAngle {
    double angle;
    double tail;
    double sin;
    double cos;
    double inverseLength;
};
extern const std::array<ShortTableAngle, 2 * kAngleBinsPerHalf> kShortAngleTable;

// v = high + low, each of at most 26 significant bits (Veltkamp's split).
struct Halves {
    double high;
    double low;
};

inline Halves halves(double v)
{
    constexpr double kSplitter = 134217729.0; // 2²⁷ + 1
    const double scaled = kSplitter * v;
    const double high = scaled - (scaled - v);
    return {high, v - high};
}

constexpr double kStepsPerRadian = 128.0 / std::numbers::pi;
constexpr double kLargestReduced = 1024.0; // beyond, k·(error of π) exceeds 1e-16
// π/128 in two parts (Cody and Waite): a head of 24 significant bits, so that k·head is exact for every
// k the reduction meets, and the tail, taken from the long double π.
constexpr long double kStepLong = std::numbers::pi_v<long double> / 128;
constexpr double kStepHead = static_cast<float>(kStepLong);
constexpr double kStepTail = static_cast<double>(kStepLong - static_cast<long double>(kStepHead));
// Adding and subtracting 1.5·2^52 rounds a double of magnitude below 2^51 to the nearest integer.
constexpr double kRoundingShift = 6755399441055744.0;

// The steps below take T a double or a register of doubles (the batch screw's lanes, screw_batch.cpp),
// so that both compute each value by the same operations.

// x = k·π/128 + remainder, |remainder| ≤ π/256 (Cody and Waite), for |x| ≤ 1024. k, rounded from
// x·128/π, is also in the low bits of `shifted`, that product plus 1.5·2⁵²: the sum is 1.5·2⁵² + k
// exactly, a double whose last place is 1, and 2⁵¹, the rest of its significand, is a multiple of 256,
// so the low 8 bits of its representation are k's table step, k mod 256.
template <class T>
struct StepReduction {
    T shifted;
    T remainder;
};

template <class T>
[[gnu::always_inline]] inline StepReduction<T> reducedByStep(T x)
{
    const T shifted = x * kStepsPerRadian + kRoundingShift;
    const T k = shifted - kRoundingShift;
    return {shifted, (x - k * kStepHead) - k * kStepTail};
}

// sin r and cos r for |r| ≤ π/256 by their Taylor series to r⁷ and r⁶; the first terms left out, r⁹/9!
// and r⁸/8!, are below 2e-20.
template <class T>
struct SinCosOf {
    T sin;
    T cos;
};

template <class T>
[[gnu::always_inline]] inline SinCosOf<T> sinCosSeries(T r)
{
    constexpr double s3 = -1.0 / 6, s5 = 1.0 / 120, s7 = -1.0 / 5040;
    constexpr double c2 = -1.0 / 2, c4 = 1.0 / 24, c6 = -1.0 / 720;
    const T r2 = r * r;
    const T r4 = r2 * r2;
    return {r + (r * r2) * ((s3 + r2 * s5) + r4 * s7), 1.0 + r2 * ((c2 + r2 * c4) + r4 * c6)};
}

// asin σ for |σ| < 0.006: σ + σ³/6 + 3σ⁵/40 + 5σ⁷/112; the first term left out, 35σ⁹/1152, is below
// 2e-22.
template <class T>
[[gnu::always_inline]] inline T arcsineSeries(T sigma)
{
    const T s2 = sigma * sigma;
    const T series = (1.0 / 6 + s2 * (3.0 / 40)) + (s2 * s2) * (5.0 / 112);
    return sigma + (sigma * s2) * series;
}

} // namespace fast_trig_detail

// fastSinCos for |x| ≤ 1024, with no branch.
inline SinCos fastSinCosReduced(double x)
{
    using namespace fast_trig_detail;
    const StepReduction<double> reduced = reducedByStep(x);
    const SinCosOf<double> ofRemainder = sinCosSeries(reduced.remainder);
    const auto j = static_cast<std::size_t>(std::bit_cast<std::uint64_t>(reduced.shifted) & (kStepsPerTurn - 1));
    const double sinK = kSinCosTable[j].sin;
    const double cosK = kSinCosTable[j].cos;
    return {sinK * ofRemainder.cos + cosK * ofRemainder.sin, cosK * ofRemainder.cos - sinK * ofRemainder.sin};
}

// sin x and cos x, with an absolute error of a few 1e-16 for |x| ≤ 1024; beyond, the standard library's.
inline SinCos fastSinCos(double x)
{
    if (!(std::abs(x) <= fast_trig_detail::kLargestReduced)) [[unlikely]]
        return {std::sin(x), std::cos(x)};
    return fastSinCosReduced(x);
}

// The angle a ∈ [0, π/2] of the point (cos a, sin a) of the unit circle, both coordinates
// non-negative: atan2(sine, cosine), to a few ulp. a = θ + asin(sin a·cos θ − cos a·sin θ), with θ
// the table angle just below a, found from whichever of sin a and cos a is the smaller: the series
// argument lies in [0, 0.0056), and the two terms, both positive, cannot cancel. GCC makes the choice
// of half a branch, which predicts well: between two random rotations a > π/4 four times in five,
// and subdivision's screws are short. An index taken from the sign bit of cos a − sin a instead, with
// no branch, made BM_Screw 2 ns slower, as the table load then waits for the comparison.
inline double fastAngleOnUnitCircle(double cosine, double sine)
{
    using namespace fast_trig_detail;
    const bool steep = sine > cosine; // a > π/4
    const auto bin = static_cast<std::size_t>(static_cast<std::int32_t>(std::min(sine, cosine) * kAngleBins));
    const TableAngle& below = kAngleTable[bin + (steep ? kAngleBinsPerHalf : 0)];
    return below.angle + arcsineSeries(sine * below.cos - cosine * below.sin);
}

// An angle as a table angle, a double, plus a correction below 0.006 in magnitude, not added: the
// exact sum is within 4e-18 of the angle.
struct TableAngleSum {
    double tableAngle;
    double correction;
};

// The angle a ∈ [0, π/2] of the point (x, y), x, y ≥ 0, of length √(x² + y²) > 0 (to a few ulp),
// within 4e-18 of atan2(y, x) before any rounding of the sum: a sum of two such angles, rounded once,
// is within about 1e-17 beyond half an ulp of the exact sum. The same steps as fastAngleOnUnitCircle,
// from a table point (c, s) of 26-bit coordinates at angle θ: y·c − x·s, whose near cancellation
// would cost up to 1e-16, is taken from exact products of halves, so that
// σ = (y·c − x·s)/(length·|(c, s)|) is only rounded relatively, and θ's tail is added. The Euler
// decomposition reads its outer angles with it (euler_angles.cpp).
inline TableAngleSum preciseAngleInFirstQuadrant(double x, double y, double length)
{
    using namespace fast_trig_detail;
    const double inverse = 1.0 / length;
    const bool steep = y > x;
    // A NaN (from a zero or NaN quaternion) reads bin 0 and gives NaN, not an index from an undefined
    // conversion.
    const double binPosition = std::min(x, y) * inverse * kAngleBins;
    const std::size_t bin = binPosition < kAngleBinsPerHalf ? static_cast<std::size_t>(static_cast<std::int32_t>(binPosition)) : 0;
    const ShortTableAngle& below = kShortAngleTable[bin + (steep ? kAngleBinsPerHalf : 0)];
    const Halves xParts = halves(x);
    const Halves yParts = halves(y);
    // Each product of a half and a table coordinate is exact. The high parts' products nearly cancel,
    // so their difference is rounded at most at σ's own scale; the low parts' terms are below 2⁻²⁶
    // of the length, and rounded far below σ's precision.
    const double crossed = (yParts.high * below.cos - xParts.high * below.sin) + (yParts.low * below.cos - xParts.low * below.sin);
    return {below.angle, below.tail + arcsineSeries(crossed * (inverse * below.inverseLength))};
}

} // namespace gyre
