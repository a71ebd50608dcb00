#pragma once
// What the artist has selected: one object and, optionally, one of its keyframes. Every view shows the
// same selection and changes it through here. Selecting is looking, not editing, so it is not undoable;
// it follows the document so that it never names an object or a key that no longer exists.

#include "model/document.h"

#include <QObject>

#include <cstddef>
#include <optional>

namespace gyre::app {

class Selection : public QObject {
    Q_OBJECT

public:
    explicit Selection(model::Document& document, QObject* parent = nullptr);

    model::ObjectId object() const { return object_; }
    std::optional<std::size_t> key() const { return key_; }
    // The selected object, or null.
    const model::SceneObject* selectedObject() const;
    // The selected keyframe, or null.
    const model::Keyframe* selectedKey() const;

    // Selects the object (kNoObject: nothing) and no key.
    void selectObject(model::ObjectId object);
    // Selects the object and its keyframe at index `key`; an index past its keys selects no key.
    void selectKey(model::ObjectId object, std::size_t key);
    void clear() { selectObject(model::kNoObject); }

signals:
    void changed();

private:
    void set(model::ObjectId object, std::optional<std::size_t> key);
    // After a new scene: the first object that has keyframes, else the first object.
    void selectDefault();
    // After the selected object's keys changed.
    void dropKeyPastEnd();

    model::Document& document_;
    model::ObjectId object_ = model::kNoObject;
    std::optional<std::size_t> key_;
};

} // namespace gyre::app
