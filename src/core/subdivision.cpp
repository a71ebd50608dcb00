#include "core/subdivision.h"

#include "core/quaternion_math.h"
#include "core/screw_batch.h"

#include <array>
#include <limits>
#include <span>
#include <stdexcept>
#include <utility>

namespace gyre {

namespace {

// The two-pose primitive of the decoupled alternative: slerp for the orientation, a straight line for
// the position. Like Screw, computed once and evaluated at any t.
class DecoupledSegment {
public:
    DecoupledSegment(const Pose& from, const Pose& to)
        : from_(from)
        , toPosition_(to.position)
        , log_(quatLog(from.orientation.conjugate() * alignedWith(to.orientation, from.orientation)))
    {
    }

    Pose at(double t) const
    {
        return {from_.orientation * quatExp(t * log_), (1.0 - t) * from_.position + t * toPosition_};
    }

private:
    Pose from_;
    Eigen::Vector3d toPosition_;
    Eigen::Vector3d log_;
};

// DecoupledSegment over many pairs, with ScrewBatch's interface.
class DecoupledBatch {
public:
    void assign(std::span<const Pose> from, std::span<const Pose> to)
    {
        segments_.clear();
        for (std::size_t i = 0; i < from.size(); ++i)
            segments_.emplace_back(from[i], to[i]);
    }

    void evaluate(double t, std::span<Pose> out) const
    {
        for (std::size_t i = 0; i < segments_.size(); ++i)
            out[i] = segments_[i].at(t);
    }

private:
    std::vector<DecoupledSegment> segments_;
};

// A scheme's two-pose primitive: the screw, or the decoupled slerp and line; one pair at a time, and
// all the pairs of a level at once.
struct ScrewPrimitive {
    using Batch = ScrewBatch;
    static Pose at(const Pose& from, const Pose& to, double t) { return Screw(from, to).at(t); }
    static void midpoints(std::span<const Pose> from, std::span<const Pose> to, std::span<Pose> out)
    {
        screwMidpoints(from, to, out);
    }
};

struct DecoupledPrimitive {
    using Batch = DecoupledBatch;
    static Pose at(const Pose& from, const Pose& to, double t) { return DecoupledSegment(from, to).at(t); }
    static void midpoints(std::span<const Pose> from, std::span<const Pose> to, std::span<Pose> out)
    {
        for (std::size_t i = 0; i < out.size(); ++i)
            out[i] = at(from[i], to[i], 0.5);
    }
};

// Poses of one level's batches, kept between levels and calls so that they allocate only as they grow.
template <class Batch>
struct BatchBuffers {
    std::vector<Pose> extended;
    Batch edges;      // extended[j] → extended[j + 1]
    Batch tweaks;     // FourPointB's second screws
    std::vector<Pose> first;
    std::vector<Pose> second;
    std::vector<Pose> result;
};

// One Split&Tweak level from `in` to `out`, each rule applied to every edge at once.
template <class Primitive>
void splitAndTweak(const std::vector<Pose>& in, BatchBuffers<typename Primitive::Batch>& buffers,
                   std::vector<Pose>& out, const SubdivisionSettings& settings)
{
    const std::size_t n = in.size();
    const bool cyclic = settings.cyclic;
    if (n == 0 || (!cyclic && n == 1)) {
        out = in;
        return;
    }
    // extended[i + 1] = in[i], with the neighbours the rules reach past either end: the wrapped poses
    // of a cycle, or the ghost poses of the dummy screws of an open sequence.
    std::vector<Pose>& extended = buffers.extended;
    extended.clear();
    if (cyclic) {
        extended.push_back(in[n - 1]);
        extended.insert(extended.end(), in.begin(), in.end());
        extended.push_back(in[0]);
        extended.push_back(in[1 % n]);
    } else {
        extended.push_back(Primitive::at(in[1], in[0], 2.0));
        extended.insert(extended.end(), in.begin(), in.end());
        extended.push_back(Primitive::at(in[n - 2], in[n - 1], 2.0));
    }

    out.resize(cyclic ? 2 * n : 2 * n - 1);
    const std::size_t newPoses = cyclic ? n : n - 1;
    // At in[i] the rules use edge i (in[i−1]→in[i], "previous"), i + 1 ("current") and i + 2
    // ("next"). The rules of the paper are written with s(Lb, u, La) = s(La, 1 − u, Lb), so every
    // screw is an edge's.
    const std::span<const Pose> poses(extended);
    const std::size_t edgeCount = extended.size() - 1;
    buffers.edges.assign(poses.first(edgeCount), poses.subspan(1, edgeCount));
    std::vector<Pose>& first = buffers.first;
    std::vector<Pose>& second = buffers.second;
    std::vector<Pose>& result = buffers.result;
    first.resize(edgeCount);
    second.resize(edgeCount);
    result.resize(newPoses);
    // The edges at t and at u, then the midpoints of edge i's pose at t and edge i + offset's at u.
    const auto midpointsOfEdges = [&](double t, double u, std::size_t offset) {
        buffers.edges.evaluate(t, first);
        buffers.edges.evaluate(u, second);
        Primitive::midpoints(std::span(first).first(newPoses), std::span(second).subspan(offset, newPoses), result);
    };
    const auto setOld = [&](const std::vector<Pose>& values, std::size_t offset) {
        for (std::size_t i = 0; i < newPoses; ++i)
            out[2 * i] = values[i + offset];
    };
    const auto setInserted = [&](const std::vector<Pose>& values, std::size_t offset) {
        for (std::size_t i = 0; i < newPoses; ++i)
            out[2 * i + 1] = values[i + offset];
    };
    switch (settings.scheme) {
    case SubdivisionScheme::FourPoint:
        setOld(in, 0);
        midpointsOfEdges(9.0 / 8.0, -1.0 / 8.0, 2); // s(s(La, 9/8, Lb), 1/2, s(Ld, 9/8, Lc))
        setInserted(result, 0);
        break;
    case SubdivisionScheme::FourPointB:
        setOld(in, 0);
        // s(s(La, 1/2, Ld), 9/8, s(Lb, 1/2, Lc))
        Primitive::midpoints(poses.first(newPoses), poses.subspan(3, newPoses), result);
        buffers.edges.evaluate(0.5, first);
        buffers.tweaks.assign(result, std::span<const Pose>(first).subspan(1, newPoses));
        buffers.tweaks.evaluate(9.0 / 8.0, result);
        setInserted(result, 0);
        break;
    case SubdivisionScheme::BSpline:
        midpointsOfEdges(3.0 / 4.0, 1.0 / 4.0, 1);
        setOld(result, 0);
        buffers.edges.evaluate(0.5, first);
        setInserted(first, 1);
        break;
    case SubdivisionScheme::Jarek:
        midpointsOfEdges(7.0 / 8.0, 1.0 / 8.0, 1);
        setOld(result, 0);
        midpointsOfEdges(17.0 / 16.0, -1.0 / 16.0, 2);
        setInserted(result, 0);
        break;
    }
    if (!cyclic) {
        // The ghosts make every rule map the ends to themselves; keep them bit for bit.
        out.front() = in.front();
        out.back() = in.back();
    }
}

} // namespace

std::optional<SubdivisionScheme> parseSubdivisionScheme(std::string_view name)
{
    return valueNamed(kSubdivisionSchemeNames, name);
}

std::string_view subdivisionSchemeName(SubdivisionScheme scheme)
{
    return nameOf(kSubdivisionSchemeNames, scheme);
}

std::optional<std::size_t> subdividedPoseCount(std::size_t controlPoses, int levels, bool cyclic)
{
    if (levels < 0)
        return std::nullopt;
    if (!cyclic && controlPoses <= 1)
        return controlPoses;
    const std::size_t spans = cyclic ? controlPoses : controlPoses - 1;
    const std::size_t extra = cyclic ? 0 : 1;
    if (spans == 0)
        return 0;
    const int bits = std::numeric_limits<std::size_t>::digits;
    if (levels >= bits || spans > ((std::numeric_limits<std::size_t>::max() - extra) >> levels))
        return std::nullopt;
    return (spans << levels) + extra;
}

struct PolyscrewSubdivider::LevelBuffers {
    BatchBuffers<ScrewBatch> screw;
    BatchBuffers<DecoupledBatch> decoupled;
};

PolyscrewSubdivider::PolyscrewSubdivider() = default;
PolyscrewSubdivider::~PolyscrewSubdivider() = default;
PolyscrewSubdivider::PolyscrewSubdivider(PolyscrewSubdivider&&) noexcept = default;
PolyscrewSubdivider& PolyscrewSubdivider::operator=(PolyscrewSubdivider&&) noexcept = default;

const std::vector<Pose>& PolyscrewSubdivider::subdivide(const std::vector<Pose>& controlPoses,
                                                        const SubdivisionSettings& settings)
{
    if (settings.levels < 0)
        throw std::invalid_argument("subdivision levels must not be negative");
    const std::optional<std::size_t> count = subdividedPoseCount(controlPoses.size(), settings.levels, settings.cyclic);
    if (!count || *count > current_.max_size())
        throw std::invalid_argument("the subdivided motion would have too many poses to hold");
    current_.reserve(*count);
    next_.reserve(*count);
    current_.assign(controlPoses.begin(), controlPoses.end());
    if (!buffers_) // on first use, or after a move
        buffers_ = std::make_unique<LevelBuffers>();
    for (int level = 0; level < settings.levels; ++level) {
        if (settings.decoupled)
            splitAndTweak<DecoupledPrimitive>(current_, buffers_->decoupled, next_, settings);
        else
            splitAndTweak<ScrewPrimitive>(current_, buffers_->screw, next_, settings);
        std::swap(current_, next_);
    }
    return current_;
}

std::vector<Pose> subdividePolyscrew(const std::vector<Pose>& controlPoses, const SubdivisionSettings& settings)
{
    PolyscrewSubdivider subdivider;
    return subdivider.subdivide(controlPoses, settings);
}

} // namespace gyre
