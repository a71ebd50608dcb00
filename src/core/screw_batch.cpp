#include "core/screw_batch.h"

#include "core/fast_trig.h"
#include "core/screw.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gyre {

namespace {

using screw_batch_detail::Block;
using screw_batch_detail::Lanes;

// Up to kScrewLanes poses in lanes; lanes past the poses hold the identity.
struct PoseLanes {
    std::array<Lanes, 4> orientation;
    std::array<Lanes, 3> position;
};

PoseLanes load(std::span<const Pose> poses, std::size_t first)
{
    PoseLanes lanes;
    const std::size_t count = std::min(kScrewLanes, poses.size() - first);
    for (std::size_t l = 0; l < kScrewLanes; ++l) {
        const Pose pose = l < count ? poses[first + l] : Pose{};
        const auto lane = static_cast<Eigen::Index>(l);
        for (Eigen::Index c = 0; c < 4; ++c)
            lanes.orientation[static_cast<std::size_t>(c)][lane] = pose.orientation.coeffs()[c];
        for (Eigen::Index c = 0; c < 3; ++c)
            lanes.position[static_cast<std::size_t>(c)][lane] = pose.position[c];
    }
    return lanes;
}

void store(const PoseLanes& lanes, std::span<Pose> out, std::size_t first)
{
    const std::size_t count = std::min(kScrewLanes, out.size() - first);
    for (std::size_t l = 0; l < count; ++l) {
        Pose& pose = out[first + l];
        const auto lane = static_cast<Eigen::Index>(l);
        for (Eigen::Index c = 0; c < 4; ++c)
            pose.orientation.coeffs()[c] = lanes.orientation[static_cast<std::size_t>(c)][lane];
        for (Eigen::Index c = 0; c < 3; ++c)
            pose.position[c] = lanes.position[static_cast<std::size_t>(c)][lane];
    }
}

// The screws from → to of every lane (Screw's constructor without the angle).
screw_detail::Terms<Lanes> assignTerms(const PoseLanes& from, const PoseLanes& to, Block& block)
{
    const screw_detail::Terms<Lanes> t = screw_detail::terms(from.orientation, from.position, to.orientation, to.position);
    block.fromOrientation = from.orientation;
    block.turnedOrientation = t.turned;
    block.fromPosition = from.position;
    block.axis = t.axis;
    block.sinSquaredTerm = t.sinSquared;
    block.sinCosTerm = t.sinCos;
    block.slide = t.slide;
    return t;
}

// Screw::pose in every lane.
PoseLanes poseLanes(const Block& block, double t, const Lanes& sinT, const Lanes& cosT, const Lanes& sinSquared,
                    const Lanes& sinCos)
{
    PoseLanes pose;
    for (std::size_t c = 0; c < 4; ++c)
        pose.orientation[c] = cosT * block.fromOrientation[c] + sinT * block.turnedOrientation[c];
    const Lanes along = t * block.slide;
    for (std::size_t c = 0; c < 3; ++c)
        pose.position[c] = ((block.fromPosition[c] + along * block.axis[c]) + sinSquared * block.sinSquaredTerm[c]) +
                           sinCos * block.sinCosTerm[c];
    return pose;
}

} // namespace

void ScrewBatch::assign(std::span<const Pose> from, std::span<const Pose> to)
{
    using namespace fast_trig_detail;
    if (from.size() != to.size())
        throw std::invalid_argument("a screw batch needs as many end poses as start poses");
    size_ = from.size();
    blocks_.resize((size_ + kScrewLanes - 1) / kScrewLanes);
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        Block& block = blocks_[b];
        const screw_detail::Terms<Lanes> t = assignTerms(load(from, b * kScrewLanes), load(to, b * kScrewLanes), block);
        // fastAngleOnUnitCircle: the table look-up lane by lane, the series in lanes. Without rotation
        // (cos, sin) = (1, 0) gives the angle 0 exactly, as Screw leaves it.
        Lanes belowAngle;
        Lanes belowSin;
        Lanes belowCos;
        for (Eigen::Index l = 0; l < static_cast<Eigen::Index>(kScrewLanes); ++l) {
            const TableAngle& below = kAngleTable[angleIndex(t.cosHalf[l], t.sinHalf[l])];
            belowAngle[l] = below.angle;
            belowSin[l] = below.sin;
            belowCos[l] = below.cos;
        }
        block.halfAngle = angleAbove(belowAngle, belowSin, belowCos, t.cosHalf, t.sinHalf);
    }
}

void ScrewBatch::evaluate(double t, std::span<Pose> out) const
{
    using namespace fast_trig_detail;
    if (out.size() != size_)
        throw std::invalid_argument("a screw batch writes one pose per screw");
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        const Block& block = blocks_[b];
        // fastSinCos(t·a) in lanes; a lane beyond the reduction's range takes the standard library's,
        // as fastSinCos does.
        const Lanes x = t * block.halfAngle;
        const bool inRange = (x.abs() <= kLargestReduced).all();
        const Reduced<Lanes> reduced = reduce(inRange ? x : Lanes(Lanes::Zero()));
        BasicSinCos<Lanes> step;
        for (Eigen::Index l = 0; l < static_cast<Eigen::Index>(kScrewLanes); ++l) {
            const std::size_t j = stepIndex(reduced.k[l]);
            step.sin[l] = kSinCosTable.sin[j];
            step.cos[l] = kSinCosTable.cos[j];
        }
        BasicSinCos<Lanes> turn = sumOfAngles(step, seriesSinCos(reduced.r));
        if (!inRange) [[unlikely]] {
            for (Eigen::Index l = 0; l < static_cast<Eigen::Index>(kScrewLanes); ++l) {
                const SinCos single = fastSinCos(x[l]);
                turn.sin[l] = single.sin;
                turn.cos[l] = single.cos;
            }
        }
        store(poseLanes(block, t, turn.sin, turn.cos, turn.sin * turn.sin, turn.sin * turn.cos), out, b * kScrewLanes);
    }
}

void screwMidpoints(std::span<const Pose> from, std::span<const Pose> to, std::span<Pose> out)
{
    if (from.size() != to.size() || out.size() != from.size())
        throw std::invalid_argument("screw midpoints need as many end poses and results as start poses");
    for (std::size_t first = 0; first < from.size(); first += kScrewLanes) {
        Block block;
        const screw_detail::Terms<Lanes> t = assignTerms(load(from, first), load(to, first), block);
        const screw_detail::HalfTurn<Lanes> half = screw_detail::halfTurn(t.cosHalf, t.sinHalf);
        store(poseLanes(block, 0.5, half.sin, half.cos, half.sinSquared, half.sinCos), out, first);
    }
}

} // namespace gyre
