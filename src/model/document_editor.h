#pragma once
// The one way to change a Document. Undo commands use it, and nothing else should: a change made
// here outside a command would not be undoable. Each function makes its change and then emits
// Document::changed with what changed, so views follow without polling.

#include "model/document.h"
#include "model/scene.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace gyre::model {

// An object and the index in scene.objects it has or had.
struct PlacedObject {
    std::size_t index = 0;
    SceneObject object;
};

class DocumentEditor {
public:
    explicit DocumentEditor(Document& document)
        : document_(document)
    {
    }

    const Scene& scene() const { return document_.scene_; }

    // Applies `change` to the scene, then emits changed(object, changes); `object` is kNoObject for
    // Change::SceneSettings.
    void edit(ObjectId object, Changes changes, const std::function<void(Scene&)>& change);

    // Inserts each object at its index, in the order given (so indices must increase), and emits
    // changed(id, Change::Added) for each.
    void insertObjects(const std::vector<PlacedObject>& objects);
    // Removes the objects with these ids and emits changed(id, Change::Removed) for each, children
    // before parents.
    // Returns them with the indices they had, increasing, ready for insertObjects.
    std::vector<PlacedObject> removeObjects(const std::vector<ObjectId>& ids);

    // `count` fresh object ids, first to last. Ids are never handed out twice in a session, so a
    // command that is undone and redone keeps the ids it was given.
    ObjectId reserveObjectIds(std::size_t count);

private:
    Document& document_;
};

} // namespace gyre::model
