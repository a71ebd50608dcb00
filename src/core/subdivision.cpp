#include "core/subdivision.h"

#include "core/quaternion_math.h"
#include "core/screw.h"
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

    static Pose midpoint(const Pose& from, const Pose& to) { return DecoupledSegment(from, to).at(0.5); }

private:
    Pose from_;
    Eigen::Vector3d toPosition_;
    Eigen::Vector3d log_;
};

// A scheme's two-pose primitive on many pairs at once, with screw_batch.h's interface, and on one pair:
// the screw, or the decoupled slerp and line.
struct ScrewPrimitive {
    // One pair alone: the batch would fill a whole block of lanes for it.
    static Pose single(const Pose& from, double t, const Pose& to) { return screwInterpolate(from, t, to); }
    static void at(std::span<const Pose> from, std::span<const Pose> to, std::span<const double> times,
                   std::span<Pose> out)
    {
        screwsAt(from, to, times, out);
    }
    static void midpoints(std::span<const Pose> from, std::span<const Pose> to, std::span<Pose> out)
    {
        screwMidpoints(from, to, out);
    }
};

struct DecoupledPrimitive {
    static Pose single(const Pose& from, double t, const Pose& to) { return DecoupledSegment(from, to).at(t); }
    static void at(std::span<const Pose> from, std::span<const Pose> to, std::span<const double> times,
                   std::span<Pose> out)
    {
        for (std::size_t i = 0; i < from.size(); ++i) {
            const DecoupledSegment segment(from[i], to[i]);
            for (std::size_t k = 0; k < times.size(); ++k)
                out[k * from.size() + i] = segment.at(times[k]);
        }
    }
    static void midpoints(std::span<const Pose> from, std::span<const Pose> to, std::span<Pose> out)
    {
        for (std::size_t i = 0; i < from.size(); ++i)
            out[i] = DecoupledSegment::midpoint(from[i], to[i]);
    }
};

// out[2i + parity] = values[i] for every value.
void interleave(std::span<const Pose> values, std::size_t parity, std::vector<Pose>& out)
{
    for (std::size_t i = 0; i < values.size(); ++i)
        out[2 * i + parity] = values[i];
}

// The times at which each scheme evaluates the edges' screws.
constexpr std::array kFourPointTimes{9.0 / 8.0, -1.0 / 8.0};
constexpr std::array kHalfTime{0.5};
constexpr std::array kFourPointBTweak{9.0 / 8.0};
constexpr std::array kBSplineTimes{3.0 / 4.0, 1.0 / 4.0, 0.5};
constexpr std::array kJarekTimes{7.0 / 8.0, 1.0 / 8.0, 17.0 / 16.0, -1.0 / 16.0};

// One Split&Tweak level from `in` to `out`, each rule applied to every edge at once; `scratch` holds
// the level's intermediate poses.
template <class Primitive>
void splitAndTweak(const std::vector<Pose>& in, SubdivisionScratch& scratch, std::vector<Pose>& out,
                   const SubdivisionSettings& settings)
{
    const std::size_t n = in.size();
    const bool cyclic = settings.cyclic;
    if (n == 0 || (!cyclic && n == 1)) {
        out = in;
        return;
    }
    // extended[i + 1] = in[i], with the neighbours the rules reach past either end: the wrapped poses
    // of a cycle, or the ghost poses of the dummy screws of an open sequence.
    PoseBuffer& extended = scratch.extended;
    extended.clear();
    if (cyclic) {
        extended.push_back(in[n - 1]);
        extended.insert(extended.end(), in.begin(), in.end());
        extended.push_back(in[0]);
        extended.push_back(in[1 % n]);
    } else {
        extended.push_back(Primitive::single(in[1], 2.0, in[0]));
        extended.insert(extended.end(), in.begin(), in.end());
        extended.push_back(Primitive::single(in[n - 2], 2.0, in[n - 1]));
    }

    out.resize(cyclic ? 2 * n : 2 * n - 1);
    const std::size_t newPoses = cyclic ? n : n - 1;
    // Edge j joins extended[j] to extended[j + 1]. At in[i] the rules use edge i (in[i−1]→in[i]),
    // i + 1 (in[i]→in[i+1]) and i + 2 (in[i+1]→in[i+2]); the rules of the paper are written with
    // s(Lb, u, La) = s(La, 1 − u, Lb), so every screw is an edge's.
    const std::span<const Pose> poses(extended);
    const std::size_t edges = newPoses + 2;
    // Every edge's screw at each of `times`; row(k, first) is then edge first + i at times[k], for each i.
    const auto evaluateEdges = [&](std::span<const double> times) {
        scratch.edgePoses.resize(edges * times.size());
        Primitive::at(poses.first(edges), poses.subspan(1, edges), times, scratch.edgePoses);
    };
    const auto row = [&](std::size_t k, std::size_t first) {
        return std::span<const Pose>(scratch.edgePoses).subspan(k * edges + first, newPoses);
    };
    PoseBuffer& tweaked = scratch.tweaked;
    tweaked.resize(newPoses);
    const auto midpoints = [&](std::span<const Pose> from, std::span<const Pose> to, std::size_t parity) {
        Primitive::midpoints(from, to, tweaked);
        interleave(tweaked, parity, out);
    };
    switch (settings.scheme) {
    case SubdivisionScheme::FourPoint: // s(s(La, 9/8, Lb), 1/2, s(Ld, 9/8, Lc))
        interleave(std::span(in).first(newPoses), 0, out);
        evaluateEdges(kFourPointTimes);
        midpoints(row(0, 0), row(1, 2), 1);
        break;
    case SubdivisionScheme::FourPointB: { // s(s(La, 1/2, Ld), 9/8, s(Lb, 1/2, Lc))
        interleave(std::span(in).first(newPoses), 0, out);
        PoseBuffer& outer = scratch.outer;
        outer.resize(newPoses);
        Primitive::midpoints(poses.first(newPoses), poses.subspan(3, newPoses), outer);
        evaluateEdges(kHalfTime);
        Primitive::at(outer, row(0, 1), kFourPointBTweak, tweaked);
        interleave(tweaked, 1, out);
        break;
    }
    case SubdivisionScheme::BSpline: // s(s(La, 3/4, Lb), 1/2, s(Lb, 1/4, Lc)) and s(Lb, 1/2, Lc)
        evaluateEdges(kBSplineTimes);
        midpoints(row(0, 0), row(1, 1), 0);
        interleave(row(2, 1), 1, out);
        break;
    case SubdivisionScheme::Jarek:
        evaluateEdges(kJarekTimes);
        midpoints(row(0, 0), row(1, 1), 0);
        midpoints(row(2, 0), row(3, 2), 1);
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
    for (int level = 0; level < settings.levels; ++level) {
        if (settings.decoupled)
            splitAndTweak<DecoupledPrimitive>(current_, scratch_, next_, settings);
        else
            splitAndTweak<ScrewPrimitive>(current_, scratch_, next_, settings);
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
