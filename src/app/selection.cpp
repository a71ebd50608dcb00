#include "app/selection.h"

namespace gyre::app {

Selection::Selection(model::Document& document, QObject* parent)
    : QObject(parent)
    , document_(document)
{
    connect(&document_, &model::Document::changed, this, [this](model::ObjectId id, model::Changes changes) {
        if (changes.testFlag(model::Change::Scene))
            selectDefault();
        else if (id == object_ && changes.testFlag(model::Change::Removed))
            clear();
        else if (id == object_ && changes.testFlag(model::Change::Keyframes))
            dropKeyPastEnd();
    });
    selectDefault();
}

const model::SceneObject* Selection::selectedObject() const
{
    return document_.object(object_);
}

const model::Keyframe* Selection::selectedKey() const
{
    const model::SceneObject* object = selectedObject();
    if (object == nullptr || !key_ || *key_ >= object->track.keys.size())
        return nullptr;
    return &object->track.keys[*key_];
}

void Selection::selectObject(model::ObjectId object)
{
    set(document_.object(object) != nullptr ? object : model::kNoObject, std::nullopt);
}

void Selection::selectKey(model::ObjectId object, std::size_t key)
{
    const model::SceneObject* selected = document_.object(object);
    if (selected == nullptr) {
        clear();
        return;
    }
    set(object, key < selected->track.keys.size() ? std::optional(key) : std::nullopt);
}

void Selection::set(model::ObjectId object, std::optional<std::size_t> key)
{
    if (object == object_ && key == key_)
        return;
    object_ = object;
    key_ = key;
    emit changed();
}

void Selection::selectDefault()
{
    const auto& objects = document_.scene().objects;
    for (const model::SceneObject& object : objects) {
        if (!object.track.keys.empty()) {
            set(object.id, std::nullopt);
            return;
        }
    }
    set(objects.empty() ? model::kNoObject : objects.front().id, std::nullopt);
}

void Selection::dropKeyPastEnd()
{
    if (key_ && selectedKey() == nullptr)
        set(object_, std::nullopt);
}

} // namespace gyre::app
