#pragma once
// The viewport's camera: it looks at a target from a distance, along a direction given by yaw about
// the view's up axis and pitch above its ground plane, in perspective or orthographic. The scene is
// Z-up; the view may show it Z-up (Blender) or Y-up (Maya, glTF): then it orbits about y, and yaw and
// pitch are taken in the view's frame, whose x, y, z are the world's x, −z, y. Orbiting
// turns about the target, panning slides the target across the view, zooming changes the distance. No
// OpenGL here: the viewport hands its matrices to the shaders, and tests check the geometry alone.
//
// Screen points are widget pixels, x to the right and y down from the top-left corner; depth is in
// [0, 1] from the near to the far plane, as the OpenGL depth buffer holds it.

#include "app/viewport/ray.h"

#include <Eigen/Core>

namespace gyre::app {

enum class UpAxis { Z, Y };

class OrbitCamera {
public:
    // Keeps the target, the distance, yaw and pitch: the same view direction in the view's frame.
    void setUpAxis(UpAxis up) { up_ = up; }
    UpAxis upAxis() const { return up_; }
    // The rotation from the view's frame (x right of the front view, y away from it, z up) to the world's:
    // the identity for Z-up, a quarter turn about x, −90°, for Y-up.
    Eigen::Matrix3d viewFrame() const;

    void setViewportSize(int width, int height);
    int width() const { return width_; }
    int height() const { return height_; }

    const Eigen::Vector3d& target() const { return target_; }
    double distance() const { return distance_; }
    Eigen::Vector3d eye() const;

    // Turns about the target so that the scene follows the cursor: dx pixels to the right swings the
    // eye to the left (yaw), dy pixels down raises it (pitch), which stays within ±kMaxPitch.
    void orbit(double dxPixels, double dyPixels);
    // Slides the target so that the point under the cursor at the target's depth follows the cursor.
    void pan(double dxPixels, double dyPixels);
    // Moves towards the target by kZoomFactor per wheel step (120 eighths of a degree), away for
    // negative steps.
    void zoom(double steps);
    // Looks at the box's centre from a distance at which the box's bounding sphere fills the view.
    void frame(const Eigen::Vector3d& boxMin, const Eigen::Vector3d& boxMax);
    // Looks from the direction of yaw and pitch (radians, pitch within ±π/2: straight down or up
    // included), keeping the target and the distance.
    void lookFrom(double yaw, double pitch);
    // The unit direction the camera looks in, from the eye towards the target.
    Eigen::Vector3d viewDirection() const;
    // Orthographic: parallel projection, showing at the target's distance what the perspective shows there.
    void setOrthographic(bool orthographic) { orthographic_ = orthographic; }
    bool isOrthographic() const { return orthographic_; }

    Eigen::Matrix4d viewMatrix() const;
    Eigen::Matrix4d projectionMatrix() const;
    Eigen::Matrix4d viewProjectionMatrix() const { return projectionMatrix() * viewMatrix(); }

    // (x, y, depth): the screen point and depth of a world point.
    Eigen::Vector3d project(const Eigen::Vector3d& world) const;
    // The world point at a screen point and depth: project's inverse.
    Eigen::Vector3d unproject(const Eigen::Vector3d& screen) const;
    // The ray through a screen point: from the eye, or in orthographic from the near plane along the view.
    Ray ray(double x, double y) const;
    // World units per pixel at the target's distance: how large to draw things that keep their size
    // on screen.
    double worldPerPixel() const;

    static constexpr double kFieldOfViewY = 0.7853981633974483; // 45°, in radians
    static constexpr double kMaxPitch = 1.5533430342749532;     // 89°: the view never flips over the pole
    static constexpr double kOrbitRadiansPerPixel = 0.01;
    static constexpr double kZoomFactor = 0.85;

private:
    Eigen::Vector3d target_ = Eigen::Vector3d::Zero();
    double distance_ = 12.0;
    double yaw_ = -1.2;  // radians about the view's z, from its x axis towards its y
    double pitch_ = 0.6; // radians above the view's ground plane
    int width_ = 1;
    int height_ = 1;
    bool orthographic_ = false;
    UpAxis up_ = UpAxis::Z;
};

} // namespace gyre::app
