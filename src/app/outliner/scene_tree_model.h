#pragma once
// The scene's hierarchy as a Qt item model: one row per object under its parent, siblings in scene
// order, one column, the object's name with a check box for whether the viewport shows it. It
// follows the document's signals row by row (an object added, removed, renamed or given another
// parent inserts, removes, changes or moves its row), and resets only when the whole scene is
// replaced. Edits go through the document's undo commands: renaming an item is one
// RenameObjectCommand, checking or unchecking it one SetObjectVisibilityCommand, dropping items on
// another one undo step of ReparentObjectInPlaceCommands, which keep each object where it is in the
// world.

#include "model/document.h"

#include <QAbstractItemModel>

#include <unordered_map>
#include <vector>

namespace gyre::app {

class SceneTreeModel final : public QAbstractItemModel {
    Q_OBJECT

public:
    explicit SceneTreeModel(model::Document& document, QObject* parent = nullptr);

    // The object an index stands for, and the index of an object (invalid for kNoObject or an
    // object not in the scene).
    static model::ObjectId objectAt(const QModelIndex& index);
    QModelIndex indexOf(model::ObjectId id) const;

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;

    // Drag and drop of objects onto a new parent (or onto empty space: no parent).
    QStringList mimeTypes() const override;
    QMimeData* mimeData(const QModelIndexList& indexes) const override;
    Qt::DropActions supportedDragActions() const override { return Qt::MoveAction; }
    Qt::DropActions supportedDropActions() const override { return Qt::MoveAction; }
    bool canDropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                         const QModelIndex& parent) const override;
    bool dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                      const QModelIndex& parent) override;

    static constexpr const char* kMimeType = "application/x-gyre-object-ids";

private:
    // The ids of the dragged objects that `data` holds, without those whose ancestor is dragged too
    // (they move with it), or nothing when a dragged object would go under itself or its descendant.
    std::vector<model::ObjectId> droppedObjects(const QMimeData* data, model::ObjectId newParent) const;

    void rebuild();
    void onObjectAdded(model::ObjectId id);
    void onObjectRemoved(model::ObjectId id);
    void onObjectChanged(model::ObjectId id);
    // The children of `parent` in the document as it is now, in scene order.
    std::vector<model::ObjectId> childrenInScene(model::ObjectId parent) const;
    std::vector<model::ObjectId>& childrenOf(model::ObjectId parent);
    const std::vector<model::ObjectId>& childrenOf(model::ObjectId parent) const;
    int rowOf(model::ObjectId id) const;
    // The row `id` takes under `parent` among `siblings` (as the views hold them, without it): after
    // those that come before it in the scene.
    int rowAmong(const std::vector<model::ObjectId>& siblings, model::ObjectId id, model::ObjectId parent) const;

    model::Document& document_;
    // The tree as the views last saw it: each object's parent, and each parent's children in order
    // (kNoObject's are the top level).
    std::unordered_map<model::ObjectId, model::ObjectId> parents_;
    std::unordered_map<model::ObjectId, std::vector<model::ObjectId>> children_;
};

} // namespace gyre::app
