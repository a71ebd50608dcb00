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
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>

// The lanes are written with GCC's and Clang's vector extension: a register of `width` doubles takes
// +, −, ×, ÷, comparisons (64-bit masks of all ones or zeros) and selects (mask ? a : b), which compile
// to packed instructions, SSE2's at width 2, AVX's at width 4 inside runAvx2 below, and AVX-512's at
// width 8 inside runAvx512. The file is built with -fno-math-errno and -fno-trapping-math
// (src/core/CMakeLists.txt), so that the square root of a register is one packed instruction. Every
// helper that takes or returns a register is forced inline, in a Debug build too: a register of four or
// eight doubles passed to a function built without AVX would cross a calling convention that differs.
//
// What shapes the loops (perf, llvm-mca, and throwaway loops timed on the development machine's AMD
// EPYC): it stores one register a cycle, and its loads, stores and shuffles limit the screw as much as
// its multiplies do. So values cross from loop to loop through memory only where a long chain of
// latency has to be broken: the square root and the division, and each table read with the series
// after it. Each loop of a block is short and its registers independent, so that the processor
// overlaps them, and the loop with the square root and the division also loads the positions, work
// that waits on neither. A pose's quaternion and position, and a table entry, are each loaded and
// stored whole, in one instruction with AVX2 or AVX-512 and one for every two doubles with SSE2, and
// transposed in registers: stored a coefficient at a time, as GCC had done, they took a store for
// each. The table rows are worked out in one loop and read in the next, their indices loaded from
// memory as integers: moving an index from a SIMD register to a general one costs more than storing it
// and loading it. (AVX-512's gathers would read the rows from the register, but took 14 cycles each.)

namespace gyre {

namespace {

using namespace fast_trig_detail;

// A register of `width` doubles, of the 64-bit masks (all ones or zeros) its comparisons give, and
// `width` 32-bit integers, a conversion's result.
template <int width>
struct Registers;
template <>
struct Registers<2> {
    using Doubles = double __attribute__((vector_size(16)));
    using Mask = std::int64_t __attribute__((vector_size(16)));
    using Int32s = std::int32_t __attribute__((vector_size(8)));
};
template <>
struct Registers<4> {
    using Doubles = double __attribute__((vector_size(32)));
    using Mask = std::int64_t __attribute__((vector_size(32)));
    using Int32s = std::int32_t __attribute__((vector_size(16)));
};
template <>
struct Registers<8> {
    using Doubles = double __attribute__((vector_size(64)));
    using Mask = std::int64_t __attribute__((vector_size(64)));
    using Int32s = std::int32_t __attribute__((vector_size(32)));
};
template <int width>
using Doubles = typename Registers<width>::Doubles;
template <int width>
using Mask = typename Registers<width>::Mask;
template <int width>
using Int32s = typename Registers<width>::Int32s;

// Registers a block, each loop's independent chains: eight of two or four doubles (four or sixteen of
// four were slower), four of eight, 32 lanes as with AVX2 (eight of eight were no faster, and would
// double a partial block's scratch).
template <int width>
constexpr std::size_t kRegisters = width == 8 ? 4 : 8;

template <int width>
constexpr std::size_t kLanes = kRegisters<width> * width;

template <int width>
using Lanes = std::array<Doubles<width>, kRegisters<width>>;

// One block's screws, Screw's members in lanes; quaternions as x, y, z, w like Eigen's coefficients.
template <int width>
struct Block {
    template <std::size_t count>
    using Components = std::array<Lanes<width>, count>;
    Components<4> fromOrientation;   // qa
    Components<3> fromPosition;      // pa
    Components<4> turnedOrientation; // (0, S)·qa; qb between relativeRotation and rotationTerms
    Components<3> axis;              // S
    Components<3> sinSquaredTerm;    // V₁; Δ = pb − pa between rotationTerms and translationTerms
    Components<3> sinCosTerm;        // V₂
    Lanes<width> sinHalfAngle;       // sin a, or 0 in a lane without rotation
    Lanes<width> cosHalfAngle;       // cos a, or 1 in a lane without rotation
    Lanes<width> cotangent;          // cot a
    Lanes<width> halfAngle;          // a, or NaN in a lane without rotation (see turnAt)
    Lanes<width> slide;              // d
    // Between the loops of buildBlock:
    Components<3> relativeVector;                 // σ·(qb·conj(qa)).vec()
    Lanes<width> productW;                        // (qb·conj(qa)).w, whose sign is σ
    Lanes<width> normSquared;                     // sin²a
    std::array<std::int32_t, kLanes<width>> rows; // each lane's row of kAngleTable
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

// Lanes of a and b interleaved, (a₀, b₀, a₂, b₂, …) and (a₁, b₁, a₃, b₃, …): within each pair of
// lanes, the transpose of the 2 × 2 matrix whose rows are a's and b's.
template <int width>
[[gnu::always_inline]] inline std::array<Doubles<width>, 2> interleaved(Doubles<width> a, Doubles<width> b)
{
    if constexpr (width == 2)
        return {__builtin_shufflevector(a, b, 0, 2), __builtin_shufflevector(a, b, 1, 3)};
    else if constexpr (width == 4)
        return {__builtin_shufflevector(a, b, 0, 4, 2, 6), __builtin_shufflevector(a, b, 1, 5, 3, 7)};
    else
        return {__builtin_shufflevector(a, b, 0, 8, 2, 10, 4, 12, 6, 14),
                __builtin_shufflevector(a, b, 1, 9, 3, 11, 5, 13, 7, 15)};
}

// Within each quad of lanes (the whole register of four, each half of a register of eight), the
// first pairs of a's and b's quads, and the second pairs.
template <int width>
[[gnu::always_inline]] inline std::array<Doubles<width>, 2> pairsOfQuads(Doubles<width> a, Doubles<width> b)
{
    if constexpr (width == 4)
        return {__builtin_shufflevector(a, b, 0, 1, 4, 5), __builtin_shufflevector(a, b, 2, 3, 6, 7)};
    else
        return {__builtin_shufflevector(a, b, 0, 1, 8, 9, 4, 5, 12, 13),
                __builtin_shufflevector(a, b, 2, 3, 10, 11, 6, 7, 14, 15)};
}

// Within each quad of lanes, the transpose of the 4 × 4 matrix whose rows are the four registers'
// quads: pairs exchanged between registers, then interleaved. A transpose is its own inverse, so this
// one takes quads just loaded to lanes, and lanes to quads to store.
template <int width>
[[gnu::always_inline]] inline std::array<Doubles<width>, 4> transposed(const std::array<Doubles<width>, 4>& rows)
{
    const auto [first02, second02] = pairsOfQuads<width>(rows[0], rows[2]);
    const auto [first13, second13] = pairsOfQuads<width>(rows[1], rows[3]);
    const auto [c0, c1] = interleaved<width>(first02, first13);
    const auto [c2, c3] = interleaved<width>(second02, second13);
    return {c0, c1, c2, c3};
}

// The register of eight doubles whose halves are `low` and `high`, and the inverse.
[[gnu::always_inline]] inline Doubles<8> joined(Doubles<4> low, Doubles<4> high)
{
    return __builtin_shufflevector(low, high, 0, 1, 2, 3, 4, 5, 6, 7);
}
[[gnu::always_inline]] inline std::array<Doubles<4>, 2> lowAndHigh(Doubles<8> value)
{
    return {__builtin_shufflevector(value, value, 0, 1, 2, 3), __builtin_shufflevector(value, value, 4, 5, 6, 7)};
}

// A register of doubles loaded from `row`, or stored to it, whatever its alignment. The loads below are
// each written out, not made in a loop into an array of registers, which GCC copies through the stack.
template <class Register>
[[gnu::always_inline]] inline Register loaded(const unsigned char* row)
{
    Register value;
    std::memcpy(&value, row, sizeof value);
    return value;
}
template <class Register>
[[gnu::always_inline]] inline void store(unsigned char* row, Register value)
{
    std::memcpy(row, &value, sizeof value);
}

// The pairs of doubles at `first` and `second` in one register of four.
[[gnu::always_inline]] inline Doubles<4> loadedPairs(const unsigned char* first, const unsigned char* second)
{
    return __builtin_shufflevector(loaded<Doubles<2>>(first), loaded<Doubles<2>>(second), 0, 1, 2, 3);
}

// `width` rows of two doubles in memory as two registers of lanes: lane i of register c holds
// rows[i][c]. A row is one load.
template <int width>
[[gnu::always_inline]] inline std::array<Doubles<width>, 2> loadPairs(const std::array<const unsigned char*, width>& rows)
{
    if constexpr (width == 2) {
        return interleaved<2>(loaded<Doubles<2>>(rows[0]), loaded<Doubles<2>>(rows[1]));
    } else {
        const Doubles<4> even = loadedPairs(rows[0], rows[2]);
        const Doubles<4> odd = loadedPairs(rows[1], rows[3]);
        if constexpr (width == 4)
            return interleaved<4>(even, odd);
        else
            return interleaved<8>(joined(even, loadedPairs(rows[4], rows[6])), joined(odd, loadedPairs(rows[5], rows[7])));
    }
}

// `width` quads, rows of four doubles in memory, as four registers of lanes: lane i of register c
// holds rows[i][c]. A quad is one load with AVX2 or AVX-512, two with SSE2.
template <int width>
[[gnu::always_inline]] inline std::array<Doubles<width>, 4> loadQuads(const std::array<const unsigned char*, width>& rows)
{
    using Quad = Doubles<4>;
    if constexpr (width == 2) {
        const auto [c0, c1] = loadPairs<2>(rows);
        const auto [c2, c3] = loadPairs<2>({rows[0] + 2 * sizeof(double), rows[1] + 2 * sizeof(double)});
        return {c0, c1, c2, c3};
    } else if constexpr (width == 4) {
        return transposed<4>({loaded<Quad>(rows[0]), loaded<Quad>(rows[1]), loaded<Quad>(rows[2]), loaded<Quad>(rows[3])});
    } else {
        return transposed<8>({joined(loaded<Quad>(rows[0]), loaded<Quad>(rows[4])),
                              joined(loaded<Quad>(rows[1]), loaded<Quad>(rows[5])),
                              joined(loaded<Quad>(rows[2]), loaded<Quad>(rows[6])),
                              joined(loaded<Quad>(rows[3]), loaded<Quad>(rows[7]))});
    }
}

// The inverse of loadQuads: lane i of register c to rows[i][c].
template <int width>
[[gnu::always_inline]] inline void storeQuads(const std::array<Doubles<width>, 4>& lanes,
                                              const std::array<unsigned char*, width>& rows)
{
    if constexpr (width == 2) {
        const auto [low0, low1] = interleaved<2>(lanes[0], lanes[1]);
        const auto [high0, high1] = interleaved<2>(lanes[2], lanes[3]);
        store(rows[0], low0);
        store(rows[0] + sizeof low0, high0);
        store(rows[1], low1);
        store(rows[1] + sizeof low1, high1);
    } else if constexpr (width == 4) {
        const auto [q0, q1, q2, q3] = transposed<4>(lanes);
        store(rows[0], q0);
        store(rows[1], q1);
        store(rows[2], q2);
        store(rows[3], q3);
    } else {
        const std::array<Doubles<8>, 4> transpose = transposed<8>(lanes);
        for (int c = 0; c < 4; ++c) {
            const auto [low, high] = lowAndHigh(transpose[c]);
            store(rows[c], low);
            store(rows[c + 4], high);
        }
    }
}

// A pose's coefficients as two quads: its quaternion x, y, z, w, and its position x, y, z with the
// 8 bytes of padding that end a Pose. The batch moves whole quads only of the poses in its callers'
// spans and its own scratch arrays, elements of arrays, whose padding belongs to them alone: a load's
// padding lane is never used, and a store writes z there again.
static_assert(std::is_standard_layout_v<Pose> && sizeof(Pose) == 8 * sizeof(double)
              && offsetof(Pose, orientation) == 0 && offsetof(Pose, position) == 4 * sizeof(double));
constexpr std::size_t kOrientationQuad = offsetof(Pose, orientation);
constexpr std::size_t kPositionQuad = offsetof(Pose, position);

// The quads at `offset` of `width` poses as registers of lanes.
template <int width>
[[gnu::always_inline]] inline std::array<Doubles<width>, 4> loadPoseQuads(const Pose* poses, std::size_t offset)
{
    std::array<const unsigned char*, width> rows;
    for (int i = 0; i < width; ++i)
        rows[i] = reinterpret_cast<const unsigned char*>(&poses[i]) + offset;
    return loadQuads<width>(rows);
}

// The orientations of `width` poses in lanes: x, y, z, w.
template <int width>
[[gnu::always_inline]] inline std::array<Doubles<width>, 4> loadOrientations(const Pose* poses)
{
    return loadPoseQuads<width>(poses, kOrientationQuad);
}

// The positions of `width` poses in lanes: x, y, z.
template <int width>
[[gnu::always_inline]] inline std::array<Doubles<width>, 3> loadPositions(const Pose* poses)
{
    const auto [x, y, z, padding] = loadPoseQuads<width>(poses, kPositionQuad);
    return {x, y, z};
}

// out[i] = the pose of lane i, its seven coefficients as loadOrientations and loadPositions give them;
// the padding gets z again.
template <int width>
[[gnu::always_inline]] inline void storePoses(const std::array<Doubles<width>, 7>& c, Pose* out)
{
    std::array<unsigned char*, width> orientations;
    std::array<unsigned char*, width> positions;
    for (int i = 0; i < width; ++i) {
        orientations[i] = reinterpret_cast<unsigned char*>(&out[i]) + kOrientationQuad;
        positions[i] = reinterpret_cast<unsigned char*>(&out[i]) + kPositionQuad;
    }
    storeQuads<width>({c[0], c[1], c[2], c[3]}, orientations);
    storeQuads<width>({c[4], c[5], c[6], c[6]}, positions);
}

// The product qb·conj(qa) of register v's pairs, in the order of Eigen's SSE2 product (Geometry_SIMD.h),
// whose result Screw uses: its vector turned to σ·vec, its w and the vector's squared norm, sin²a; and
// qa and qb in lanes.
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
    for (std::size_t c = 0; c < 4; ++c) {
        block.fromOrientation[c][v] = qa[c];
        block.turnedOrientation[c][v] = qb[c]; // until rotationTerms
    }
}

// Screw's members that follow from sin a: the square root and the division, then the axis, cot a and
// (0, S)·qa; with each lane's row of the angle table if `withAngle`. The lanes without rotation are
// left to the single screw, their sin a and cos a set to 0 and 1 so that every row stays in its table.
// The positions too, which keep the processor busy while it divides: pa in lanes, and Δ.
template <int width, bool withAngle>
[[gnu::always_inline]] inline void rotationTerms(const Pose* from, const Pose* to, Block<width>& block, std::size_t v)
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
        const Int32s<width> bins = __builtin_convertvector(smaller * static_cast<double>(kAngleBins), Int32s<width>);
        const Int32s<width> steepHalf = __builtin_convertvector(sine > cosine, Int32s<width>) & kAngleBinsPerHalf;
        const Int32s<width> rows = bins + steepHalf;
        std::memcpy(&block.rows[v * width], &rows, sizeof rows);
    }
    const D minusCotangent = -cotangent;
    for (std::size_t c = 0; c < 4; ++c)
        block.turnedOrientation[c][v] = toWeight * block.turnedOrientation[c][v] + minusCotangent * block.fromOrientation[c][v];
    const std::array<D, 3> pa = loadPositions<width>(from + v * width);
    const std::array<D, 3> pb = loadPositions<width>(to + v * width);
    for (std::size_t c = 0; c < 3; ++c) {
        block.sinSquaredTerm[c][v] = pb[c] - pa[c]; // Δ, until translationTerms
        block.fromPosition[c][v] = pa[c];
    }
}

// Screw's members that carry the positions: d, V₁ and V₂.
template <int width>
[[gnu::always_inline]] inline void translationTerms(Block<width>& block, std::size_t v)
{
    using D = Doubles<width>;
    const D cx = block.sinSquaredTerm[0][v], cy = block.sinSquaredTerm[1][v], cz = block.sinSquaredTerm[2][v]; // Δ
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
}

// fastAngleOnUnitCircle of register v, from its rows; NaN in a lane without rotation.
template <int width>
[[gnu::always_inline]] inline void fastHalfAngle(Block<width>& block, std::size_t v)
{
    using D = Doubles<width>;
    const D cosine = block.cosHalfAngle[v], sine = block.sinHalfAngle[v];
    std::array<const unsigned char*, width> entries;
    for (int i = 0; i < width; ++i)
        entries[i] = reinterpret_cast<const unsigned char*>(&kAngleTable[static_cast<std::size_t>(block.rows[v * width + i])]);
    const auto [angleBelow, sinBelow, cosBelow, padding] = loadQuads<width>(entries);
    const D angle = angleBelow + arcsineSeries(sine * cosBelow - cosine * sinBelow);
    block.halfAngle[v] = sine == 0.0 ? D{} + std::numeric_limits<double>::quiet_NaN() : angle;
}

// Screw(from[l], to[l]) for the kLanes<width> pairs, with its angle only if `withAngle`.
template <int width, bool withAngle>
[[gnu::always_inline]] inline void buildBlock(const Pose* from, const Pose* to, Block<width>& block)
{
    for (std::size_t v = 0; v < kRegisters<width>; ++v)
        relativeRotation(from, to, block, v);
    for (std::size_t v = 0; v < kRegisters<width>; ++v)
        rotationTerms<width, withAngle>(from, to, block, v);
    for (std::size_t v = 0; v < kRegisters<width>; ++v)
        translationTerms(block, v);
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
    std::array<std::int64_t, kLanes<width>> steps;
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
        std::array<const unsigned char*, width> entries;
        for (int i = 0; i < width; ++i)
            entries[i] = reinterpret_cast<const unsigned char*>(&kSinCosTable[static_cast<std::size_t>(turn.steps[v * width + i])]);
        const auto [sinK, cosK] = loadPairs<width>(entries);
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
// copies padded with identities (PartialBlock).
struct BlockPairs {
    const Pose* from;
    const Pose* to;
    std::size_t used; // lanes that hold a pair
};

// A last, partial block's pairs padded with identities, and its poses before they are copied out. Made
// only for such a block: made for every batch, its 3·kLanes poses cost 100 to 150 ns a batch with
// AVX2, 30% of the time of a batch of 32 pairs.
template <int width>
struct PartialBlock {
    std::array<Pose, kLanes<width>> from;
    std::array<Pose, kLanes<width>> to;
    std::array<Pose, kLanes<width>> poses;
};

template <int width>
[[gnu::always_inline]] inline BlockPairs blockPairs(std::span<const Pose> from, std::span<const Pose> to,
                                                    std::size_t first, std::optional<PartialBlock<width>>& partial)
{
    const std::size_t used = std::min(kLanes<width>, from.size() - first);
    if (used == kLanes<width>)
        return {from.data() + first, to.data() + first, used};
    PartialBlock<width>& padded = partial.emplace();
    std::copy_n(from.begin() + static_cast<std::ptrdiff_t>(first), used, padded.from.begin());
    std::copy_n(to.begin() + static_cast<std::ptrdiff_t>(first), used, padded.to.begin());
    return {padded.from.data(), padded.to.data(), used};
}

// out[l] = Screw::pose of each lane that holds a pair: posesOfBlock straight into `target` for a full
// block, through `partial` for the last, partial one.
template <int width>
[[gnu::always_inline]] inline void storeBlock(const Block<width>& block, double t, const Turn<width>& turn,
                                              std::size_t used, Pose* target, std::optional<PartialBlock<width>>& partial)
{
    if (used == kLanes<width>) {
        posesOfBlock(block, t, turn, target);
        return;
    }
    posesOfBlock(block, t, turn, partial->poses.data());
    std::copy_n(partial->poses.begin(), used, target);
}

// What a batch reuses from block to block.
template <int width>
struct Scratch {
    Block<width> block;
    Turn<width> turn;
    std::optional<PartialBlock<width>> partial;
};

template <int width>
[[gnu::always_inline]] inline void screwsAtLanes(std::span<const Pose> from, std::span<const Pose> to,
                                                 std::span<const double> times, std::span<Pose> out)
{
    const std::size_t n = from.size();
    if (to.size() != n || out.size() != n * times.size())
        throw std::invalid_argument("screwsAt: spans of different lengths");
    Scratch<width> scratch;
    for (std::size_t first = 0; first < n; first += kLanes<width>) {
        const BlockPairs pairs = blockPairs(from, to, first, scratch.partial);
        buildBlock<width, true>(pairs.from, pairs.to, scratch.block);
        for (std::size_t k = 0; k < times.size(); ++k) {
            Pose* target = out.data() + k * n + first;
            const bool leftToSingleScrew = turnAt(scratch.block, times[k], scratch.turn);
            storeBlock(scratch.block, times[k], scratch.turn, pairs.used, target, scratch.partial);
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
    for (std::size_t first = 0; first < from.size(); first += kLanes<width>) {
        const BlockPairs pairs = blockPairs(from, to, first, scratch.partial);
        buildBlock<width, false>(pairs.from, pairs.to, scratch.block);
        turnAtMidpoint(scratch.block, scratch.turn);
        Pose* target = out.data() + first;
        storeBlock(scratch.block, 0.5, scratch.turn, pairs.used, target, scratch.partial);
        for (std::size_t l = 0; l < pairs.used; ++l)
            if (lane<width>(scratch.block.sinHalfAngle, l) == 0.0) [[unlikely]]
                target[l] = Screw::midpoint(pairs.from[l], pairs.to[l]);
    }
}

// One call of screwsAt (the times given) or of screwMidpoints.
struct BatchCall {
    std::span<const Pose> from;
    std::span<const Pose> to;
    std::optional<std::span<const double>> times; // none for the midpoints
    std::span<Pose> out;
};

template <int width>
[[gnu::always_inline]] inline void runLanes(const BatchCall& call)
{
    if (call.times)
        screwsAtLanes<width>(call.from, call.to, *call.times, call.out);
    else
        screwMidpointsLanes<width>(call.from, call.to, call.out);
}

// The same lanes for AVX2 and AVX-512. AVX-512 has fused multiply-adds, which would round differently
// from the single screw: -ffp-contract=off (src/core/CMakeLists.txt) keeps GCC from forming them.
// AVX-512's vector-length extension (VL) gives the lanes of eight its 32 registers for their loads and
// stores of quads; without it they were 5% slower.
[[gnu::target("avx2")]] void runAvx2(const BatchCall& call)
{
    runLanes<4>(call);
}

[[gnu::target("avx512f,avx512vl")]] void runAvx512(const BatchCall& call)
{
    runLanes<8>(call);
}

using screw_batch_detail::InstructionSet;

InstructionSet widestInstructionSet()
{
    static const InstructionSet widest = [] {
        __builtin_cpu_init(); // its checks include the system's support for each set's registers
        if (__builtin_cpu_supports("avx2") == 0)
            return InstructionSet::Sse2;
        // AVX-512's lanes hold AVX2's instructions too: the compiler takes AVX-512 to include AVX2.
        if (__builtin_cpu_supports("avx512f") != 0 && __builtin_cpu_supports("avx512vl") != 0)
            return InstructionSet::Avx512;
        return InstructionSet::Avx2;
    }();
    return widest;
}

void run(InstructionSet set, const BatchCall& call)
{
    if (!screw_batch_detail::processorHas(set))
        throw std::invalid_argument(std::string(call.times ? "screwsAtWith" : "screwMidpointsWith")
                                    + ": this processor lacks " + screw_batch_detail::instructionSetName(set));
    switch (set) {
    case InstructionSet::Sse2:
        runLanes<2>(call);
        return;
    case InstructionSet::Avx2:
        runAvx2(call);
        return;
    case InstructionSet::Avx512:
        runAvx512(call);
        return;
    }
}

} // namespace

namespace screw_batch_detail {

bool processorHas(InstructionSet set)
{
    const InstructionSet widest = widestInstructionSet();
    switch (set) {
    case InstructionSet::Sse2:
        return true;
    case InstructionSet::Avx2:
        return widest != InstructionSet::Sse2;
    case InstructionSet::Avx512:
        return widest == InstructionSet::Avx512;
    }
    return false; // not one of the sets
}

std::string instructionSetName(InstructionSet set)
{
    switch (set) {
    case InstructionSet::Sse2:
        return "SSE2";
    case InstructionSet::Avx2:
        return "AVX2";
    case InstructionSet::Avx512:
        return "AVX-512";
    }
    return "an unknown instruction set";
}

void screwsAtWith(InstructionSet set, std::span<const Pose> from, std::span<const Pose> to,
                  std::span<const double> times, std::span<Pose> out)
{
    run(set, {from, to, times, out});
}

void screwMidpointsWith(InstructionSet set, std::span<const Pose> from, std::span<const Pose> to,
                        std::span<Pose> out)
{
    run(set, {from, to, std::nullopt, out});
}

} // namespace screw_batch_detail

void screwsAt(std::span<const Pose> from, std::span<const Pose> to, std::span<const double> times,
              std::span<Pose> out)
{
    screw_batch_detail::screwsAtWith(widestInstructionSet(), from, to, times, out);
}

void screwMidpoints(std::span<const Pose> from, std::span<const Pose> to, std::span<Pose> out)
{
    screw_batch_detail::screwMidpointsWith(widestInstructionSet(), from, to, out);
}

} // namespace gyre
