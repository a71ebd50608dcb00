#pragma once
// The sphere view's geometry, without any drawing: the unit sphere seen orthographically, turned by an
// arcball. View coordinates have x to the right, y up and z towards the viewer; the view rotation
// takes world directions to them. A world direction d is at widget point
//     centre + radius · (v.x, −v.y),   v = rotation · d,
// on the front of the sphere when v.z ≥ 0.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <QPointF>

namespace gyre::app {

class SphereProjection {
public:
    SphereProjection();

    // The sphere fills the widget's shorter side but for room for the axes' labels: its radius is
    // half that side over kLabelReach.
    void setViewportSize(int width, int height);
    QPointF centre() const { return centre_; }
    double radius() const { return radius_; }

    const Eigen::Quaterniond& rotation() const { return rotation_; }
    void setRotation(const Eigen::Quaterniond& rotation) { rotation_ = rotation.normalized(); }
    // z up, seen from a little above the xy plane, between the x and y axes.
    static Eigen::Quaterniond defaultRotation();

    Eigen::Vector3d toView(const Eigen::Vector3d& world) const { return rotation_ * world; }
    QPointF project(const Eigen::Vector3d& world) const;
    bool facesViewer(const Eigen::Vector3d& world) const { return toView(world).z() >= 0.0; }
    // The world direction of the front hemisphere under a widget point; a point off the disc gives
    // the nearest point of the rim.
    Eigen::Vector3d cast(const QPointF& widgetPoint) const;

    // The arcball: the sphere point pressed follows the pointer, turning about the axis normal to
    // where it was and where it is (Shoemake's arcball with the rotation taken once, not doubled).
    void beginTurn(const QPointF& widgetPoint);
    void turnTo(const QPointF& widgetPoint);

    static constexpr double kAxisOvershoot = 1.12;     // the axes stick out of the sphere this far
    static constexpr double kAxisLabelDistance = 1.22; // their labels sit here
    static constexpr double kLabelReach = 1.3;         // the widget's edge, in sphere radii

private:
    Eigen::Vector3d castInView(const QPointF& widgetPoint) const;

    QPointF centre_{0.0, 0.0};
    double radius_ = 1.0;
    Eigen::Quaterniond rotation_;
    Eigen::Quaterniond turnStartRotation_ = Eigen::Quaterniond::Identity();
    Eigen::Vector3d turnStartPoint_ = Eigen::Vector3d::UnitZ(); // in view coordinates
};

} // namespace gyre::app
