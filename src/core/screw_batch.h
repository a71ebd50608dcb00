#pragma once
// Many screws at once: Screw (screw.h) for a list of pose pairs, computed in blocks of lanes held as
// SIMD registers per component (structure of arrays), each step done on several screws at once: two
// doubles a register at the project's flags (SSE2), four in the AVX2 version chosen at run time on
// processors that have it. The subdivision evaluates each level's screws this way, and with it
// ScrewBender's trail, which is the subdivided polyscrew.
//
// Each lane does Screw's own operations in Screw's order (Eigen's quaternion product included) and
// no multiply-add is fused, so each result is the one Screw gives, to the bit. The lanes of a block
// run branch-free through every case but the rare ones, which are done after by the single Screw:
// no rotation (sin a ≤ Screw::kNoRotation, where the axis comes from the chord) and t·a beyond the
// reach of the fast sine and cosine.

#include "core/pose.h"

#include <span>

namespace gyre {

// out[k·n + i] = Screw(from[i], to[i]).at(times[k]) for the n = from.size() pairs and every k: each
// screw built once and evaluated at every time. `to` holds n poses, out n·times.size().
void screwsAt(std::span<const Pose> from, std::span<const Pose> to, std::span<const double> times,
              std::span<Pose> out);

// out[i] = Screw::midpoint(from[i], to[i]) for every i; the three spans of one length.
void screwMidpoints(std::span<const Pose> from, std::span<const Pose> to, std::span<Pose> out);

namespace screw_batch_detail {

// The portable lanes, whatever the processor: two doubles a register. Tests call them to check this
// version on a processor where screwsAt and screwMidpoints choose the AVX2 one.
void screwsAtPortable(std::span<const Pose> from, std::span<const Pose> to, std::span<const double> times,
                      std::span<Pose> out);
void screwMidpointsPortable(std::span<const Pose> from, std::span<const Pose> to, std::span<Pose> out);

} // namespace screw_batch_detail

} // namespace gyre
