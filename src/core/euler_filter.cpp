#include "core/euler_filter.h"

namespace gyre {

std::vector<Eigen::Vector3d> continuousEulerAngles(std::vector<Eigen::Vector3d> angles,
                                                   const EulerConvention& convention,
                                                   const std::optional<Eigen::Vector3d>& before)
{
    std::optional<Eigen::Vector3d> previous = before;
    for (Eigen::Vector3d& triple : angles) {
        if (previous)
            triple = nearestEquivalentAngles(triple, *previous, convention);
        previous = triple;
    }
    return angles;
}

} // namespace gyre
