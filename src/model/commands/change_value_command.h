#pragma once
// The shape of most commands, after Tiled's ChangeValue: redo puts a new value into one field of the
// document and keeps the old one; undo swaps them back. Within one gesture, consecutive commands on
// the same field of the same target merge (MergeableCommand), so a drag is undone at once; when the
// merged value is the one from before, the command changes nothing and its gesture leaves no step.
//
// A Field (object_fields.h) says what is changed:
//   using Value = ...;
//   static constexpr Changes kChanges;   // the signals the change emits
//   static constexpr bool kMerges;       // whether consecutive edits in a gesture merge
//   static Value get(const Scene&, const FieldTarget&);
//   static void set(Scene&, const FieldTarget&, Value);

#include "model/commands/mergeable_command.h"
#include "model/document_editor.h"

#include <Eigen/Geometry>

#include <cstddef>
#include <optional>
#include <tuple>
#include <utility>

namespace gyre::model {

// Whether two values of a field are the same, exactly: the test for a gesture that came back to
// where it began.
template <class Value>
bool sameValue(const Value& a, const Value& b)
{
    return a == b;
}
// Component by component: q and −q are the same rotation but not the same value of the document.
inline bool sameValue(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) { return a.coeffs() == b.coeffs(); }

// A key's orientation and its stored angles (scene.h's Keyframe).
using KeyRotation = std::tuple<Eigen::Quaterniond, std::optional<Eigen::Vector3d>>;
inline bool sameValue(const KeyRotation& a, const KeyRotation& b)
{
    return sameValue(std::get<0>(a), std::get<0>(b)) && std::get<1>(a) == std::get<1>(b);
}

// The object a field belongs to (kNoObject for a field of the scene) and, for a field of a keyframe
// or stroke, its index.
struct FieldTarget {
    ObjectId object = kNoObject;
    std::size_t index = 0;
    bool operator==(const FieldTarget&) const = default;
};

template <class Field>
class ChangeValueCommand : public MergeableCommand {
public:
    using Value = typename Field::Value;

    void redo() override { swap(); }
    void undo() override { swap(); }

    // `later`'s value is in the document now; this command keeps the value from before both, which
    // undo restores. Only a command of the same Field (the same class) on the same target merges.
    bool mergeWithin(const MergeableCommand& later) override
    {
        if constexpr (!Field::kMerges) {
            return false;
        } else {
            const auto* same = dynamic_cast<const ChangeValueCommand*>(&later);
            return same != nullptr && same->target_ == target_;
        }
    }

    // Done, this command holds the value from before it; the document holds the value it set.
    bool changesNothing() const override
    {
        if constexpr (!Field::kMerges)
            return false; // never merged, so never brought back; and some of these values have no ==
        else
            return sameValue(Field::get(document_.scene(), target_), value_);
    }

protected:
    ChangeValueCommand(Document& document, FieldTarget target, Value value, const QString& text,
                       QUndoCommand* parent)
        : MergeableCommand(text, parent)
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
