#pragma once
// Which objects of a scene are joints: the one rule that the viewport (its bones, app/viewport/skeleton.h)
// and the scene import (which makes every other object without a mesh an Empty) share. A joint is an
// object without a mesh of its own, not an Empty, that is a joint of a skinned mesh (Skin::joints), or
// whose parent or one of whose children is such an object too (a BVH's joints, an FBX skeleton's nodes).

#include "model/scene.h"

#include <cstddef>
#include <vector>

namespace gyre::model {

// The index of each object's parent in scene.objects, or the object's own index for a top-level one
// (parents come before their children).
void findParentIndices(const Scene& scene, std::vector<std::size_t>& parents);

// Whether each of scene.objects is a joint, `parents` being findParentIndices's.
void findJoints(const Scene& scene, const std::vector<std::size_t>& parents, std::vector<bool>& joints);
std::vector<bool> findJoints(const Scene& scene);

} // namespace gyre::model
