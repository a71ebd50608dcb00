#pragma once
// A scene as the exporters write it (scene_export.h): each object with a name unique in the file, its
// parent resolved to an earlier object, its local pose at the start time, its mesh checked, and its
// motion baked (model::bakeTrack). Both writers, Assimp's and Gyre's FBX writer, start from it.

#include "core/pose.h"
#include "model/scene.h"
#include "model/track_evaluation.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace gyre {

struct BakedObject {
    std::string name;                      // UTF-8, unique within the file, not empty
    std::optional<std::size_t> parent;     // the index of an earlier object; none at the top level
    Pose startPose;                        // relative to the parent, at the scene's start time
    const model::Mesh* mesh = nullptr;     // null when the object has no triangles; indices checked
    std::vector<model::TimedPose> samples; // the baked motion; empty when the object does not move
};

struct BakedScene {
    std::vector<BakedObject> objects;
    model::BakeRange range; // the scene's start and end time and the frame rate of the bake
};

} // namespace gyre
