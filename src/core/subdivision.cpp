#include "core/subdivision.h"

#include "core/quaternion_math.h"

#include <array>
#include <limits>
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

// One Split&Tweak level from `in` to `out`; `extended` is scratch space.
template <class Segment>
void splitAndTweak(const std::vector<Pose>& in, std::vector<Pose>& extended, std::vector<Pose>& out,
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
    extended.clear();
    if (cyclic) {
        extended.push_back(in[n - 1]);
        extended.insert(extended.end(), in.begin(), in.end());
        extended.push_back(in[0]);
        extended.push_back(in[1 % n]);
    } else {
        extended.push_back(Segment(in[1], in[0]).at(2.0));
        extended.insert(extended.end(), in.begin(), in.end());
        extended.push_back(Segment(in[n - 2], in[n - 1]).at(2.0));
    }

    out.resize(cyclic ? 2 * n : 2 * n - 1);
    const std::size_t newPoses = cyclic ? n : n - 1;
    // At in[i]: previous joins in[i−1]→in[i], current in[i]→in[i+1], next in[i+1]→in[i+2]. The rules
    // of the paper are written with s(Lb, u, La) = s(La, 1 − u, Lb), so every screw is an edge's.
    Segment previous(extended[0], extended[1]);
    Segment current(extended[1], extended[2]);
    for (std::size_t i = 0; i < newPoses; ++i) {
        const Segment next(extended[i + 2], extended[i + 3]);
        Pose& old = out[2 * i];
        Pose& inserted = out[2 * i + 1];
        switch (settings.scheme) {
        case SubdivisionScheme::FourPoint:
            old = in[i];
            inserted = Segment::midpoint(previous.at(9.0 / 8.0), next.at(-1.0 / 8.0));
            break;
        case SubdivisionScheme::FourPointB:
            old = in[i];
            inserted = Segment(Segment::midpoint(extended[i], extended[i + 3]), current.at(0.5)).at(9.0 / 8.0);
            break;
        case SubdivisionScheme::BSpline:
            old = Segment::midpoint(previous.at(3.0 / 4.0), current.at(1.0 / 4.0));
            inserted = current.at(0.5);
            break;
        case SubdivisionScheme::Jarek:
            old = Segment::midpoint(previous.at(7.0 / 8.0), current.at(1.0 / 8.0));
            inserted = Segment::midpoint(previous.at(17.0 / 16.0), next.at(-1.0 / 16.0));
            break;
        }
        previous = current;
        current = next;
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
            splitAndTweak<DecoupledSegment>(current_, extended_, next_, settings);
        else
            splitAndTweak<Screw>(current_, extended_, next_, settings);
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
