#pragma once
// Questions about a scene's objects and their hierarchy. Scenes hold tens to thousands of objects,
// so a linear search is fast enough and keeps Scene a plain value.

#include "model/scene.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace gyre::model {

// The object with this id, or null.
const SceneObject* findObject(const Scene& scene, ObjectId id);
SceneObject* findObject(Scene& scene, ObjectId id);

// Where the object with this id stands in scene.objects, if it is there.
std::optional<std::size_t> objectIndex(const Scene& scene, ObjectId id);

// Whether `ancestor` is `object`'s parent, its parent's parent, and so on (an object is not its own
// ancestor). Follows at most scene.objects.size() links, so a broken hierarchy cannot loop forever.
bool isAncestor(const Scene& scene, ObjectId ancestor, ObjectId object);

// The object and all its descendants, in scene order (so parents before their children).
std::vector<ObjectId> subtreeOf(const Scene& scene, ObjectId root);

// The ids of scene.objects, in order.
std::vector<ObjectId> objectOrder(const Scene& scene);

// The keyframe count over all objects.
std::size_t keyframeCount(const Scene& scene);

} // namespace gyre::model
