#include "model/document_editor.h"

#include "model/rotation_mode.h"

#include <algorithm>

namespace gyre::model {

void DocumentEditor::edit(ObjectId object, Changes changes, const std::function<void(Scene&)>& change)
{
    change(document_.scene_);
    // The one place where the keys' angles are made to follow their orientations (rotation_mode.h). Undo puts back
    // values that hold it already, so there this changes nothing.
    if (changes & (Changes(Change::Keyframes) | Change::TrackSettings))
        for (SceneObject& edited : document_.scene_.objects)
            if (object == kNoObject || edited.id == object)
                keepRotationMode(edited.track);
    document_.notifyChanged(object, changes);
}

void DocumentEditor::insertObjects(const std::vector<PlacedObject>& objects)
{
    std::vector<SceneObject>& sceneObjects = document_.scene_.objects;
    for (const PlacedObject& placed : objects) {
        const auto inserted = sceneObjects.insert(sceneObjects.begin() + static_cast<std::ptrdiff_t>(placed.index), placed.object);
        keepRotationMode(inserted->track);
    }
    for (const PlacedObject& placed : objects)
        document_.notifyChanged(placed.object.id, Change::Added);
}

std::vector<PlacedObject> DocumentEditor::removeObjects(const std::vector<ObjectId>& ids)
{
    std::vector<SceneObject>& sceneObjects = document_.scene_.objects;
    std::vector<PlacedObject> removed;
    std::vector<SceneObject> kept;
    for (std::size_t index = 0; index < sceneObjects.size(); ++index) {
        SceneObject& object = sceneObjects[index];
        if (std::find(ids.begin(), ids.end(), object.id) != ids.end())
            removed.push_back({index, std::move(object)});
        else
            kept.push_back(std::move(object));
    }
    sceneObjects = std::move(kept);
    for (auto placed = removed.rbegin(); placed != removed.rend(); ++placed)
        document_.notifyChanged(placed->object.id, Change::Removed);
    return removed;
}

ObjectId DocumentEditor::reserveObjectIds(std::size_t count)
{
    const ObjectId first = document_.scene_.nextObjectId;
    document_.scene_.nextObjectId += count;
    return first;
}

} // namespace gyre::model
