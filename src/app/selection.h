#pragma once
// What the artist has selected: a set of objects, one of them active, and a set of keyframes of those
// objects, one of them (the active object's) active. The inspector, the sketch panels and the
// graph editor show the active object and key; the timeline's rows, key editing (keyframe_actions.h)
// and the clipboard work on all of them. Every view shows the same selection and changes it through
// here. Selecting is looking, not editing, so it is not undoable; it follows the document so that it
// never names an object or a key that no longer exists.

#include "model/document.h"

#include <QObject>

#include <cstddef>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace gyre::app {

// A key of an object, by its index in the object's keys.
using KeyRef = std::pair<model::ObjectId, std::size_t>;

class Selection : public QObject {
    Q_OBJECT

public:
    explicit Selection(model::Document& document, QObject* parent = nullptr);

    // The active object and its active key.
    model::ObjectId object() const { return object_; }
    std::optional<std::size_t> key() const { return key_; }
    // The active object, or null.
    const model::SceneObject* selectedObject() const;
    // The active keyframe, or null.
    const model::Keyframe* selectedKey() const;

    // Every selected object, in the scene's order; the active one among them.
    std::vector<model::ObjectId> objects() const;
    bool isObjectSelected(model::ObjectId object) const { return objects_.contains(object); }
    // Every selected key, ordered by object id, then index.
    const std::set<KeyRef>& keys() const { return keys_; }
    bool isKeySelected(model::ObjectId object, std::size_t key) const { return keys_.contains({object, key}); }
    // The selected keys' indices of one object, increasing.
    std::vector<std::size_t> keysOf(model::ObjectId object) const;

    // Selects the object alone (kNoObject: nothing) and no key.
    void selectObject(model::ObjectId object);
    // Selects `objects` (unknown ids are left out), `active` among them (else the first) active;
    // keys of objects no longer selected are dropped.
    void selectObjects(const std::vector<model::ObjectId>& objects, model::ObjectId active);
    // Adds the object to the selected objects as the active one, or takes it out if it is selected.
    void toggleObject(model::ObjectId object);
    // Selects this key alone and makes it and its object active; the other selected objects stay
    // selected. An index past the object's keys selects no key.
    void selectKey(model::ObjectId object, std::size_t key);
    // Adds the key to the selected keys as the active one (its object selected and active), or takes
    // it out if it is selected.
    void toggleKey(model::ObjectId object, std::size_t key);
    // Selects `keys` (replacing the selected keys, or added to them if `extend`), their objects
    // selected too; `active` becomes the active key if it is among them, else the active key stays
    // if it is still selected.
    void selectKeys(const std::set<KeyRef>& keys, bool extend, std::optional<KeyRef> active = std::nullopt);
    // Every key of the active object, or none at all.
    void selectAllKeys();
    void deselectKeys();
    void clear() { selectObject(model::kNoObject); }

signals:
    void changed();

private:
    void set(model::ObjectId object, std::optional<std::size_t> key, std::set<model::ObjectId> objects,
             std::set<KeyRef> keys);
    // After a new scene: the first object that has keyframes, else the first object.
    void selectDefault();
    // After an object was removed: forget it and its keys.
    void forgetObject(model::ObjectId object);
    // After an object's keys changed: drop indices past its last key.
    void dropKeysPastEnd(model::ObjectId object);

    model::Document& document_;
    model::ObjectId object_ = model::kNoObject;
    std::optional<std::size_t> key_;
    std::set<model::ObjectId> objects_; // holds object_ unless that is kNoObject
    std::set<KeyRef> keys_;             // holds {object_, *key_} when there is an active key
};

} // namespace gyre::app
