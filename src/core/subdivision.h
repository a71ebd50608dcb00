#pragma once
// ScrewBender's Split&Tweak subdivision of polyscrews. Each level doubles the control poses: a pose is
// inserted between each pair of neighbours and the poses are tweaked, every step built from the screw
// primitive s(La, t, Lb) alone, so that a pure translation reproduces the linear masks of the paper
//   B-spline  q₂ᵢ = (pᵢ₋₁ + 6pᵢ + pᵢ₊₁)/8,          q₂ᵢ₊₁ = (pᵢ + pᵢ₊₁)/2
//   4-point   q₂ᵢ = pᵢ,                           q₂ᵢ₊₁ = (−pᵢ₋₁ + 9pᵢ + 9pᵢ₊₁ − pᵢ₊₂)/16
//   Jarek     q₂ᵢ = (2pᵢ₋₁ + 28pᵢ + 2pᵢ₊₁)/32,      q₂ᵢ₊₁ = (−pᵢ₋₁ + 17pᵢ + 17pᵢ₊₁ − pᵢ₊₂)/32
// and poses sampled along one screw stay on it.
//
// Open sequences are extended at each level by a dummy screw at each end: a ghost pose s(L₁, 2, L₀)
// before the first pose and s(Lₙ₋₂, 2, Lₙ₋₁) after the last, continuing the end screws. With these
// ghosts every scheme maps the end poses to themselves (for a translation (2p₀ − p₁ + 6p₀ + p₁)/8 = p₀),
// so the endpoints are kept.

#include "core/name_table.h"
#include "core/pose.h"
#include "core/screw.h"
#include "core/screw_batch.h"

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace gyre {

enum class SubdivisionScheme {
    FourPoint,  // formulation A: s(s(La, 9/8, Lb), 1/2, s(Ld, 9/8, Lc)) between Lb and Lc
    FourPointB, // formulation B: s(s(La, 1/2, Ld), 9/8, s(Lb, 1/2, Lc))
    BSpline,
    Jarek,
};

inline constexpr NameTable<SubdivisionScheme, 4> kSubdivisionSchemeNames{{
    {SubdivisionScheme::FourPoint, "four-point"},
    {SubdivisionScheme::FourPointB, "four-point-b"},
    {SubdivisionScheme::BSpline, "bspline"},
    {SubdivisionScheme::Jarek, "jarek"},
}};

std::optional<SubdivisionScheme> parseSubdivisionScheme(std::string_view name);
std::string_view subdivisionSchemeName(SubdivisionScheme scheme);

struct SubdivisionSettings {
    SubdivisionScheme scheme = SubdivisionScheme::FourPoint;
    int levels = 4;
    bool cyclic = true;
    // The decoupled alternative the paper compares against: positions by the linear scheme,
    // orientations by the same Split&Tweak on rotations alone (slerp in place of the screw).
    bool decoupled = false;
    bool operator==(const SubdivisionSettings&) const = default;
};

// How many poses `levels` subdivisions of `controlPoses` poses give: n·2^L for a cycle,
// (n − 1)·2^L + 1 for an open sequence. nullopt if that does not fit in std::size_t.
std::optional<std::size_t> subdividedPoseCount(std::size_t controlPoses, int levels, bool cyclic);

// The poses a level computes on its way, kept by PolyscrewSubdivider so that they allocate only as
// they grow; in PoseBuffers, which the batch screw reads and writes fastest.
struct SubdivisionScratch {
    PoseBuffer extended;  // the level's poses with the neighbours the rules reach past either end
    PoseBuffer edgePoses; // every edge's screw at the scheme's times
    PoseBuffer outer;     // FourPointB's midpoints of the outer poses
    PoseBuffer tweaked;   // one rule's new poses
};

// Subdivides repeatedly into buffers it keeps, so that re-subdividing while the artist drags a pose
// allocates nothing once the buffers have grown. Output pose i·2^L is the image of control pose i.
class PolyscrewSubdivider {
public:
    // Throws std::invalid_argument for negative levels or a result too large to hold.
    const std::vector<Pose>& subdivide(const std::vector<Pose>& controlPoses, const SubdivisionSettings& settings);

private:
    std::vector<Pose> current_;
    std::vector<Pose> next_;
    SubdivisionScratch scratch_;
};

// One-shot convenience over PolyscrewSubdivider.
std::vector<Pose> subdividePolyscrew(const std::vector<Pose>& controlPoses, const SubdivisionSettings& settings);

} // namespace gyre
