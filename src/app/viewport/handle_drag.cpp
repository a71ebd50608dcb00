#include "app/viewport/handle_drag.h"

#include "app/viewport/picking.h"
#include "model/commands/set_keyframe_orientation_command.h"
#include "model/commands/set_keyframe_position_command.h"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace gyre::app {

namespace {

double wrapAngle(double angle)
{
    return std::remainder(angle, 2 * std::numbers::pi);
}

} // namespace

bool HandleDrag::start(Handle handle, const HandleFrame& handles, model::ObjectId object, std::size_t key,
                       const QPointF& position, const OrbitCamera& camera)
{
    const model::SceneObject* dragged = document_.object(object);
    if (dragged == nullptr || key >= dragged->track.keys.size())
        return false;
    handle_ = handle;
    object_ = object;
    key_ = key;
    startKeyPose_ = dragged->track.keys[key].pose;
    axisIndex_ = static_cast<int>(handle) % 3;
    worldAxis_ = handles.axes.col(axisIndex_);
    centre_ = handles.centre;
    if (static_cast<int>(handle) < 3) {
        const std::optional<double> along = nearestOnAxis(camera.ray(position.x(), position.y()), centre_, worldAxis_);
        if (!along)
            return false; // the axis points at the eye: moving along it cannot follow the cursor
        startAxisParameter_ = *along;
    } else {
        startScreenAngle_ = screenAngle(position, camera);
    }
    gesture_.emplace(document_);
    return true;
}

double HandleDrag::screenAngle(const QPointF& position, const OrbitCamera& camera) const
{
    const QPointF centre = toScreen(camera, centre_);
    return std::atan2(centre.y() - position.y(), position.x() - centre.x());
}

void HandleDrag::moveTo(const QPointF& position, const OrbitCamera& camera)
{
    if (!gesture_)
        return;
    const model::SceneObject* object = document_.object(object_);
    if (object == nullptr || key_ >= object->track.keys.size()) {
        // Another view removed the key mid-drag: the drag has nothing left to move.
        gesture_.reset();
        return;
    }
    const Eigen::Vector3d localAxis = Eigen::Vector3d::Unit(axisIndex_);
    if (static_cast<int>(handle_) < 3) {
        const std::optional<double> along = nearestOnAxis(camera.ray(position.x(), position.y()), centre_, worldAxis_);
        if (!along)
            return;
        // The world axis is the parent frame's axis, so the same distance moves the local position.
        const Eigen::Vector3d moved = startKeyPose_.position + (*along - startAxisParameter_) * localAxis;
        if (moved.allFinite())
            gesture_->push(new model::SetKeyframePositionCommand(document_, object_, key_, moved));
    } else {
        // Turning the cursor counter-clockwise about the centre turns the pose counter-clockwise as
        // seen from the eye: about +axis if it points at the eye, about −axis otherwise.
        const double facing = worldAxis_.dot(camera.eye() - centre_) >= 0 ? 1.0 : -1.0;
        const double angle = facing * wrapAngle(screenAngle(position, camera) - startScreenAngle_);
        const Eigen::Quaterniond turned = (Eigen::Quaterniond(Eigen::AngleAxisd(angle, localAxis)) * startKeyPose_.orientation).normalized();
        gesture_->push(new model::SetKeyframeOrientationCommand(document_, object_, key_, turned));
    }
}

} // namespace gyre::app
