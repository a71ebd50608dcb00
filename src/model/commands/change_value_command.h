#pragma once
// The shape of most commands, after Tiled's ChangeValue: redo puts a new value into one field of the
// document and keeps the old one; undo swaps them back. Consecutive commands on the same field of
// the same target merge into one undo step, so a drag is undone at once.
//
// A Field (object_fields.h) says what is changed:
//   using Value = ...;
//   static constexpr Changes kChanges;   // the signals the change emits
//   static constexpr int kMergeId;       // unique among fields, or -1: never merges
//   static Value get(const Scene&, const FieldTarget&);
//   static void set(Scene&, const FieldTarget&, Value);

#include "model/document_editor.h"

#include <QUndoCommand>

#include <cstddef>
#include <utility>

namespace gyre::model {

// The object a field belongs to (kNoObject for a field of the scene) and, for a field of a keyframe
// or stroke, its index.
struct FieldTarget {
    ObjectId object = kNoObject;
    std::size_t index = 0;
    bool operator==(const FieldTarget&) const = default;
};

template <class Field>
class ChangeValueCommand : public QUndoCommand {
public:
    using Value = typename Field::Value;

    void redo() override { swap(); }
    void undo() override { swap(); }
    int id() const override { return Field::kMergeId; }

    // The stack asks only when other->id() == id(), so `other` changes the same field, maybe of
    // another target. Its value is in the document now; this command keeps the value from before
    // both, which undo restores.
    bool mergeWith(const QUndoCommand* other) override
    {
        return static_cast<const ChangeValueCommand*>(other)->target_ == target_;
    }

protected:
    ChangeValueCommand(Document& document, FieldTarget target, Value value, const QString& text,
                       QUndoCommand* parent)
        : QUndoCommand(text, parent)
        , document_(document)
        , target_(target)
        , value_(std::move(value))
    {
    }

private:
    void swap()
    {
        DocumentEditor editor(document_);
        Value previous = Field::get(editor.scene(), target_);
        editor.edit(target_.object, Field::kChanges,
                    [this](Scene& scene) { Field::set(scene, target_, std::move(value_)); });
        value_ = std::move(previous);
    }

    Document& document_;
    FieldTarget target_;
    Value value_; // the value that the next redo or undo puts in
};

} // namespace gyre::model
