#pragma once
// The shape of commands that add or remove one entry of a list an object holds (its direction
// strokes): one direction inserts the entry at its index, the other removes it again.
//
// A List (object_fields.h) says which list:
//   using Entry = ...;
//   static constexpr Changes kChanges;
//   static std::vector<Entry>& of(Scene&, ObjectId);

#include "model/document_editor.h"

#include <QUndoCommand>

#include <cstddef>
#include <iterator>
#include <utility>

namespace gyre::model {

template <class List>
class ListEntryCommand : public QUndoCommand {
public:
    using Entry = typename List::Entry;
    enum class Direction { Insert, Remove };

    void redo() override { direction_ == Direction::Insert ? insert() : remove(); }
    void undo() override { direction_ == Direction::Insert ? remove() : insert(); }

protected:
    // `entry` is the entry to insert, or the one at `index` that is to be removed.
    ListEntryCommand(Document& document, ObjectId object, std::size_t index, Entry entry, Direction direction,
                     const QString& text, QUndoCommand* parent)
        : QUndoCommand(text, parent)
        , document_(document)
        , object_(object)
        , index_(index)
        , entry_(std::move(entry))
        , direction_(direction)
    {
    }

private:
    auto position(std::vector<Entry>& list) const { return std::next(list.begin(), static_cast<std::ptrdiff_t>(index_)); }

    void insert()
    {
        DocumentEditor(document_).edit(object_, List::kChanges, [this](Scene& scene) {
            std::vector<Entry>& list = List::of(scene, object_);
            list.insert(position(list), entry_);
        });
    }

    void remove()
    {
        DocumentEditor(document_).edit(object_, List::kChanges, [this](Scene& scene) {
            std::vector<Entry>& list = List::of(scene, object_);
            list.erase(position(list));
        });
    }

    Document& document_;
    ObjectId object_;
    std::size_t index_;
    Entry entry_;
    Direction direction_;
};

} // namespace gyre::model
