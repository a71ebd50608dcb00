#include "core/screw_batch.h"

#include "core/fast_trig.h"
#include "core/screw.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>

// The lanes are written with GCC's and Clang's vector extension: a register of `width` doubles takes
// +, −, ×, ÷, comparisons (64-bit masks of all ones or zeros) and selects (mask ? a : b), which compile
// to packed instructions, SSE2's at width 2 and AVX's at width 4 inside the AVX2 functions below. The
// file is built with -fno-math-errno and -fno-trapping-math (src/core/CMakeLists.txt), so that the
// square root of a register is one packed instruction. Every helper that takes or returns a register
// is forced inline, in a Debug build too: a register of four doubles passed to a function built
// without AVX would cross a calling convention that differs.
//
// What shapes the loops (perf, and llvm-mca's model of the development machine's AMD EPYC): the
// floating-point loads and stores, two a cycle together and one store, limit the screw as much as its
// multiplies do. So values cross from loop to loop through memory only where a long chain of latency
// has to be broken: the square root and the division, and each table read with the series after it.
// Each loop of a block is short and its registers independent, so that the processor overlaps them.
// The table rows are worked out in one loop and read in the next, their indices loaded from memory as
// integers: moving an index from a SIMD register to a general one costs more than storing it and
// loading it.

namespace gyre {

namespace {

using namespace fast_trig_detail;

// Screws a block. 8 and 32 were no faster.
constexpr std::size_t kLanes = 16;

// A register of `width` doubles, and of the 64-bit masks (all ones or zeros) its comparisons give.
template <int width>
struct Registers;
template <>
struct Registers<2> {
    using Doubles = double __attribute__((vector_size(16)));
    using Mask = std::int64_t __attribute__((vector_size(16)));
};
template <>
struct Registers<4> {
    using Doubles = double __attribute__((vector_size(32)));
    using Mask = std::int64_t __attribute__((vector_size(32)));
};
template <int width>
using Doubles = typename Registers<width>::Doubles;
template <int width>
using Mask = typename Registers<width>::Mask;

template <int width>
constexpr std::size_t kRegisters = kLanes / width;

template <int width>
using Lanes = std::array<Doubles<width>, kRegisters<width>>;

// One block's screws, Screw's members in lanes; quaternions as x, y, z, w like Eigen's coefficients.
template <int width>
struct Block {
    template <std::size_t count>
    using Components = std::array<Lanes<width>, count>;
    Components<4> fromOrientation;   // qa
    Components<3> fromPosition;      // pa
    Components<4> turnedOrientation; // (0, S)·qa
    Components<3> axis;              // S
    Components<3> sinSquaredTerm;    // V₁
    Components<3> sinCosTerm;        // V₂
    Lanes<width> sinHalfAngle;       // sin a, or 0 in a lane without rotation
    Lanes<width> cosHalfAngle;       // cos a, or 1 in a lane without rotation
    Lanes<width> cotangent;          // cot a
    Lanes<width> halfAngle;          // a, or NaN in a lane without rotation (see turnAt)
    Lanes<width> slide;              // d
    // Between the loops of buildBlock:
    Components<3> relativeVector;          // σ·(qb·conj(qa)).vec()
    Lanes<width> productW;                 // (qb·conj(qa)).w, whose sign is σ
    Lanes<width> normSquared;              // sin²a
    std::array<std::int64_t, kLanes> rows; // each lane's row of kAngleTable
};

template <int width>
[[gnu::always_inline]] inline Doubles<width> squareRoot(Doubles<width> value)
{
    Doubles<width> root;
    for (int i = 0; i < width; ++i)
        root[i] = std::sqrt(value[i]); // one packed square root: GCC joins the lanes
    return root;
}

// The sign bit of each lane.
template <int width>
[[gnu::always_inline]] inline Mask<width> signBits(Doubles<width> value)
{
    return reinterpret_cast<Mask<width>>(value) & std::numeric_limits<std::int64_t>::min();
}

// value·σ with σ = −1 in the lanes whose `side` has the sign bit and 1 in the others: exactly, as a
// flip of the sign bit.
template <int width>
[[gnu::always_inline]] inline Doubles<width> timesSide(Doubles<width> value, Mask<width> side)
{
    return reinterpret_cast<Doubles<width>>(reinterpret_cast<Mask<width>>(value) ^ side);
}

// Two registers of pairs, even = (e₀, e₁, e₂, e₃, …) and odd = (o₀, o₁, o₂, o₃, …), interleaved within
// each pair of lanes, as unpcklpd and unpckhpd do: first = (e₀, o₀, e₂, o₂, …), second = (e₁, o₁, e₃,
// o₃, …). __builtin_shufflevector, which GCC and Clang both have.
template <int width>
[[gnu::always_inline]] inline void interleave(Doubles<width> even, Doubles<width> odd, Doubles<width>& first,
                                              Doubles<width>& second)
{
    if constexpr (width == 2) {
        first = __builtin_shufflevector(even, odd, 0, 2);
        second = __builtin_shufflevector(even, odd, 1, 3);
    } else {
        first = __builtin_shufflevector(even, odd, 0, 4, 2, 6);
        second = __builtin_shufflevector(even, odd, 1, 5, 3, 7);
    }
}

// rows[i][0] and rows[i][1] of `width` rows as two registers of lanes: each row's pair loaded together
// (one load, where two single ones would each take a load port), then the lanes interleaved.
template <int width>
[[gnu::always_inline]] inline void loadPairs(const std::array<const double*, width>& rows, Doubles<width>& first,
                                             Doubles<width>& second)
{
    Doubles<width> even; // rows 0, 2, …, two doubles each
    Doubles<width> odd;  // rows 1, 3, …
    for (int i = 0; i < width / 2; ++i) {
        even[2 * i] = rows[2 * i][0];
        even[2 * i + 1] = rows[2 * i][1];
        odd[2 * i] = rows[2 * i + 1][0];
        odd[2 * i + 1] = rows[2 * i + 1][1];
    }
    interleave<width>(even, odd, first, second);
}

// The inverse of loadPairs: lanes first and second to rows[i][0] and rows[i][1].
template <int width>
[[gnu::always_inline]] inline void storePairs(Doubles<width> first, Doubles<width> second,
                                              const std::array<double*, width>& rows)
{
    Doubles<width> even; // rows 0, 2, …
    Doubles<width> odd;  // rows 1, 3, …
    interleave<width>(first, second, even, odd);
    for (int i = 0; i < width / 2; ++i) {
        rows[2 * i][0] = even[2 * i];
        rows[2 * i][1] = even[2 * i + 1];
        rows[2 * i + 1][0] = odd[2 * i];
        rows[2 * i + 1][1] = odd[2 * i + 1];
    }
}

// The orientations of `width` poses in lanes: x, y, z, w.
template <int width>
[[gnu::always_inline]] inline std::array<Doubles<width>, 4> loadOrientations(const Pose* poses)
{
    std::array<const double*, width> xy;
    std::array<const double*, width> zw;
    for (int i = 0; i < width; ++i) {
        xy[i] = poses[i].orientation.coeffs().data();
        zw[i] = xy[i] + 2;
    }
    std::array<Doubles<width>, 4> q;
    loadPairs<width>(xy, q[0], q[1]);
    loadPairs<width>(zw, q[2], q[3]);
    return q;
}

// The positions of `width` poses in lanes: z from the pairs (y, z).
template <int width>
[[gnu::always_inline]] inline std::array<Doubles<width>, 3> loadPositions(const Pose* poses)
{
    std::array<const double*, width> xy;
    std::array<const double*, width> yz;
    for (int i = 0; i < width; ++i) {
        xy[i] = poses[i].position.data();
        yz[i] = xy[i] + 1;
    }
    std::array<Doubles<width>, 3> p;
    Doubles<width> yAgain;
    loadPairs<width>(xy, p[0], p[1]);
    loadPairs<width>(yz, yAgain, p[2]);
    return p;
}

// out[i] = the pose of lane i, its seven coefficients as loadOrientations and loadPositions give them.
template <int width>
[[gnu::always_inline]] inline void storePoses(const std::array<Doubles<width>, 7>& c, Pose* out)
{
    std::array<double*, width> xy;
    std::array<double*, width> zw;
    std::array<double*, width> position;
    for (int i = 0; i < width; ++i) {
        xy[i] = out[i].orientation.coeffs().data();
        zw[i] = xy[i] + 2;
        position[i] = out[i].position.data();
    }
    storePairs<width>(c[0], c[1], xy);
    storePairs<width>(c[2], c[3], zw);
    storePairs<width>(c[4], c[5], position);
    for (int i = 0; i < width; ++i)
        position[i][2] = c[6][i];
}

// The product qb·conj(qa) of register v's pairs, in the order of Eigen's SSE2 product (Geometry_SIMD.h),
// whose result Screw uses: its vector turned to σ·vec, its w and the vector's squared norm, sin²a; and
// qa in lanes, for the poses.
template <int width>
[[gnu::always_inline]] inline void relativeRotation(const Pose* from, const Pose* to, Block<width>& block, std::size_t v)
{
    using D = Doubles<width>;
    const std::array<D, 4> qa = loadOrientations<width>(from + v * width);
    const std::array<D, 4> qb = loadOrientations<width>(to + v * width);
    const D ax = -qa[0], ay = -qa[1], az = -qa[2], aw = qa[3];
    const D bx = qb[0], by = qb[1], bz = qb[2], bw = qb[3];
    const D px = (bw * ax + by * az) - (bz * ay - bx * aw);
    const D py = (bw * ay + by * aw) + (bz * ax - bx * az);
    const D pz = (bw * az - by * ax) + (bz * aw + bx * ay);
    const D pw = (bw * aw - by * ay) - (bz * az + bx * ax);
    const Mask<width> side = signBits<width>(pw); // σ
    const D rx = timesSide<width>(px, side), ry = timesSide<width>(py, side), rz = timesSide<width>(pz, side);
    block.relativeVector[0][v] = rx;
    block.relativeVector[1][v] = ry;
    block.relativeVector[2][v] = rz;
    block.productW[v] = pw;
    block.normSquared[v] = (rx * rx + ry * ry) + rz * rz;
    for (std::size_t c = 0; c < 4; ++c)
        block.fromOrientation[c][v] = qa[c];
}

// Screw's members that follow from sin a: the square root and the division, then the axis, cot a and
// (0, S)·qa; with each lane's row of the angle table if `withAngle`. The lanes without rotation are
// left to the single screw, their sin a and cos a set to 0 and 1 so that every row stays in its table.
template <int width, bool withAngle>
[[gnu::always_inline]] inline void rotationTerms(const Pose* to, Block<width>& block, std::size_t v)
{
    using D = Doubles<width>;
    const D s = squareRoot<width>(block.normSquared[v]);
    const Mask<width> rotating = s > Screw::kNoRotation;
    const D inverseSin = 1.0 / s;
    const Mask<width> side = signBits<width>(block.productW[v]);
    const D rw = timesSide<width>(block.productW[v], side);
    for (std::size_t c = 0; c < 3; ++c)
        block.axis[c][v] = inverseSin * block.relativeVector[c][v];
    const D cotangent = rw * inverseSin;
    const D toWeight = timesSide<width>(inverseSin, side); // σ / sin a
    block.cotangent[v] = cotangent;
    const D sine = rotating ? s : D{};
    const D cosine = rotating ? rw : D{} + 1.0;
    block.sinHalfAngle[v] = sine;
    block.cosHalfAngle[v] = cosine;
    if constexpr (withAngle) {
        // fastAngleOnUnitCircle's row: the bin of the smaller coordinate, in the half of the larger.
        const D smaller = cosine < sine ? cosine : sine;
        const D binPosition = smaller * static_cast<double>(kAngleBins);
        const Mask<width> steep = sine > cosine;
        for (int i = 0; i < width; ++i)
            block.rows[v * width + i] = static_cast<std::int32_t>(binPosition[i]) + (steep[i] != 0 ? kAngleBinsPerHalf : 0);
    }
    const std::array<D, 4> qb = loadOrientations<width>(to + v * width);
    const D minusCotangent = -cotangent;
    for (std::size_t c = 0; c < 4; ++c)
        block.turnedOrientation[c][v] = toWeight * qb[c] + minusCotangent * block.fromOrientation[c][v];
}

// Screw's members that carry the positions: d, V₁ and V₂.
template <int width>
[[gnu::always_inline]] inline void translationTerms(const Pose* from, const Pose* to, Block<width>& block, std::size_t v)
{
    using D = Doubles<width>;
    const std::array<D, 3> pa = loadPositions<width>(from + v * width);
    const std::array<D, 3> pb = loadPositions<width>(to + v * width);
    const D cx = pb[0] - pa[0], cy = pb[1] - pa[1], cz = pb[2] - pa[2]; // Δ
    const D sx = block.axis[0][v], sy = block.axis[1][v], sz = block.axis[2][v];
    const D cotangent = block.cotangent[v];
    const D d = (sx * cx + sy * cy) + sz * cz;
    const D acrossX = cx - d * sx, acrossY = cy - d * sy, acrossZ = cz - d * sz; // Δ⊥
    const D turnedX = sy * cz - sz * cy, turnedY = sz * cx - sx * cz, turnedZ = sx * cy - sy * cx; // S×Δ
    block.sinSquaredTerm[0][v] = acrossX + cotangent * turnedX;
    block.sinSquaredTerm[1][v] = acrossY + cotangent * turnedY;
    block.sinSquaredTerm[2][v] = acrossZ + cotangent * turnedZ;
    block.sinCosTerm[0][v] = cotangent * acrossX - turnedX;
    block.sinCosTerm[1][v] = cotangent * acrossY - turnedY;
    block.sinCosTerm[2][v] = cotangent * acrossZ - turnedZ;
    block.slide[v] = d;
    for (std::size_t c = 0; c < 3; ++c)
        block.fromPosition[c][v] = pa[c];
}

// fastAngleOnUnitCircle of register v, from its rows; NaN in a lane without rotation.
template <int width>
[[gnu::always_inline]] inline void fastHalfAngle(Block<width>& block, std::size_t v)
{
    using D = Doubles<width>;
    const D cosine = block.cosHalfAngle[v], sine = block.sinHalfAngle[v];
    D belowAngle, belowSin, belowCos;
    for (int i = 0; i < width; ++i) {
        const TableAngle& below = kAngleTable[static_cast<std::size_t>(block.rows[v * width + i])];
        belowAngle[i] = below.angle;
        belowSin[i] = below.sin;
        belowCos[i] = below.cos;
    }
    const D angle = belowAngle + arcsineSeries(sine * belowCos - cosine * belowSin);
    block.halfAngle[v] = sine == 0.0 ? D{} + std::numeric_limits<double>::quiet_NaN() : angle;
}

// Screw(from[l], to[l]) for the kLanes pairs, with its angle only if `withAngle`.
template <int width, bool withAngle>
[[gnu::always_inline]] inline void buildBlock(const Pose* from, const Pose* to, Block<width>& block)
{
    for (std::size_t v = 0; v < kRegisters<width>; ++v)
        relativeRotation(from, to, block, v);
    for (std::size_t v = 0; v < kRegisters<width>; ++v)
        rotationTerms<width, withAngle>(to, block, v);
    for (std::size_t v = 0; v < kRegisters<width>; ++v)
        translationTerms(from, to, block, v);
    if constexpr (withAngle)
        for (std::size_t v = 0; v < kRegisters<width>; ++v)
            fastHalfAngle(block, v);
}

// sin(ta) and cos(ta) of each lane at one t, with sin²(ta) and sin(ta)·cos(ta).
template <int width>
struct Turn {
    Lanes<width> sin;
    Lanes<width> cos;
    Lanes<width> sinSquared;
    Lanes<width> sinCos;
    // Between the loops of turnAt: fastSinCosReduced's argument reduced, and its table steps.
    Lanes<width> remainder;
    std::array<std::int64_t, kLanes> steps;
};

// The turn of Screw::at(t): fastSinCosReduced(t·a), in two loops, the reduction and then the table and
// the series. A lane whose t·a is beyond the reduction's range, or NaN (a lane without rotation, a
// padding lane included), gets the turn of 0 here and the single screw after: true if there is one.
template <int width>
[[gnu::always_inline]] inline bool turnAt(const Block<width>& block, double t, Turn<width>& turn)
{
    using D = Doubles<width>;
    D singleScrew{};
    for (std::size_t v = 0; v < kRegisters<width>; ++v) {
        const D angle = t * block.halfAngle[v];
        const D magnitude = reinterpret_cast<D>(reinterpret_cast<Mask<width>>(angle) & std::numeric_limits<std::int64_t>::max());
        const Mask<width> reduced = magnitude <= kLargestReduced;
        const D x = reduced ? angle : D{};
        const StepReduction<D> reduction = reducedByStep(x);
        turn.remainder[v] = reduction.remainder;
        // The table step from the low bits of the shifted sum, as fastSinCosReduced takes it.
        const Mask<width> steps = reinterpret_cast<Mask<width>>(reduction.shifted) & (kStepsPerTurn - 1);
        std::memcpy(&turn.steps[v * width], &steps, sizeof steps); // one store, not one a lane
        singleScrew += reduced ? D{} : D{} + 1.0;
    }
    for (std::size_t v = 0; v < kRegisters<width>; ++v) {
        const SinCosOf<D> ofRemainder = sinCosSeries(turn.remainder[v]);
        D sinK, cosK;
        for (int i = 0; i < width; ++i) {
            const auto step = static_cast<std::size_t>(turn.steps[v * width + i]);
            sinK[i] = kSinCosTable.sin[step];
            cosK[i] = kSinCosTable.cos[step];
        }
        const D sinT = sinK * ofRemainder.cos + cosK * ofRemainder.sin;
        const D cosT = cosK * ofRemainder.cos - sinK * ofRemainder.sin;
        turn.sin[v] = sinT;
        turn.cos[v] = cosT;
        turn.sinSquared[v] = sinT * sinT;
        turn.sinCos[v] = sinT * cosT;
    }
    double count = 0.0;
    for (int i = 0; i < width; ++i)
        count += singleScrew[i];
    return count != 0.0;
}

// The turn of Screw::midpoint, by its half-angle formulas.
template <int width>
[[gnu::always_inline]] inline void turnAtMidpoint(const Block<width>& block, Turn<width>& turn)
{
    using D = Doubles<width>;
    for (std::size_t v = 0; v < kRegisters<width>; ++v) {
        const D sinA = block.sinHalfAngle[v];
        const D onePlusCos = 1.0 + block.cosHalfAngle[v];
        const D cosT = squareRoot<width>(0.5 * onePlusCos);
        turn.sin[v] = 0.5 * sinA / cosT;
        turn.cos[v] = cosT;
        turn.sinSquared[v] = 0.5 * sinA * sinA / onePlusCos;
        turn.sinCos[v] = 0.5 * sinA;
    }
}

// out[l] = Screw::pose of lane l at t with `turn`.
template <int width>
[[gnu::always_inline]] inline void posesOfBlock(const Block<width>& block, double t, const Turn<width>& turn, Pose* out)
{
    using D = Doubles<width>;
    for (std::size_t v = 0; v < kRegisters<width>; ++v) {
        std::array<D, 7> c;
        for (std::size_t k = 0; k < 4; ++k)
            c[k] = turn.cos[v] * block.fromOrientation[k][v] + turn.sin[v] * block.turnedOrientation[k][v];
        const D along = t * block.slide[v];
        for (std::size_t k = 0; k < 3; ++k)
            c[4 + k] = ((block.fromPosition[k][v] + along * block.axis[k][v]) + turn.sinSquared[v] * block.sinSquaredTerm[k][v])
                       + turn.sinCos[v] * block.sinCosTerm[k][v];
        storePoses<width>(c, out + v * width);
    }
}

template <int width>
[[gnu::always_inline]] inline double lane(const Lanes<width>& lanes, std::size_t l)
{
    return lanes[l / width][l % width];
}

// The pairs of the block that starts at pair `first`: the caller's own, or for a last, partial block
// copies padded with identities.
struct BlockPairs {
    const Pose* from;
    const Pose* to;
    std::size_t used; // lanes that hold a pair
};

struct PaddedPairs {
    std::array<Pose, kLanes> from;
    std::array<Pose, kLanes> to;
};

[[gnu::always_inline]] inline BlockPairs blockPairs(std::span<const Pose> from, std::span<const Pose> to,
                                                    std::size_t first, PaddedPairs& padded)
{
    const std::size_t used = std::min(kLanes, from.size() - first);
    if (used == kLanes)
        return {from.data() + first, to.data() + first, used};
    std::copy_n(from.begin() + static_cast<std::ptrdiff_t>(first), used, padded.from.begin());
    std::copy_n(to.begin() + static_cast<std::ptrdiff_t>(first), used, padded.to.begin());
    return {padded.from.data(), padded.to.data(), used};
}

// out[l] = Screw::pose of each lane that holds a pair: posesOfBlock straight into `target` for a full
// block, through `padded` for the last, partial one.
template <int width>
[[gnu::always_inline]] inline void storeBlock(const Block<width>& block, double t, const Turn<width>& turn,
                                              std::size_t used, Pose* target, std::array<Pose, kLanes>& padded)
{
    if (used == kLanes) {
        posesOfBlock(block, t, turn, target);
        return;
    }
    posesOfBlock(block, t, turn, padded.data());
    std::copy_n(padded.begin(), used, target);
}

// What a batch reuses from block to block.
template <int width>
struct Scratch {
    Block<width> block;
    Turn<width> turn;
    PaddedPairs pairs;
    std::array<Pose, kLanes> poses;
};

template <int width>
[[gnu::always_inline]] inline void screwsAtLanes(std::span<const Pose> from, std::span<const Pose> to,
                                                 std::span<const double> times, std::span<Pose> out)
{
    const std::size_t n = from.size();
    if (to.size() != n || out.size() != n * times.size())
        throw std::invalid_argument("screwsAt: spans of different lengths");
    Scratch<width> scratch;
    for (std::size_t first = 0; first < n; first += kLanes) {
        const BlockPairs pairs = blockPairs(from, to, first, scratch.pairs);
        buildBlock<width, true>(pairs.from, pairs.to, scratch.block);
        for (std::size_t k = 0; k < times.size(); ++k) {
            Pose* target = out.data() + k * n + first;
            const bool leftToSingleScrew = turnAt(scratch.block, times[k], scratch.turn);
            storeBlock(scratch.block, times[k], scratch.turn, pairs.used, target, scratch.poses);
            if (leftToSingleScrew) [[unlikely]]
                for (std::size_t l = 0; l < pairs.used; ++l)
                    if (!(std::abs(times[k] * lane<width>(scratch.block.halfAngle, l)) <= kLargestReduced))
                        target[l] = screwInterpolate(pairs.from[l], times[k], pairs.to[l]);
        }
    }
}

template <int width>
[[gnu::always_inline]] inline void screwMidpointsLanes(std::span<const Pose> from, std::span<const Pose> to,
                                                       std::span<Pose> out)
{
    if (to.size() != from.size() || out.size() != from.size())
        throw std::invalid_argument("screwMidpoints: spans of different lengths");
    Scratch<width> scratch;
    for (std::size_t first = 0; first < from.size(); first += kLanes) {
        const BlockPairs pairs = blockPairs(from, to, first, scratch.pairs);
        buildBlock<width, false>(pairs.from, pairs.to, scratch.block);
        turnAtMidpoint(scratch.block, scratch.turn);
        Pose* target = out.data() + first;
        storeBlock(scratch.block, 0.5, scratch.turn, pairs.used, target, scratch.poses);
        for (std::size_t l = 0; l < pairs.used; ++l)
            if (lane<width>(scratch.block.sinHalfAngle, l) == 0.0) [[unlikely]]
                target[l] = Screw::midpoint(pairs.from[l], pairs.to[l]);
    }
}

// The same lanes for AVX2, four doubles a register, without FMA: fused products would round
// differently from the single screw.
[[gnu::target("avx2")]] void screwsAtAvx2(std::span<const Pose> from, std::span<const Pose> to,
                                          std::span<const double> times, std::span<Pose> out)
{
    screwsAtLanes<4>(from, to, times, out);
}

[[gnu::target("avx2")]] void screwMidpointsAvx2(std::span<const Pose> from, std::span<const Pose> to,
                                                std::span<Pose> out)
{
    screwMidpointsLanes<4>(from, to, out);
}

bool hasAvx2()
{
    static const bool has = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") != 0;
    }();
    return has;
}

} // namespace

namespace screw_batch_detail {

void screwsAtPortable(std::span<const Pose> from, std::span<const Pose> to, std::span<const double> times,
                      std::span<Pose> out)
{
    screwsAtLanes<2>(from, to, times, out);
}

void screwMidpointsPortable(std::span<const Pose> from, std::span<const Pose> to, std::span<Pose> out)
{
    screwMidpointsLanes<2>(from, to, out);
}

} // namespace screw_batch_detail

void screwsAt(std::span<const Pose> from, std::span<const Pose> to, std::span<const double> times,
              std::span<Pose> out)
{
    if (hasAvx2())
        screwsAtAvx2(from, to, times, out);
    else
        screw_batch_detail::screwsAtPortable(from, to, times, out);
}

void screwMidpoints(std::span<const Pose> from, std::span<const Pose> to, std::span<Pose> out)
{
    if (hasAvx2())
        screwMidpointsAvx2(from, to, out);
    else
        screw_batch_detail::screwMidpointsPortable(from, to, out);
}

} // namespace gyre
