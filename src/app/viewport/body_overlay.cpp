#include "app/viewport/body_overlay.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gyre::app {

namespace {

constexpr Rgba kMomentumColor{1.0F, 0.85F, 0.25F, 1.0F};
// The principal axes from the smallest moment's (the long axis of a rod) to the largest's.
constexpr Rgba kPrincipalColors[3] = {{1.0F, 0.55F, 0.85F, 1.0F}, {0.75F, 0.55F, 1.0F, 1.0F}, {0.45F, 0.85F, 1.0F, 1.0F}};
constexpr double kArrowHeadFraction = 0.15; // of the arrow's length
constexpr double kMaximumArrowRadii = 6.0;

} // namespace

double momentumArrowLength(double momentum, const MassProperties& mass, double bodyRadius)
{
    const double oneTurnASecond = 2.0 * std::numbers::pi * principalAxes(mass.inertia).moments[2];
    return bodyRadius * std::min(2.0 * momentum / oneTurnASecond, kMaximumArrowRadii);
}

Eigen::Vector3d worldAngularMomentum(const Pose& worldPose, const MassProperties& mass,
                                     const Eigen::Vector3d& worldVelocity)
{
    return angularMomentum(mass.inertia, worldPose.orientation, worldVelocity);
}

void appendMomentumArrow(std::vector<LineVertex>& lines, const Pose& worldPose, const MassProperties& mass,
                         const Eigen::Vector3d& worldVelocity, double bodyRadius)
{
    const Eigen::Vector3d momentum = worldAngularMomentum(worldPose, mass, worldVelocity);
    const double length = momentumArrowLength(momentum.norm(), mass, bodyRadius);
    if (!(length > 0.0))
        return;
    const Eigen::Vector3d direction = momentum.normalized();
    const Eigen::Vector3d base = worldPose.apply(mass.centre);
    const Eigen::Vector3d tip = base + length * direction;
    lines.push_back(lineVertex(base, kMomentumColor));
    lines.push_back(lineVertex(tip, kMomentumColor));
    // The head: four barbs back from the tip, in two planes through the shaft.
    const Eigen::Vector3d across = direction.unitOrthogonal();
    const Eigen::Vector3d other = direction.cross(across);
    const double head = kArrowHeadFraction * length;
    for (const Eigen::Vector3d& side : {across, Eigen::Vector3d(-across), other, Eigen::Vector3d(-other)}) {
        lines.push_back(lineVertex(tip, kMomentumColor));
        lines.push_back(lineVertex(tip - head * direction + 0.5 * head * side, kMomentumColor));
    }
}

void appendPrincipalAxes(std::vector<LineVertex>& lines, const Pose& worldPose, const MassProperties& mass,
                         double bodyRadius)
{
    const PrincipalAxes principal = principalAxes(mass.inertia);
    const Eigen::Vector3d centre = worldPose.apply(mass.centre);
    for (int axis = 0; axis < 3; ++axis) {
        const Eigen::Vector3d reach = bodyRadius * (worldPose.orientation * principal.axes.col(axis));
        lines.push_back(lineVertex(centre - reach, kPrincipalColors[axis]));
        lines.push_back(lineVertex(centre + reach, kPrincipalColors[axis]));
    }
}

} // namespace gyre::app
