#pragma once
// A drag of a handle: it moves the key along or turns it about an axis of its parent frame as the
// cursor goes, pushing one command per move within one gesture of the document, so the whole drag is one undo step.

#include "app/viewport/orbit_camera.h"
#include "app/viewport/pose_handles.h"
#include "model/document.h"
#include "model/gesture.h"

#include <QPointF>

#include <cstddef>
#include <optional>

namespace gyre::app {

class HandleDrag {
public:
    explicit HandleDrag(model::Document& document) : document_(document) {}

    // Grabs `handle` of the key at index `key` of `object`, whose handles are `handles`, at the screen
    // point `position`. False when the drag cannot follow the cursor (an arrow pointing at the eye).
    bool start(Handle handle, const HandleFrame& handles, model::ObjectId object, std::size_t key,
               const QPointF& position, const OrbitCamera& camera);
    bool isActive() const { return gesture_.has_value(); }
    // Moves or turns the key to follow the cursor at `position`.
    void moveTo(const QPointF& position, const OrbitCamera& camera);
    // Ends the drag and its undo step.
    void finish() { gesture_.reset(); }

private:
    // Counter-clockwise on screen from the right, about the handle's centre; screen y points down.
    double screenAngle(const QPointF& position, const OrbitCamera& camera) const;

    model::Document& document_;
    std::optional<model::Gesture> gesture_;
    Handle handle_ = Handle::MoveX;
    model::ObjectId object_ = model::kNoObject;
    std::size_t key_ = 0;
    Pose startKeyPose_;                                     // the key's local pose when the drag began
    int axisIndex_ = 0;                                     // 0, 1, 2: x, y, z of the parent frame
    Eigen::Vector3d worldAxis_ = Eigen::Vector3d::UnitX(); // the handle's axis in the world
    Eigen::Vector3d centre_ = Eigen::Vector3d::Zero();     // the key's world position when the drag began
    double startAxisParameter_ = 0.0;
    double startScreenAngle_ = 0.0;
};

} // namespace gyre::app
