#include "model/commands/reparent_object_in_place_command.h"

#include "model/commands/command_checks.h"
#include "model/commands/reparent_object_command.h"
#include "model/scene_motion.h"

namespace gyre::model {

namespace {

ParentAndKeysField::Value reparentedInPlace(const Document& document, ObjectId object, ObjectId newParent)
{
    ParentField::Value parentAndOrder = reparented(document, object, newParent); // checks both ids
    const SceneMotion motion(document.scene(), [&document](const SceneObject& each) { return document.motion(each.id); });
    std::vector<Keyframe> keys = document.object(object)->track.keys.vector();
    for (Keyframe& key : keys) {
        const Pose world = motion.parentWorldPose(object, key.time) * key.pose;
        const Pose newFrame = newParent == kNoObject ? Pose() : motion.worldPose(newParent, key.time);
        key.pose = newFrame.inverse() * world;
        key.pose.orientation.normalize();
    }
    return {std::move(parentAndOrder), std::move(keys)};
}

} // namespace

ReparentObjectInPlaceCommand::ReparentObjectInPlaceCommand(Document& document, ObjectId object, ObjectId newParent,
                                                           QUndoCommand* parent)
    : ChangeValueCommand(document, {object, 0}, reparentedInPlace(document, object, newParent),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Reparent Object in Place")), parent)
{
}

} // namespace gyre::model
