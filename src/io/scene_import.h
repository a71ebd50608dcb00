#pragma once
// Scenes from every format Assimp reads (FBX, OBJ, glTF 2.0, Collada, BVH, DirectX .x, 3DS, ASE, …):
// the node hierarchy as objects, meshes for display, and one of the file's animations as keyframes.
//
// - Objects: one per node, named as the node, parents before children, ids from 1. The root node is
//   left out when it carries nothing (no mesh, identity transform, not animated): then its children
//   are the top-level objects. A node's meshes are merged into the one Mesh of its object.
// - Motion: every key of the chosen animation comes through exactly, at time = tick / ticks per
//   second (kDefaultTicksPerSecond when the file gives 0); nothing is resampled. Where a node's
//   rotation and position keys fall at different times, its keyframes are at the union of the times,
//   the other value taken where Assimp's data puts it: slerp between rotation keys, linear between
//   position keys, held before the first and after the last. A value the channel does not animate,
//   and every value of a node without a channel, is the node's own transform; a node without a
//   channel gets one key at time 0. Imported tracks use slerp, which plays the file's motion.
// - Scale: Gyre's tracks are rigid. A node's scale (its first scaling key when animated) is baked
//   into its own mesh; a uniform scale also into its descendants' positions and meshes. A scale that
//   changes over time, or that is not uniform on a node with children, is reported as a warning.
// - Skinning, morph targets, cameras, lights and materials are not imported (warnings say so).

#include "model/input_error.h"
#include "model/scene.h"

#include <QString>
#include <QStringList>

#include <cstddef>
#include <vector>

namespace gyre {

// The ticks per second assumed when a file gives none: what Assimp's own viewer assumes.
inline constexpr double kDefaultTicksPerSecond = 25.0;

struct ImportOptions {
    std::size_t animationIndex = 0; // which of the file's animations gives the motion
};

struct AnimationSummary {
    QString name;
    double durationSeconds = 0.0;
    std::size_t channelCount = 0; // the nodes it moves
};

struct SceneImport {
    model::Scene scene;
    std::vector<AnimationSummary> animations; // every animation of the file, in its order
    QStringList warnings;                     // what the scene could not keep
};

// Throws InputError, whose message names the file, for a file that is missing, a directory, empty or
// unreadable, that Assimp cannot read, whose keys are not finite or whose key times do not increase
// (naming the node and the key), or when the file has no animation `animationIndex` (but has some).
// Nothing is returned on error.
SceneImport importScene(const QString& path, const ImportOptions& options = {});

// The version of the Assimp library Gyre reads and writes scenes with, "5.2.5" for example.
QString assimpVersion();

} // namespace gyre
