#include "app/viewport/pose_handles.h"

#include "app/viewport/picking.h"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace gyre::app {

namespace {

constexpr double kRingRadius = 0.7;       // of the arrow length
constexpr int kRingSegments = 64;
constexpr double kArrowPressPoint = 0.95; // where along an arrow pressPoint points

Eigen::Vector2d screenPoint(const OrbitCamera& camera, const Eigen::Vector3d& world)
{
    return camera.project(world).head<2>();
}

double ringAngle(int segment)
{
    return 2 * std::numbers::pi * segment / kRingSegments;
}

} // namespace

QPointF toScreen(const OrbitCamera& camera, const Eigen::Vector3d& world)
{
    const Eigen::Vector3d screen = camera.project(world);
    return {screen.x(), screen.y()};
}

HandleFrame HandleFrame::place(const Pose& parentFrame, const Eigen::Vector3d& keyPosition, const OrbitCamera& camera)
{
    HandleFrame handles;
    handles.centre = parentFrame.apply(keyPosition);
    handles.axes = parentFrame.orientation.toRotationMatrix();
    // The world size of a pixel at the centre's distance d is 2·d·tan(fovY/2) / height.
    const double pixelSize = 2 * (handles.centre - camera.eye()).norm() * std::tan(OrbitCamera::kFieldOfViewY / 2) / camera.height();
    handles.length = kHandlePixels * pixelSize;
    return handles;
}

Eigen::Vector3d HandleFrame::ringPoint(int axis, double angle) const
{
    // The ring about axis k lies in the plane of the next two axes, k+1 and k+2.
    const Eigen::Vector3d u = axes.col((axis + 1) % 3);
    const Eigen::Vector3d v = axes.col((axis + 2) % 3);
    return centre + kRingRadius * length * (std::cos(angle) * u + std::sin(angle) * v);
}

QPointF HandleFrame::pressPoint(Handle handle, const OrbitCamera& camera) const
{
    const int index = static_cast<int>(handle);
    if (index < 3)
        return toScreen(camera, centre + kArrowPressPoint * length * axes.col(index));
    // Halfway between the two arrows the ring passes, away from both.
    return toScreen(camera, ringPoint(index - 3, std::numbers::pi / 4));
}

std::optional<Handle> HandleFrame::handleAt(const QPointF& position, const OrbitCamera& camera) const
{
    const Eigen::Vector2d point(position.x(), position.y());
    std::optional<Handle> nearest;
    double nearestDistance = kGrabPixels;
    const auto consider = [&](Handle handle, double distance) {
        if (distance <= nearestDistance) {
            nearest = handle;
            nearestDistance = distance;
        }
    };
    const Eigen::Vector2d screenCentre = screenPoint(camera, centre);
    for (int axis = 0; axis < 3; ++axis) {
        const Eigen::Vector2d tip = screenPoint(camera, centre + length * axes.col(axis));
        consider(static_cast<Handle>(axis), distanceToSegment(point, screenCentre, tip));
        Eigen::Vector2d previous = screenPoint(camera, ringPoint(axis, 0));
        for (int segment = 1; segment <= kRingSegments; ++segment) {
            const Eigen::Vector2d next = screenPoint(camera, ringPoint(axis, ringAngle(segment)));
            consider(static_cast<Handle>(3 + axis), distanceToSegment(point, previous, next));
            previous = next;
        }
    }
    return nearest;
}

void HandleFrame::appendLines(std::vector<LineVertex>& lines) const
{
    for (int axis = 0; axis < 3; ++axis) {
        lines.push_back(lineVertex(centre, kAxisColors[axis]));
        lines.push_back(lineVertex(centre + length * axes.col(axis), kAxisColors[axis]));
        for (int segment = 0; segment < kRingSegments; ++segment) {
            lines.push_back(lineVertex(ringPoint(axis, ringAngle(segment)), kAxisColors[axis]));
            lines.push_back(lineVertex(ringPoint(axis, ringAngle(segment + 1)), kAxisColors[axis]));
        }
    }
}

void HandleFrame::appendTips(std::vector<LineVertex>& points) const
{
    for (int axis = 0; axis < 3; ++axis)
        points.push_back(lineVertex(centre + length * axes.col(axis), kAxisColors[axis]));
}

} // namespace gyre::app
