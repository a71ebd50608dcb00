#include "model/commands/import_objects_command.h"

#include "model/commands/command_checks.h"
#include "model/skinning.h"
#include "model/value_checks.h"

#include <map>
#include <memory>
#include <stdexcept>
#include <string>

namespace gyre::model {

namespace {

[[noreturn]] void refuseObject(std::size_t index, const std::string& message)
{
    throw std::invalid_argument("imported object " + std::to_string(index) + ": " + message);
}

// The batch with scene ids, placed after the scene's objects. Ids are reserved only once the whole
// batch has passed its checks.
std::vector<PlacedObject> placeBatch(Document& document, std::vector<SceneObject> objects)
{
    std::map<ObjectId, std::size_t> batchIndex;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        SceneObject& object = objects[i];
        if (object.parent != kNoObject && !batchIndex.contains(object.parent))
            refuseObject(i, "its parent " + std::to_string(object.parent) + " does not come before it in the batch");
        if (object.id == kNoObject || !batchIndex.emplace(object.id, i).second)
            refuseObject(i, "its id " + std::to_string(object.id) + " is 0 or not unique in the batch");
        try {
            checkTrack(object.track);
            if (object.mesh)
                checkMesh(*object.mesh);
        } catch (const std::invalid_argument& problem) {
            refuseObject(i, problem.what());
        }
    }
    // A skin's joints are objects of the batch, anywhere in it; they get the ids their objects get.
    const auto skinJointsPlaced = [&batchIndex](const Mesh& mesh, ObjectId firstId) {
        return skinWithJoints(mesh.skin, [&](ObjectId joint) {
            const auto found = batchIndex.find(joint);
            return found == batchIndex.end() ? kNoObject : firstId + found->second;
        });
    };
    for (std::size_t i = 0; i < objects.size(); ++i)
        if (objects[i].mesh && !objects[i].mesh->skin.empty()) {
            try {
                skinJointsPlaced(*objects[i].mesh, 1);
            } catch (const std::invalid_argument& problem) {
                refuseObject(i, problem.what());
            }
        }
    const ObjectId firstId = DocumentEditor(document).reserveObjectIds(objects.size());
    const std::size_t firstIndex = document.scene().objects.size();
    std::map<const Mesh*, std::shared_ptr<const Mesh>> placedMeshes; // a shared skinned mesh stays shared
    std::vector<PlacedObject> placed;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        SceneObject& object = objects[i];
        object.id = firstId + i;
        if (object.parent != kNoObject)
            object.parent = firstId + batchIndex.at(object.parent);
        if (object.mesh && !object.mesh->skin.empty()) {
            std::shared_ptr<const Mesh>& mesh = placedMeshes[object.mesh.get()];
            if (!mesh) {
                auto copy = std::make_shared<Mesh>(*object.mesh);
                copy->skin = skinJointsPlaced(*object.mesh, firstId);
                mesh = std::move(copy);
            }
            object.mesh = mesh;
        }
        placed.push_back({firstIndex + i, std::move(object)});
    }
    return placed;
}

std::vector<ObjectId> idsOf(const std::vector<PlacedObject>& placed)
{
    std::vector<ObjectId> ids;
    for (const PlacedObject& object : placed)
        ids.push_back(object.object.id);
    return ids;
}

} // namespace

ImportObjectsCommand::ImportObjectsCommand(Document& document, std::vector<SceneObject> objects, QUndoCommand* parent)
    : ImportObjectsCommand(document, placeBatch(document, std::move(objects)), parent)
{
}

ImportObjectsCommand::ImportObjectsCommand(Document& document, std::vector<PlacedObject> placed, QUndoCommand* parent)
    : ObjectBatchCommand(document, placed, Direction::Insert,
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Import Objects")), parent)
    , ids_(idsOf(placed))
{
}

} // namespace gyre::model
