#include "app/sketch/sphere_projection.h"

#include <algorithm>
#include <cmath>

namespace gyre::app {

SphereProjection::SphereProjection()
    : rotation_(defaultRotation())
{
}

void SphereProjection::setViewportSize(int width, int height)
{
    centre_ = QPointF(width / 2.0, height / 2.0);
    radius_ = std::max(1.0, std::min(width, height) / 2.0 / kLabelReach);
}

Eigen::Quaterniond SphereProjection::defaultRotation()
{
    // The rows of the rotation are the view's axes in the world: z points at the eye, y is the world's
    // z made normal to it, x = y × z completes a right-handed frame.
    const Eigen::Vector3d toEye = Eigen::Vector3d(1.0, 1.4, 0.7).normalized();
    const Eigen::Vector3d up = (Eigen::Vector3d::UnitZ() - toEye.z() * toEye).normalized();
    Eigen::Matrix3d worldToView;
    worldToView.row(0) = up.cross(toEye);
    worldToView.row(1) = up;
    worldToView.row(2) = toEye;
    return Eigen::Quaterniond(worldToView).normalized();
}

QPointF SphereProjection::project(const Eigen::Vector3d& world) const
{
    const Eigen::Vector3d view = toView(world);
    return centre_ + radius_ * QPointF(view.x(), -view.y());
}

Eigen::Vector3d SphereProjection::castInView(const QPointF& widgetPoint) const
{
    const QPointF onDisc = (widgetPoint - centre_) / radius_;
    const Eigen::Vector2d planar(onDisc.x(), -onDisc.y());
    const double squaredDistance = planar.squaredNorm();
    if (squaredDistance >= 1.0)
        return {planar.x() / std::sqrt(squaredDistance), planar.y() / std::sqrt(squaredDistance), 0.0};
    return {planar.x(), planar.y(), std::sqrt(1.0 - squaredDistance)};
}

Eigen::Vector3d SphereProjection::cast(const QPointF& widgetPoint) const
{
    return rotation_.conjugate() * castInView(widgetPoint);
}

void SphereProjection::beginTurn(const QPointF& widgetPoint)
{
    turnStartRotation_ = rotation_;
    turnStartPoint_ = castInView(widgetPoint);
}

void SphereProjection::turnTo(const QPointF& widgetPoint)
{
    const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(turnStartPoint_, castInView(widgetPoint));
    setRotation(turn * turnStartRotation_);
}

} // namespace gyre::app
