#pragma once
// Replaces the keyframes of several objects at once: what the key editing of the timeline, the graph
// editor and the clipboard does to a selection that spans objects (delete, insert, paste, move,
// scale). One command is one undo step however many objects it touches; within a gesture (a drag of
// selected keys) consecutive replacements of the same objects merge, so the drag is undone at once.

#include "model/commands/mergeable_command.h"
#include "model/document.h"
#include "model/shared_vector.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace gyre::model {

// Each object's whole new list of keys.
using ObjectKeys = std::vector<std::pair<ObjectId, std::vector<Keyframe>>>;

class ReplaceKeyframesCommand final : public MergeableCommand {
public:
    // What the replacement does, which names the undo step.
    enum class Edit { Delete, Insert, Paste, Move, Scale };

    // Throws std::invalid_argument for an unknown object, an object named twice, keys value_checks.h
    // refuses (times must increase; drifted orientations are normalised) or more poses than a screw
    // track may subdivide into.
    ReplaceKeyframesCommand(Document& document, ObjectKeys keys, Edit edit, QUndoCommand* parent = nullptr);

    void redo() override { swap(); }
    void undo() override { swap(); }
    bool mergeWithin(const MergeableCommand& later) override;
    bool changesNothing() const override;

private:
    void swap();

    Document& document_;
    Edit edit_;
    // The keys that the next redo or undo puts in, shared with the document once put in: undo and redo
    // copy no keys.
    std::vector<std::pair<ObjectId, SharedVector<Keyframe>>> keys_;
};

} // namespace gyre::model
