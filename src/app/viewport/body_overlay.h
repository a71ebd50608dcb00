#pragma once
// The physics drawn on the selected object, on request (View ▸ Angular Momentum, View ▸ Principal
// Axes): its angular momentum L as an arrow from its centre of mass, and its principal axes of inertia
// through the centre. In free flight L is fixed in space, so the arrow stands still while the body
// tumbles about it. No OpenGL: lines for FrameLines, testable without a context.

#include "app/viewport/frame_lines.h"
#include "core/mass_properties.h"
#include "core/pose.h"

#include <Eigen/Core>

#include <vector>

namespace gyre::app {

// The arrow's length for |L|, as a multiple of the body's radius: 2 for the momentum of one turn a
// second about its largest principal axis (L = 2π·I₃), growing with |L| up to 6. The arrow's
// direction is what the eye reads; its length only says "more" or "less".
double momentumArrowLength(double momentum, const MassProperties& mass, double bodyRadius);

// `worldPose`: the body's frame in the world at the time; `worldVelocity`: its angular velocity in the
// world, rad/s. L = R·I·Rᵀ·ω with R the world orientation. Nothing for |L| of zero.
void appendMomentumArrow(std::vector<LineVertex>& lines, const Pose& worldPose, const MassProperties& mass,
                         const Eigen::Vector3d& worldVelocity, double bodyRadius);

// The three principal axes through the centre of mass, each `bodyRadius` long either side, the
// smallest moment's axis brightest.
void appendPrincipalAxes(std::vector<LineVertex>& lines, const Pose& worldPose, const MassProperties& mass,
                         double bodyRadius);

// The world angular momentum the arrow draws.
Eigen::Vector3d worldAngularMomentum(const Pose& worldPose, const MassProperties& mass,
                                     const Eigen::Vector3d& worldVelocity);

} // namespace gyre::app
