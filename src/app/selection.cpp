#include "app/selection.h"

#include <algorithm>

namespace gyre::app {

Selection::Selection(model::Document& document, QObject* parent)
    : QObject(parent)
    , document_(document)
{
    connect(&document_, &model::Document::changed, this, [this](model::ObjectId id, model::Changes changes) {
        if (changes.testFlag(model::Change::Scene))
            selectDefault();
        else if (changes.testFlag(model::Change::Removed))
            forgetObject(id);
        else if (changes.testFlag(model::Change::Keyframes))
            dropKeysPastEnd(id);
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

std::vector<model::ObjectId> Selection::objects() const
{
    std::vector<model::ObjectId> ordered;
    for (const model::SceneObject& object : document_.scene().objects)
        if (objects_.contains(object.id))
            ordered.push_back(object.id);
    return ordered;
}

std::vector<std::size_t> Selection::keysOf(model::ObjectId object) const
{
    std::vector<std::size_t> indices;
    for (auto it = keys_.lower_bound({object, 0}); it != keys_.end() && it->first == object; ++it)
        indices.push_back(it->second);
    return indices;
}

void Selection::selectObject(model::ObjectId object)
{
    if (document_.object(object) == nullptr)
        object = model::kNoObject;
    set(object, std::nullopt, object == model::kNoObject ? std::set<model::ObjectId>() : std::set{object}, {});
}

void Selection::selectObjects(const std::vector<model::ObjectId>& objects, model::ObjectId active)
{
    std::set<model::ObjectId> chosen;
    for (model::ObjectId object : objects)
        if (document_.object(object) != nullptr)
            chosen.insert(object);
    if (!chosen.contains(active))
        active = chosen.empty() ? model::kNoObject : *chosen.begin();
    std::set<KeyRef> keys;
    for (const KeyRef& key : keys_)
        if (chosen.contains(key.first))
            keys.insert(key);
    set(active, active == object_ ? key_ : std::nullopt, std::move(chosen), std::move(keys));
}

void Selection::toggleObject(model::ObjectId object)
{
    if (document_.object(object) == nullptr)
        return;
    std::vector<model::ObjectId> objects(objects_.begin(), objects_.end());
    if (objects_.contains(object)) {
        std::erase(objects, object);
        selectObjects(objects, object == object_ ? model::kNoObject : object_);
    } else {
        objects.push_back(object);
        selectObjects(objects, object);
    }
}

void Selection::selectKey(model::ObjectId object, std::size_t key)
{
    const model::SceneObject* selected = document_.object(object);
    if (selected == nullptr) {
        clear();
        return;
    }
    std::set<model::ObjectId> objects = objects_;
    objects.insert(object);
    if (key >= selected->track.keys.size()) {
        set(object, std::nullopt, std::move(objects), {});
        return;
    }
    set(object, key, std::move(objects), {{object, key}});
}

void Selection::toggleKey(model::ObjectId object, std::size_t key)
{
    const model::SceneObject* selected = document_.object(object);
    if (selected == nullptr || key >= selected->track.keys.size())
        return;
    std::set<model::ObjectId> objects = objects_;
    std::set<KeyRef> keys = keys_;
    if (keys.erase({object, key}) > 0) {
        const bool wasActive = object == object_ && key_ == key;
        set(object_, wasActive ? std::nullopt : key_, std::move(objects), std::move(keys));
        return;
    }
    objects.insert(object);
    keys.insert({object, key});
    set(object, key, std::move(objects), std::move(keys));
}

void Selection::selectKeys(const std::set<KeyRef>& keys, bool extend, std::optional<KeyRef> active)
{
    std::set<model::ObjectId> objects = objects_;
    std::set<KeyRef> chosen = extend ? keys_ : std::set<KeyRef>();
    for (const KeyRef& key : keys) {
        const model::SceneObject* object = document_.object(key.first);
        if (object == nullptr || key.second >= object->track.keys.size())
            continue;
        objects.insert(key.first);
        chosen.insert(key);
    }
    if (active && chosen.contains(*active)) {
        set(active->first, active->second, std::move(objects), std::move(chosen));
        return;
    }
    const bool activeKept = key_ && chosen.contains({object_, *key_});
    set(object_, activeKept ? key_ : std::nullopt, std::move(objects), std::move(chosen));
}

void Selection::selectAllKeys()
{
    const model::SceneObject* object = selectedObject();
    if (object == nullptr)
        return;
    std::set<KeyRef> keys;
    for (std::size_t index = 0; index < object->track.keys.size(); ++index)
        keys.insert({object->id, index});
    selectKeys(keys, true);
}

void Selection::deselectKeys()
{
    set(object_, std::nullopt, objects_, {});
}

void Selection::set(model::ObjectId object, std::optional<std::size_t> key, std::set<model::ObjectId> objects,
                    std::set<KeyRef> keys)
{
    if (object == object_ && key == key_ && objects == objects_ && keys == keys_)
        return;
    object_ = object;
    key_ = key;
    objects_ = std::move(objects);
    keys_ = std::move(keys);
    emit changed();
}

void Selection::selectDefault()
{
    const auto& objects = document_.scene().objects;
    const auto keyed = std::find_if(objects.begin(), objects.end(),
                                    [](const model::SceneObject& object) { return !object.track.keys.empty(); });
    selectObject(keyed != objects.end() ? keyed->id : objects.empty() ? model::kNoObject : objects.front().id);
}

void Selection::forgetObject(model::ObjectId object)
{
    if (!objects_.contains(object))
        return;
    std::vector<model::ObjectId> remaining(objects_.begin(), objects_.end());
    std::erase(remaining, object);
    selectObjects(remaining, object == object_ ? model::kNoObject : object_);
}

void Selection::dropKeysPastEnd(model::ObjectId object)
{
    const model::SceneObject* changed = document_.object(object);
    if (changed == nullptr)
        return;
    const std::size_t count = changed->track.keys.size();
    std::set<KeyRef> keys = keys_;
    std::erase_if(keys, [&](const KeyRef& key) { return key.first == object && key.second >= count; });
    const bool activeGone = object == object_ && key_ && *key_ >= count;
    set(object_, activeGone ? std::nullopt : key_, objects_, std::move(keys));
}

} // namespace gyre::app
