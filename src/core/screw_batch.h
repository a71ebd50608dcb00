#pragma once
// Many screws at once: Screw (screw.h) for a list of pose pairs, computed in blocks of lanes held as
// SIMD registers per component (structure of arrays), each step done on several screws at once: two
// doubles a register at the project's flags (SSE2), four or eight in the AVX2 and AVX-512 versions,
// the widest the processor has chosen at run time. The subdivision evaluates each level's screws this
// way, and with it ScrewBender's trail, which is the subdivided polyscrew.
//
// Each lane does Screw's own operations in Screw's order (Eigen's quaternion product included) and
// no multiply-add is fused, so each result is the one Screw gives, to the bit. The lanes of a block
// run branch-free through every case but the rare ones, which are done after by the single Screw:
// no rotation (sin a ≤ Screw::kNoRotation, where the axis comes from the chord) and t·a beyond the
// reach of the fast sine and cosine.

#include "core/pose.h"

#include <cstddef>
#include <limits>
#include <new>
#include <span>
#include <string>
#include <vector>

namespace gyre {

// Allocates on 64-byte boundaries, so that each pose of a PoseBuffer fills one cache line.
template <class T>
struct CacheLineAllocator {
    using value_type = T;
    static constexpr std::align_val_t kAlignment{64};
    static_assert(alignof(T) <= 64);

    CacheLineAllocator() = default;
    template <class U>
    CacheLineAllocator(const CacheLineAllocator<U>&) noexcept
    {
    }
    T* allocate(std::size_t n)
    {
        if (n > std::numeric_limits<std::size_t>::max() / sizeof(T))
            throw std::bad_array_new_length();
        return static_cast<T*>(::operator new(n * sizeof(T), kAlignment));
    }
    void deallocate(T* pointer, std::size_t) noexcept { ::operator delete(pointer, kAlignment); }
    template <class U>
    bool operator==(const CacheLineAllocator<U>&) const noexcept
    {
        return true;
    }
};

// Poses for the batch to read and write. A std::vector's poses often start 16 bytes past a 32-byte
// boundary, which puts one of each pose's two quads across two cache lines: the batch then takes up to
// 4% longer (README, on BM_ScrewBatch).
using PoseBuffer = std::vector<Pose, CacheLineAllocator<Pose>>;

// out[k·n + i] = Screw(from[i], to[i]).at(times[k]) for the n = from.size() pairs and every k: each
// screw built once and evaluated at every time. `to` holds n poses, out n·times.size().
void screwsAt(std::span<const Pose> from, std::span<const Pose> to, std::span<const double> times,
              std::span<Pose> out);

// out[i] = Screw::midpoint(from[i], to[i]) for every i; the three spans of one length.
void screwMidpoints(std::span<const Pose> from, std::span<const Pose> to, std::span<Pose> out);

namespace screw_batch_detail {

// The versions of the lanes, by the instructions they need: two doubles a register with SSE2, which
// every x86-64 processor has; four with AVX2; eight with AVX-512 (its foundation and vector-length
// extensions). screwsAt and screwMidpoints run the widest this processor has; tests and gyre-bench
// run each one it has.
enum class InstructionSet { Sse2, Avx2, Avx512 };

bool processorHas(InstructionSet set); // false for a value that is not one of the sets
std::string instructionSetName(InstructionSet set);

// screwsAt and screwMidpoints with the lanes of `set`: std::invalid_argument if this processor lacks it
// (or it is not one of the sets).
void screwsAtWith(InstructionSet set, std::span<const Pose> from, std::span<const Pose> to,
                  std::span<const double> times, std::span<Pose> out);
void screwMidpointsWith(InstructionSet set, std::span<const Pose> from, std::span<const Pose> to,
                        std::span<Pose> out);

} // namespace screw_batch_detail

} // namespace gyre
