#pragma once
// The handles on the selected key pose: arrows along and rings about its parent frame's axes, kept
// the same size on screen. Where they are, which one a press grabs, and their lines. No OpenGL, so
// tests can check them on their own.

#include "app/viewport/orbit_camera.h"
#include "app/viewport/frame_lines.h"
#include "core/pose.h"

#include <QPointF>

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace gyre::app {

enum class Handle { MoveX, MoveY, MoveZ, RotateX, RotateY, RotateZ };

// The handles in the world: centre, the parent frame's axes (columns) and the arrows' length.
struct HandleFrame {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
    double length = 1.0;

    // The handles of a key at `keyPosition` in `parentFrame`, as large on screen as kHandlePixels.
    static HandleFrame place(const Pose& parentFrame, const Eigen::Vector3d& keyPosition, const OrbitCamera& camera);

    // The point at `angle` on the ring about axis 0, 1 or 2.
    Eigen::Vector3d ringPoint(int axis, double angle) const;
    // Where to press to grab `handle`.
    QPointF pressPoint(Handle handle, const OrbitCamera& camera) const;
    // The handle a press at `position` grabs: the nearest within kGrabPixels, or nullopt.
    std::optional<Handle> handleAt(const QPointF& position, const OrbitCamera& camera) const;

    // Appends the arrows and rings as line pairs, and the arrows' tips as points.
    void appendLines(std::vector<LineVertex>& lines) const;
    void appendTips(std::vector<LineVertex>& points) const;

    static constexpr double kHandlePixels = 90.0; // arrow length on screen
    static constexpr double kGrabPixels = 8.0;    // how near a handle a press grabs it
};

// A point of the world on screen, in widget pixels.
QPointF toScreen(const OrbitCamera& camera, const Eigen::Vector3d& world);

} // namespace gyre::app
