#pragma once
// The Euler filter on angle triples as stored (an Euler-mode track's keys, typed or imported), as Blender's: the
// first triple as it is, each later one replaced by its equivalent nearest the filtered one before it
// (nearestEquivalentAngles: each angle ± 2πk, or the convention's second solution), so that the angle curves
// have no 2π jumps or flips and every triple still gives the same rotation. unwrappedEulerAngles
// (euler_angles.h) is this filter on the angles read from a sequence of rotations.

#include "core/euler_angles.h"

#include <optional>
#include <vector>

namespace gyre {

// Where `before` is given, the first triple too is chosen nearest to it.
std::vector<Eigen::Vector3d> continuousEulerAngles(std::vector<Eigen::Vector3d> angles,
                                                   const EulerConvention& convention,
                                                   const std::optional<Eigen::Vector3d>& before = std::nullopt);

} // namespace gyre
