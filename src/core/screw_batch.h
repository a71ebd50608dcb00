#pragma once
// Many screws at once: the screw of screw.h for a list of pose pairs, in structure-of-arrays blocks of
// kScrewLanes screws, so that each step runs on several screws per SIMD register. Subdivision
// evaluates each level's screws this way, and with it the trail, which is the subdivided polyscrew.
//
// The lanes run Screw's own operations (screw_detail::terms, the pieces of fast_trig.h), so each
// result is the one Screw gives, to the bit as long as the compiler contracts nothing into fused
// multiply-adds (it does not at the project's flags).
//
// Lanes are Eigen arrays, whose operations Eigen runs a packet at a time: at the project's flags
// (x86-64 without -march: SSE2) two doubles a register, four with AVX. Only the table look-ups of the
// trigonometry, the sign and the float-to-integer conversions run one lane at a time.

#include "core/pose.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace gyre {

// Screws per block: one SIMD register of doubles (2 with SSE2, 4 with AVX), so that a block's
// values stay in registers; 8 lanes (four SSE2 registers a value) spilled to the stack.
inline constexpr std::size_t kScrewLanes = 8;

namespace screw_batch_detail {

using Lanes = Eigen::Array<double, kScrewLanes, 1>;

// kScrewLanes screws' parameters, each coefficient in lanes (quaternions x, y, z, w).
struct Block {
    std::array<Lanes, 4> fromOrientation; // qa
    std::array<Lanes, 4> turnedOrientation; // (0, S)·qa
    std::array<Lanes, 3> fromPosition;
    std::array<Lanes, 3> axis;
    std::array<Lanes, 3> sinSquaredTerm;
    std::array<Lanes, 3> sinCosTerm;
    Lanes halfAngle;
    Lanes slide;
};

} // namespace screw_batch_detail

class ScrewBatch {
public:
    // Screw(from[i], to[i]) for every i; the spans of one length.
    void assign(std::span<const Pose> from, std::span<const Pose> to);
    std::size_t size() const { return size_; }

    // out[i] = Screw(from[i], to[i]).at(t) for every screw; out holds size() poses.
    void evaluate(double t, std::span<Pose> out) const;

private:
    std::vector<screw_batch_detail::Block> blocks_;
    std::size_t size_ = 0;
};

// out[i] = Screw::midpoint(from[i], to[i]) for every i; the three spans of one length.
void screwMidpoints(std::span<const Pose> from, std::span<const Pose> to, std::span<Pose> out);

} // namespace gyre
