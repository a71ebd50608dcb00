#include "app/viewport/orbit_camera.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gyre::app {

namespace {

constexpr double kMinDistance = 1e-3;
constexpr double kMaxDistance = 1e6;
// The near and far planes scale with the distance so that depth precision follows the zoom.
constexpr double kNearPerDistance = 0.01;
constexpr double kFarPerDistance = 100.0;

} // namespace

void OrbitCamera::setViewportSize(int width, int height)
{
    width_ = std::max(width, 1);
    height_ = std::max(height, 1);
}

Eigen::Matrix3d OrbitCamera::viewFrame() const
{
    if (up_ == UpAxis::Z)
        return Eigen::Matrix3d::Identity();
    // Columns: the view's x, y, z in the world: x, −z, y.
    Eigen::Matrix3d frame;
    frame << 1, 0, 0, //
        0, 0, 1,      //
        0, -1, 0;
    return frame;
}

Eigen::Vector3d OrbitCamera::eye() const
{
    const Eigen::Vector3d towardsEye(std::cos(pitch_) * std::cos(yaw_), std::cos(pitch_) * std::sin(yaw_),
                                     std::sin(pitch_));
    return target_ + distance_ * (viewFrame() * towardsEye);
}

void OrbitCamera::orbit(double dxPixels, double dyPixels)
{
    yaw_ -= dxPixels * kOrbitRadiansPerPixel;
    pitch_ = std::clamp(pitch_ + dyPixels * kOrbitRadiansPerPixel, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(double dxPixels, double dyPixels)
{
    const Eigen::Matrix4d view = viewMatrix();
    // The rows of the view's rotation are the camera's right, up and backward axes in the world.
    const Eigen::Vector3d right = view.block<1, 3>(0, 0).transpose();
    const Eigen::Vector3d up = view.block<1, 3>(1, 0).transpose();
    target_ += worldPerPixel() * (-dxPixels * right + dyPixels * up);
}

void OrbitCamera::zoom(double steps)
{
    distance_ = std::clamp(distance_ * std::pow(kZoomFactor, steps), kMinDistance, kMaxDistance);
}

void OrbitCamera::frame(const Eigen::Vector3d& boxMin, const Eigen::Vector3d& boxMax)
{
    target_ = 0.5 * (boxMin + boxMax);
    const double radius = std::max(0.5 * (boxMax - boxMin).norm(), kMinDistance);
    // The narrower of the two fields of view decides: tan(fovX/2) = aspect·tan(fovY/2).
    const double halfTan = std::tan(kFieldOfViewY / 2) * std::min(1.0, double(width_) / height_);
    const double halfAngle = std::atan(halfTan);
    distance_ = std::clamp(radius / std::sin(halfAngle), kMinDistance, kMaxDistance);
}

void OrbitCamera::lookFrom(double yaw, double pitch)
{
    yaw_ = yaw;
    pitch_ = std::clamp(pitch, -std::numbers::pi / 2, std::numbers::pi / 2);
}

Eigen::Vector3d OrbitCamera::viewDirection() const
{
    return (target_ - eye()).normalized();
}

Eigen::Matrix4d OrbitCamera::viewMatrix() const
{
    // lookAt: rows right, up, backward; the eye goes to the origin. Right is up × backward normalised,
    // (−sin yaw, cos yaw, 0) in the view's frame, written from the yaw so that it holds looking straight
    // down or up too.
    const Eigen::Vector3d from = eye();
    const Eigen::Vector3d backward = (from - target_).normalized();
    const Eigen::Vector3d right = viewFrame() * Eigen::Vector3d(-std::sin(yaw_), std::cos(yaw_), 0.0);
    const Eigen::Vector3d up = backward.cross(right);
    Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
    view.block<1, 3>(0, 0) = right.transpose();
    view.block<1, 3>(1, 0) = up.transpose();
    view.block<1, 3>(2, 0) = backward.transpose();
    view.block<3, 1>(0, 3) = -view.block<3, 3>(0, 0) * from;
    return view;
}

Eigen::Matrix4d OrbitCamera::projectionMatrix() const
{
    // The OpenGL perspective: f = cot(fovY/2), clip z = ((far+near)·z + 2·far·near)/(near − far).
    const double farPlane = kFarPerDistance * distance_;
    const double f = 1.0 / std::tan(kFieldOfViewY / 2);
    const double aspect = double(width_) / height_;
    Eigen::Matrix4d projection = Eigen::Matrix4d::Zero();
    if (orthographic_) {
        // glOrtho with half-height h = distance·tan(fovY/2), the perspective's at the target, from
        // −far to far: nothing behind the eye is cut off, since zooming moves no plane through the scene.
        const double halfHeight = distance_ / f;
        projection(0, 0) = 1 / (aspect * halfHeight);
        projection(1, 1) = 1 / halfHeight;
        projection(2, 2) = -1 / farPlane;
        projection(3, 3) = 1;
        return projection;
    }
    const double nearPlane = kNearPerDistance * distance_;
    projection(0, 0) = f / aspect;
    projection(1, 1) = f;
    projection(2, 2) = (farPlane + nearPlane) / (nearPlane - farPlane);
    projection(2, 3) = 2 * farPlane * nearPlane / (nearPlane - farPlane);
    projection(3, 2) = -1;
    return projection;
}

Eigen::Vector3d OrbitCamera::project(const Eigen::Vector3d& world) const
{
    const Eigen::Vector4d clip = viewProjectionMatrix() * world.homogeneous();
    const Eigen::Vector3d ndc = clip.head<3>() / clip.w();
    return {(ndc.x() + 1) / 2 * width_, (1 - ndc.y()) / 2 * height_, (ndc.z() + 1) / 2};
}

Eigen::Vector3d OrbitCamera::unproject(const Eigen::Vector3d& screen) const
{
    const Eigen::Vector4d ndc(2 * screen.x() / width_ - 1, 1 - 2 * screen.y() / height_, 2 * screen.z() - 1, 1);
    const Eigen::Vector4d world = viewProjectionMatrix().inverse() * ndc;
    return world.head<3>() / world.w();
}

Ray OrbitCamera::ray(double x, double y) const
{
    if (orthographic_)
        return {unproject({x, y, 0.0}), viewDirection()};
    const Eigen::Vector3d from = eye();
    return {from, (unproject({x, y, 0.5}) - from).normalized()};
}

double OrbitCamera::worldPerPixel() const
{
    return 2 * distance_ * std::tan(kFieldOfViewY / 2) / height_;
}

} // namespace gyre::app
