#pragma once
// The one way to change a Document. Undo commands use it, and nothing else should: a change made
// here outside a command would not be undoable. Each function makes its change and then emits the
// signals that say what changed, so views follow without polling.

#include "model/document.h"
#include "model/scene.h"

#include <QFlags>

#include <cstddef>
#include <functional>
#include <vector>

namespace gyre::model {

// What a change touches; each part has its signal on Document.
enum class Change {
    Object = 1 << 0,        // name, parent (and with it the order of objects), mesh: objectChanged
    Keyframes = 1 << 1,     // keyframesChanged
    TrackSettings = 1 << 2, // interpolation, subdivision: trackSettingsChanged
    Sketch = 1 << 3,        // sketchChanged
    SceneSettings = 1 << 4, // fps, time range: sceneSettingsChanged
};
Q_DECLARE_FLAGS(Changes, Change)

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

    // Applies `change` to the scene, then emits the signals of `changes`; the object signals carry
    // `object`.
    void edit(ObjectId object, Changes changes, const std::function<void(Scene&)>& change);

    // Inserts each object at its index, in the order given (so indices must increase), and emits
    // objectAdded for each.
    void insertObjects(const std::vector<PlacedObject>& objects);
    // Removes the objects with these ids and emits objectRemoved for each, children before parents.
    // Returns them with the indices they had, increasing, ready for insertObjects.
    std::vector<PlacedObject> removeObjects(const std::vector<ObjectId>& ids);

    // `count` fresh object ids, first to last. Ids are never handed out twice in a session, so a
    // command that is undone and redone keeps the ids it was given.
    ObjectId reserveObjectIds(std::size_t count);

private:
    Document& document_;
};

} // namespace gyre::model

Q_DECLARE_OPERATORS_FOR_FLAGS(gyre::model::Changes)
