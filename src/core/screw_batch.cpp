#include "core/screw_batch.h"

#include "core/fast_trig.h"
#include "core/screw.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>

// Each loop below runs over the lanes of one block with no branch and no call, so that GCC vectorises
// it (checked with -fopt-info-vec and in the disassembly: mulpd, not mulsd). The file is built with
// -fno-math-errno and -fno-trapping-math (src/core/CMakeLists.txt), so that std::sqrt is one packed
// instruction and a select may compute both of its sides; the table reads of the fast trigonometry
// are the only loads done a lane at a time.

namespace gyre {

namespace {

using namespace fast_trig_detail;

// Screws a block, the trip count of every loop below. With 8 BM_ScrewBatch took a third longer with
// AVX2 (the loops too short to overlap their iterations); 32 and 64 gained nothing over 16.
constexpr std::size_t kLanes = 16;
using Lanes = std::array<double, kLanes>;

// One block's screws, Screw's members in lanes; quaternions as x, y, z, w like Eigen's coefficients.
struct Block {
    std::array<Lanes, 4> fromOrientation;   // qa
    std::array<Lanes, 3> fromPosition;      // pa
    std::array<Lanes, 4> toOrientation;     // qb
    std::array<Lanes, 3> toPosition;        // pb
    std::array<Lanes, 4> turnedOrientation; // (0, S)·qa
    std::array<Lanes, 3> axis;              // S
    std::array<Lanes, 3> sinSquaredTerm;    // V₁
    std::array<Lanes, 3> sinCosTerm;        // V₂
    Lanes sinHalfAngle;                     // sin a, or 0 in a lane without rotation
    Lanes cosHalfAngle;                     // cos a, or 1 in a lane without rotation
    Lanes cotangent;                        // cot a
    Lanes toWeight;                         // σ / sin a
    Lanes halfAngle;                        // a
    Lanes slide;                            // d
};

// Two doubles, one SSE2 register (GCC's and Clang's vector extension).
using DoublePair = double __attribute__((vector_size(16)));

[[gnu::always_inline]] inline DoublePair loadPair(const double* p)
{
    DoublePair pair;
    std::memcpy(&pair, p, sizeof pair);
    return pair;
}

[[gnu::always_inline]] inline void storePair(double* p, DoublePair pair)
{
    std::memcpy(p, &pair, sizeof pair);
}

// The poses of two lanes into `coefficients` (a quaternion's four or a position's three arrays of lanes)
// at lanes l and l + 1: each two adjacent coefficients of a pose loaded together, and the pairs of the
// two poses interleaved. A loop over the lanes that read the poses' coefficients one by one, as GCC
// vectorises it, took a fifth of the screw's time.
template <std::size_t count>
[[gnu::always_inline]] inline void loadTwoLanes(const double* first, const double* second,
                                                std::array<Lanes, count>& coefficients, std::size_t l)
{
    for (std::size_t c = 0; c + 1 < count; c += 2) {
        const DoublePair a = loadPair(first + c);
        const DoublePair b = loadPair(second + c);
        storePair(&coefficients[c][l], DoublePair{a[0], b[0]});
        storePair(&coefficients[c + 1][l], DoublePair{a[1], b[1]});
    }
    if constexpr (count % 2 == 1) {
        coefficients[count - 1][l] = first[count - 1];
        coefficients[count - 1][l + 1] = second[count - 1];
    }
}

// The block's pairs into its lanes.
[[gnu::always_inline]] inline void loadBlock(const Pose* from, const Pose* to, Block& block)
{
    static_assert(kLanes % 2 == 0);
    for (std::size_t l = 0; l < kLanes; l += 2) {
        loadTwoLanes(from[l].orientation.coeffs().data(), from[l + 1].orientation.coeffs().data(), block.fromOrientation, l);
        loadTwoLanes(to[l].orientation.coeffs().data(), to[l + 1].orientation.coeffs().data(), block.toOrientation, l);
        loadTwoLanes(from[l].position.data(), from[l + 1].position.data(), block.fromPosition, l);
        loadTwoLanes(to[l].position.data(), to[l + 1].position.data(), block.toPosition, l);
    }
}

// Screw(from[l], to[l]) for the kLanes pairs, with its angle only if `withAngle`; the lanes without
// rotation are left to the single screw, their sin a and cos a set to 0 and 1 so that every index below
// stays in its table. Three loops, each short enough for the processor to run several of its
// iterations at once: otherwise each waits for its own square root and division, and then its table.
template <bool withAngle>
[[gnu::always_inline]] inline void buildBlock(const Pose* from, const Pose* to, Block& block)
{
    loadBlock(from, to, block);
    for (std::size_t l = 0; l < kLanes; ++l) {
        // qb·conj(qa) in the order of Eigen's SSE2 product (Geometry_SIMD.h), whose result Screw uses.
        const double ax = -block.fromOrientation[0][l], ay = -block.fromOrientation[1][l];
        const double az = -block.fromOrientation[2][l], aw = block.fromOrientation[3][l];
        const double bx = block.toOrientation[0][l], by = block.toOrientation[1][l];
        const double bz = block.toOrientation[2][l], bw = block.toOrientation[3][l];
        const double px = (bw * ax + by * az) - (bz * ay - bx * aw);
        const double py = (bw * ay + by * aw) + (bz * ax - bx * az);
        const double pz = (bw * az - by * ax) + (bz * aw + bx * ay);
        const double pw = (bw * aw - by * ay) - (bz * az + bx * ax);
        const double side = std::copysign(1.0, pw); // σ
        const double rx = side * px, ry = side * py, rz = side * pz, rw = side * pw;
        const double s = std::sqrt((rx * rx + ry * ry) + rz * rz);
        const bool rotating = s > Screw::kNoRotation;
        const double inverseSin = 1.0 / s;
        block.axis[0][l] = inverseSin * rx;
        block.axis[1][l] = inverseSin * ry;
        block.axis[2][l] = inverseSin * rz;
        block.cotangent[l] = rw * inverseSin;
        block.toWeight[l] = side * inverseSin;
        block.sinHalfAngle[l] = rotating ? s : 0.0;
        block.cosHalfAngle[l] = rotating ? rw : 1.0;
    }
    for (std::size_t l = 0; l < kLanes; ++l) {
        const double sx = block.axis[0][l], sy = block.axis[1][l], sz = block.axis[2][l];
        const double cotangent = block.cotangent[l];
        const double cx = block.toPosition[0][l] - block.fromPosition[0][l]; // Δ
        const double cy = block.toPosition[1][l] - block.fromPosition[1][l];
        const double cz = block.toPosition[2][l] - block.fromPosition[2][l];
        const double d = (sx * cx + sy * cy) + sz * cz;
        const double acrossX = cx - d * sx, acrossY = cy - d * sy, acrossZ = cz - d * sz; // Δ⊥
        const double turnedX = sy * cz - sz * cy, turnedY = sz * cx - sx * cz, turnedZ = sx * cy - sy * cx; // S×Δ
        block.sinSquaredTerm[0][l] = acrossX + cotangent * turnedX;
        block.sinSquaredTerm[1][l] = acrossY + cotangent * turnedY;
        block.sinSquaredTerm[2][l] = acrossZ + cotangent * turnedZ;
        block.sinCosTerm[0][l] = cotangent * acrossX - turnedX;
        block.sinCosTerm[1][l] = cotangent * acrossY - turnedY;
        block.sinCosTerm[2][l] = cotangent * acrossZ - turnedZ;
        block.slide[l] = d;
        for (std::size_t c = 0; c < 4; ++c)
            block.turnedOrientation[c][l] =
                block.toWeight[l] * block.toOrientation[c][l] + -cotangent * block.fromOrientation[c][l];
    }
    if constexpr (withAngle)
        for (std::size_t l = 0; l < kLanes; ++l)
            block.halfAngle[l] = fastAngleOnUnitCircle(block.cosHalfAngle[l], block.sinHalfAngle[l]);
}

// sin(ta) and cos(ta) of each lane at one t, with sin²(ta) and sin(ta)·cos(ta).
struct Turn {
    Lanes sin;
    Lanes cos;
    Lanes sinSquared;
    Lanes sinCos;
    Lanes singleScrew; // turnAt's: 1 in a lane left to the single screw, else 0
};

// The turn of Screw::at(t): fastSinCos(t·a). A lane beyond the reduction's range gets the turn of 0
// here, and the single screw after.
[[gnu::always_inline]] inline void turnAt(const Block& block, double t, Turn& turn)
{
    for (std::size_t l = 0; l < kLanes; ++l) {
        const double angle = t * block.halfAngle[l];
        const bool reduced = std::abs(angle) <= kLargestReduced;
        const double x = reduced ? angle : 0.0;
        const SinCos sinCos = fastSinCosReduced(x);
        const double sinT = sinCos.sin;
        const double cosT = sinCos.cos;
        turn.sin[l] = sinT;
        turn.cos[l] = cosT;
        turn.sinSquared[l] = sinT * sinT;
        turn.sinCos[l] = sinT * cosT;
        turn.singleScrew[l] = (!reduced | (block.sinHalfAngle[l] == 0.0)) ? 1.0 : 0.0;
    }
}

// The turn of Screw::midpoint, by its half-angle formulas.
[[gnu::always_inline]] inline void turnAtMidpoint(const Block& block, Turn& turn)
{
    for (std::size_t l = 0; l < kLanes; ++l) {
        const double sinA = block.sinHalfAngle[l];
        const double onePlusCos = 1.0 + block.cosHalfAngle[l];
        const double cosT = std::sqrt(0.5 * onePlusCos);
        turn.sin[l] = 0.5 * sinA / cosT;
        turn.cos[l] = cosT;
        turn.sinSquared[l] = 0.5 * sinA * sinA / onePlusCos;
        turn.sinCos[l] = 0.5 * sinA;
    }
}

// out[l] = Screw::pose of lane l at t with `turn`.
[[gnu::always_inline]] inline void posesOfBlock(const Block& block, double t, const Turn& turn, Pose* out)
{
    for (std::size_t l = 0; l < kLanes; ++l) {
        Eigen::Quaterniond& q = out[l].orientation;
        for (int c = 0; c < 4; ++c)
            q.coeffs()[c] = turn.cos[l] * block.fromOrientation[c][l] + turn.sin[l] * block.turnedOrientation[c][l];
        const double along = t * block.slide[l];
        Eigen::Vector3d& p = out[l].position;
        for (int c = 0; c < 3; ++c)
            p[c] = ((block.fromPosition[c][l] + along * block.axis[c][l]) + turn.sinSquared[l] * block.sinSquaredTerm[c][l])
                   + turn.sinCos[l] * block.sinCosTerm[c][l];
    }
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
[[gnu::always_inline]] inline void storeBlock(const Block& block, double t, const Turn& turn, std::size_t used,
                                              Pose* target, std::array<Pose, kLanes>& padded)
{
    if (used == kLanes) {
        posesOfBlock(block, t, turn, target);
        return;
    }
    posesOfBlock(block, t, turn, padded.data());
    std::copy_n(padded.begin(), used, target);
}

// What a batch reuses from block to block.
struct Scratch {
    Block block;
    Turn turn;
    PaddedPairs pairs;
    std::array<Pose, kLanes> poses;
};

[[gnu::always_inline]] inline void screwsAtLanes(std::span<const Pose> from, std::span<const Pose> to,
                                                 std::span<const double> times, std::span<Pose> out)
{
    const std::size_t n = from.size();
    if (to.size() != n || out.size() != n * times.size())
        throw std::invalid_argument("screwsAt: spans of different lengths");
    Scratch scratch;
    for (std::size_t first = 0; first < n; first += kLanes) {
        const BlockPairs pairs = blockPairs(from, to, first, scratch.pairs);
        buildBlock<true>(pairs.from, pairs.to, scratch.block);
        for (std::size_t k = 0; k < times.size(); ++k) {
            Pose* target = out.data() + k * n + first;
            turnAt(scratch.block, times[k], scratch.turn);
            storeBlock(scratch.block, times[k], scratch.turn, pairs.used, target, scratch.poses);
            // One branch a block, not one a lane: the sum of the flags.
            double leftToSingleScrew = 0.0;
            for (const double flag : scratch.turn.singleScrew)
                leftToSingleScrew += flag;
            if (leftToSingleScrew != 0.0) [[unlikely]]
                for (std::size_t l = 0; l < pairs.used; ++l)
                    if (scratch.turn.singleScrew[l] != 0.0)
                        target[l] = screwInterpolate(pairs.from[l], times[k], pairs.to[l]);
        }
    }
}

[[gnu::always_inline]] inline void screwMidpointsLanes(std::span<const Pose> from, std::span<const Pose> to,
                                                       std::span<Pose> out)
{
    if (to.size() != from.size() || out.size() != from.size())
        throw std::invalid_argument("screwMidpoints: spans of different lengths");
    Scratch scratch;
    for (std::size_t first = 0; first < from.size(); first += kLanes) {
        const BlockPairs pairs = blockPairs(from, to, first, scratch.pairs);
        buildBlock<false>(pairs.from, pairs.to, scratch.block);
        turnAtMidpoint(scratch.block, scratch.turn);
        Pose* target = out.data() + first;
        storeBlock(scratch.block, 0.5, scratch.turn, pairs.used, target, scratch.poses);
        for (std::size_t l = 0; l < pairs.used; ++l)
            if (scratch.block.sinHalfAngle[l] == 0.0) [[unlikely]]
                target[l] = Screw::midpoint(pairs.from[l], pairs.to[l]);
    }
}

// The same lanes for AVX2, four doubles a register, without FMA: fused products would round
// differently from the single screw.
[[gnu::target("avx2")]] void screwsAtAvx2(std::span<const Pose> from, std::span<const Pose> to,
                                          std::span<const double> times, std::span<Pose> out)
{
    screwsAtLanes(from, to, times, out);
}

[[gnu::target("avx2")]] void screwMidpointsAvx2(std::span<const Pose> from, std::span<const Pose> to,
                                                std::span<Pose> out)
{
    screwMidpointsLanes(from, to, out);
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
    screwsAtLanes(from, to, times, out);
}

void screwMidpointsPortable(std::span<const Pose> from, std::span<const Pose> to, std::span<Pose> out)
{
    screwMidpointsLanes(from, to, out);
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
