#pragma once
// Scenes from every format Assimp reads (FBX, OBJ, glTF 2.0, Collada, BVH, DirectX .x, 3DS, ASE, …):
// the node hierarchy as objects, meshes for display, and the chosen animations as keyframes.
//
// - Objects: one per node, named as the node, parents before children, ids from 1. The root node is
//   left out when it carries nothing (no mesh, identity transform, not animated): then its children
//   are the top-level objects. A node's meshes are merged into the one Mesh of its object. A node
//   without meshes that is no joint (model/scene_joints.h: not a joint of a skin, nor joined to another
//   node without meshes, as a skeleton's nodes are) is an Empty.
// - Takes: a file may hold several animations. Those the options name, or the automatic choice of
//   planTakes(), are merged into one motion.
// - Motion: every key of the chosen animations comes through exactly, at time = tick / ticks per
//   second (kDefaultTicksPerSecond when the file gives 0); nothing is resampled. Where a node's
//   rotation and position keys fall at different times, its keyframes are at the union of the times,
//   the other value taken where Assimp's data puts it: slerp between rotation keys, linear between
//   position keys, held before the first and after the last. A single key beside several is a
//   constant and adds no time of its own. A value the channel does not animate,
//   and every value of a node without a channel, is the node's own transform; a node without a
//   channel gets one key at time 0. Imported tracks use slerp, which plays the file's motion.
// - glTF: Assimp keeps no sampler interpolation, so a glTF node's rotation and translation come from
//   TinyGLTF instead (gltf_animation.h): STEP stays a step, CUBICSPLINE keeps its tangents (a hermite
//   track whose applied fit is the file's spline). Meshes, hierarchy and scale are Assimp's.
// - Settings (ImportSettings): frame rate, unit and up axis as the file says (scene_import_settings.h)
//   unless the options say otherwise; positions and meshes are scaled to metres, a Y-up scene turned
//   Z-up (Gyre's world), and the times moved so the first key is at 0 unless TimeOrigin::File.
// - Scale: Gyre's tracks are rigid. A node's scale (its first scaling key when animated) is baked
//   into its own mesh; a uniform scale also into its descendants' positions and meshes. A scale that
//   changes over time, or that is not uniform on a node with children, is reported as a warning.
// - Skinned meshes keep their skin (scene_import_skin.h). Morph targets, cameras, lights and materials
//   are not imported (warnings say so).

#include "core/name_table.h"
#include "io/up_axis.h"
#include "model/input_error.h"
#include "model/scene.h"

#include <QString>
#include <QStringList>

#include <cstddef>
#include <optional>
#include <vector>

namespace gyre::io {

// The ticks per second assumed when a file gives none: what Assimp's own viewer assumes.
inline constexpr double kDefaultTicksPerSecond = 25.0;

// Where the imported motion's time 0 is. FirstKey (the default): the earliest key of the imported
// motion is at t = 0 whatever the format (FBX and BVH files say so already; glTF and Collada from
// Blender put frame f at f/fps). File: key times as the file has them.
enum class TimeOrigin : quint8 { FirstKey = 1, File = 2 };
inline constexpr NameTable<TimeOrigin, 2> kTimeOriginNames{{{TimeOrigin::FirstKey, "zero"}, {TimeOrigin::File, "file"}}};

// The settings an import applies; each defaults to what the file says (FileSettings).
struct ImportSettings {
    double fps = 24.0;         // the project's frame rate; keys are never resampled
    double metresPerUnit = 1.0; // Gyre works in metres: a centimetre FBX has 0.01
    UpAxis up = UpAxis::Y;
};

// What the file says about each setting, and where it says it ("the FBX time mode", ...).
struct FileSettings {
    ImportSettings values;
    QString fpsSource;
    QString unitSource;
    QString upSource;
};

enum class TakeSelection : quint8 { Automatic = 1, All = 2, Listed = 3 };

struct ImportOptions {
    // Which of the file's animations (takes) make the motion: the automatic choice (planTakes), all of
    // them, or those listed in `takes`; merged in their order, a node moved by several taking the last
    // one's channel.
    TakeSelection takeSelection = TakeSelection::Automatic;
    std::vector<std::size_t> takes;
    // Each unset one is what the file says.
    std::optional<double> fps;
    std::optional<double> metresPerUnit;
    std::optional<UpAxis> up;
    TimeOrigin timeOrigin = TimeOrigin::FirstKey;
};

struct AnimationSummary {
    QString name;
    double durationSeconds = 0.0;
    QStringList nodes; // the nodes it moves, in the file's order
};

// How the takes of SceneImport::takes were chosen.
enum class TakeRule : quint8 {
    NoAnimation = 1,    // the file has none
    Single = 2,         // it has one
    Disjoint = 3,       // every animation moves nodes no other moves: all merged (Blender's glTF, one per action)
    BlenderActions = 4, // Blender's FBX takes "Object|Action": each object plays its own action
    ChoiceNeeded = 5,   // the animations overlap and follow no known pattern: animation 0 alone, by default
    Chosen = 6,         // ImportOptions::takeSelection named them (all, or a list)
};

struct SceneImport {
    model::Scene scene;                       // its fps is the one applied
    std::vector<AnimationSummary> animations; // every animation of the file, in its order
    std::vector<std::size_t> takes;           // those the motion came from, in the order merged
    TakeRule takeRule = TakeRule::NoAnimation;
    FileSettings file;                        // what the file says: the defaults of ImportOptions
    ImportSettings applied;                   // what the import applied
    double timeShift = 0.0;                   // seconds added to the file's key times
    QStringList warnings;                     // what the scene could not keep, and which take each object got
};

// The automatic choice of takes (TakeRule) for animations that move `animations[i].nodes`, with the
// warning that says which take each object got for Blender's takes. Blender names an object's first
// action after it ("CubeAction"), and writes a take "Object|Action" for every object and action: an
// object gets the take of its own action; without one, of an action no other object is named by,
// else its first take.
struct TakePlan {
    std::vector<std::size_t> takes;
    TakeRule rule = TakeRule::NoAnimation;
    QStringList warnings;
};
TakePlan planTakes(const std::vector<AnimationSummary>& animations);

// Throws InputError, whose message names the file, for a file that is missing, a directory, empty or
// unreadable, that Assimp cannot read, whose keys are not finite or whose key times do not increase
// (naming the node and the key), when ImportOptions::takes lists an animation the file does not have,
// or when an option is out of range (fps in (0, 1000], a positive finite unit). Nothing is returned on
// error. With TakeRule::ChoiceNeeded it returns animation 0's motion: callers that must not import
// silently as one (gyre-cli, the app) ask which takes to use.
SceneImport importScene(const QString& path, const ImportOptions& options = {});

// Assimp's own read of `path` with the settings importScene gives it, and none of Gyre's work after:
// the floor an import is measured against (gyre-bench's BM_AssimpReadBvh, docs/file-format.md).
// Returns the number of animations read; throws InputError as importScene does.
unsigned readWithAssimpOnly(const QString& path);

// The version of the Assimp library Gyre reads and writes scenes with, "5.2.5" for example.
QString assimpVersion();

} // namespace gyre::io
