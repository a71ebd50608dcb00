#pragma once
// Random documents for the model's tests: scenes, objects and every kind of undo command, all from a
// seeded generator so that a failure can be replayed.

#include "model/commands/replace_keyframes_command.h"
#include "model/document.h"
#include "model/scene.h"

#include <QUndoCommand>

#include <array>
#include <cstddef>
#include <memory>
#include <random>
#include <vector>

namespace gyre::model::test {

// Every command kind, for the random edits and for counting that each was tried.
enum class EditKind {
    ImportObjects,
    DeleteObject,
    RenameObject,
    SetObjectVisibility,
    SetMassOverride,
    ReparentObject,
    ReparentObjectInPlace,
    InsertKeyframe,
    DeleteKeyframe,
    MoveKeyframe,
    RetimeKeyframes,
    ApplyEulerFilter,
    SetKeyframeOrientation,
    SetKeyframePosition,
    ToggleKeyframeConstraint,
    SetInterpolation,
    SetSubdivision,
    AddStroke,
    EraseStroke,
    EditStroke,
    SetMagnitudeCurve,
    SetPattern,
    SetFitWindow,
    SetFitParameter,
    ApplyFitResult,
    SetTimeRange,
};
inline constexpr int kEditKinds = static_cast<int>(EditKind::SetTimeRange) + 1;

// What the window's Add Keyframe and Delete Keyframe do to one object (app/keyframe_actions.cpp): its
// keys replaced by the same keys with `key` put in, in time order (replacing a key at its time), or
// with the key at index `key` taken out. The object must exist.
std::unique_ptr<ReplaceKeyframesCommand> insertKeyframe(Document& document, ObjectId id, const Keyframe& key);
std::unique_ptr<ReplaceKeyframesCommand> deleteKeyframe(Document& document, ObjectId id, std::size_t key);

class RandomEdits {
public:
    explicit RandomEdits(unsigned seed);

    // A random command for the document as it is, or null when this kind has nothing to act on
    // (no objects, no keys, a key already at the time to key). With some probability the command
    // repeats the previous kind and target, so that drags merge. May throw std::invalid_argument where
    // the command refuses the edit, as a reparenting under a descendant does.
    std::unique_ptr<QUndoCommand> command(Document& document, EditKind kind);
    // The kind of the next edit; imports give way to deletions once the scene has enough objects,
    // so that every step stays cheap to compare.
    EditKind kind(const Document& document);
    // Whether the latest kind() repeats the kind before it, and command() then its target.
    bool repeating() const { return repeating_; }

    // Random values.
    Eigen::Quaterniond rotation();
    Eigen::Vector3d vector();
    double number(double low, double high);
    std::size_t index(std::size_t count);
    Keyframe keyframe(double time);
    std::vector<Keyframe> keyframes(int count);
    SketchState sketch();
    // A batch of objects in ImportObjectsCommand's terms: local ids 1..n, parents earlier in the batch.
    std::vector<SceneObject> objects(int count);
    std::shared_ptr<const Mesh> mesh();
    // A box's: of random size and mass, turned and off centre.
    MassProperties massProperties();
    // A scene with `count` objects, each with keys and a sketch, some sharing a mesh.
    Scene scene(int count);

    std::mt19937& engine() { return engine_; }

private:
    ObjectId object(const Document& document);

    std::mt19937 engine_;
    EditKind lastKind_ = EditKind::ImportObjects;
    ObjectId lastObject_ = kNoObject;
    std::size_t lastIndex_ = 0;
    bool repeating_ = false;
};

} // namespace gyre::model::test
