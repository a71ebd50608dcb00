#include "app/outliner/scene_tree_model.h"

#include "model/commands/rename_object_command.h"
#include "model/commands/reparent_object_in_place_command.h"
#include "model/commands/set_object_visibility_command.h"
#include "model/scene_queries.h"

#include <QDataStream>
#include <QIODevice>
#include <QMimeData>

#include <algorithm>
#include <stdexcept>

namespace gyre::app {

SceneTreeModel::SceneTreeModel(model::Document& document, QObject* parent)
    : QAbstractItemModel(parent)
    , document_(document)
{
    connect(&document_, &model::Document::changed, this, [this](model::ObjectId id, model::Changes changes) {
        using model::Change;
        if (changes.testFlag(Change::Scene)) {
            beginResetModel();
            rebuild();
            endResetModel();
        } else if (changes.testFlag(Change::Added)) {
            onObjectAdded(id);
        } else if (changes.testFlag(Change::Removed)) {
            onObjectRemoved(id);
        } else if (changes.testFlag(Change::Object)) {
            onObjectChanged(id);
        }
    });
    rebuild();
}

model::ObjectId SceneTreeModel::objectAt(const QModelIndex& index)
{
    return index.isValid() ? static_cast<model::ObjectId>(index.internalId()) : model::kNoObject;
}

QModelIndex SceneTreeModel::indexOf(model::ObjectId id) const
{
    const int row = rowOf(id);
    return row < 0 ? QModelIndex() : createIndex(row, 0, static_cast<quintptr>(id));
}

// --- The tree as the views see it ------------------------------------------------------------------

const std::vector<model::ObjectId>& SceneTreeModel::childrenOf(model::ObjectId parent) const
{
    static const std::vector<model::ObjectId> none;
    const auto found = children_.find(parent);
    return found == children_.end() ? none : found->second;
}

std::vector<model::ObjectId>& SceneTreeModel::childrenOf(model::ObjectId parent)
{
    return children_[parent];
}

int SceneTreeModel::rowOf(model::ObjectId id) const
{
    const auto parent = parents_.find(id);
    if (parent == parents_.end())
        return -1;
    const std::vector<model::ObjectId>& siblings = childrenOf(parent->second);
    return static_cast<int>(std::find(siblings.begin(), siblings.end(), id) - siblings.begin());
}

std::vector<model::ObjectId> SceneTreeModel::childrenInScene(model::ObjectId parent) const
{
    std::vector<model::ObjectId> children;
    for (const model::SceneObject& object : document_.scene().objects)
        if (object.parent == parent)
            children.push_back(object.id);
    return children;
}

int SceneTreeModel::rowAmong(const std::vector<model::ObjectId>& siblings, model::ObjectId id, model::ObjectId parent) const
{
    const std::vector<model::ObjectId> inScene = childrenInScene(parent);
    const auto rank = [&inScene](model::ObjectId child) { return std::find(inScene.begin(), inScene.end(), child) - inScene.begin(); };
    const auto after = std::find_if(siblings.begin(), siblings.end(), [&](model::ObjectId sibling) { return rank(sibling) > rank(id); });
    return static_cast<int>(after - siblings.begin());
}

void SceneTreeModel::rebuild()
{
    parents_.clear();
    children_.clear();
    for (const model::SceneObject& object : document_.scene().objects) {
        parents_[object.id] = object.parent;
        children_[object.parent].push_back(object.id);
    }
}

QModelIndex SceneTreeModel::index(int row, int column, const QModelIndex& parent) const
{
    const std::vector<model::ObjectId>& children = childrenOf(objectAt(parent));
    if (column != 0 || row < 0 || row >= static_cast<int>(children.size()))
        return {};
    return createIndex(row, 0, static_cast<quintptr>(children[static_cast<std::size_t>(row)]));
}

QModelIndex SceneTreeModel::parent(const QModelIndex& child) const
{
    const auto found = parents_.find(objectAt(child));
    return found == parents_.end() ? QModelIndex() : indexOf(found->second);
}

int SceneTreeModel::rowCount(const QModelIndex& parent) const
{
    return parent.column() > 0 ? 0 : static_cast<int>(childrenOf(objectAt(parent)).size());
}

int SceneTreeModel::columnCount(const QModelIndex&) const
{
    return 1;
}

QVariant SceneTreeModel::data(const QModelIndex& index, int role) const
{
    const model::SceneObject* object = document_.object(objectAt(index));
    if (object == nullptr)
        return {};
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole:
        return object->name;
    case Qt::CheckStateRole:
        return object->visible ? Qt::Checked : Qt::Unchecked;
    case Qt::ToolTipRole:
        return object->visible ? tr("Shown in the viewport: uncheck to hide it") : tr("Hidden in the viewport: check to show it");
    default:
        return {};
    }
}

Qt::ItemFlags SceneTreeModel::flags(const QModelIndex& index) const
{
    // Dropping on empty space takes the objects out of their parents.
    if (!index.isValid())
        return Qt::ItemIsDropEnabled;
    return Qt::ItemIsSelectable | Qt::ItemIsEnabled | Qt::ItemIsEditable | Qt::ItemIsUserCheckable | Qt::ItemIsDragEnabled
           | Qt::ItemIsDropEnabled;
}

bool SceneTreeModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    const model::SceneObject* object = document_.object(objectAt(index));
    if (object != nullptr && role == Qt::CheckStateRole) {
        const bool visible = value.value<Qt::CheckState>() == Qt::Checked;
        if (visible == object->visible)
            return false;
        document_.push(new model::SetObjectVisibilityCommand(document_, object->id, visible));
        return true;
    }
    const QString name = value.toString().trimmed();
    // A nameless object could not be found in the outliner again; an unchanged name is no edit.
    if (object == nullptr || role != Qt::EditRole || name.isEmpty() || name == object->name)
        return false;
    document_.push(new model::RenameObjectCommand(document_, object->id, name));
    return true; // the document's changed (Change::Object) has told the views
}

// --- Following the document ------------------------------------------------------------------------

void SceneTreeModel::onObjectAdded(model::ObjectId id)
{
    const model::SceneObject* object = document_.object(id);
    if (object == nullptr || parents_.contains(id))
        return;
    if (object->parent != model::kNoObject && !parents_.contains(object->parent)) {
        // Parents are added first; a tree that missed one is rebuilt rather than left wrong.
        beginResetModel();
        rebuild();
        endResetModel();
        return;
    }
    std::vector<model::ObjectId>& siblings = childrenOf(object->parent);
    const int row = rowAmong(siblings, id, object->parent);
    beginInsertRows(indexOf(object->parent), row, row);
    siblings.insert(siblings.begin() + row, id);
    parents_[id] = object->parent;
    endInsertRows();
}

void SceneTreeModel::onObjectRemoved(model::ObjectId id)
{
    const int row = rowOf(id);
    if (row < 0)
        return;
    const model::ObjectId parent = parents_.at(id);
    beginRemoveRows(indexOf(parent), row, row);
    childrenOf(parent).erase(childrenOf(parent).begin() + row);
    // Children are removed before their parents; any left go with their row.
    std::vector<model::ObjectId> gone{id};
    while (!gone.empty()) {
        const model::ObjectId next = gone.back();
        gone.pop_back();
        parents_.erase(next);
        if (const auto children = children_.find(next); children != children_.end()) {
            gone.insert(gone.end(), children->second.begin(), children->second.end());
            children_.erase(children);
        }
    }
    endRemoveRows();
}

void SceneTreeModel::onObjectChanged(model::ObjectId id)
{
    const model::SceneObject* object = document_.object(id);
    const int oldRow = rowOf(id);
    if (object == nullptr || oldRow < 0)
        return;
    const model::ObjectId oldParent = parents_.at(id);
    const model::ObjectId newParent = object->parent;
    std::vector<model::ObjectId> newSiblings = childrenOf(newParent);
    std::erase(newSiblings, id);
    const int newRow = rowAmong(newSiblings, id, newParent);
    if (oldParent != newParent || oldRow != newRow) {
        // beginMoveRows counts the destination before the row leaves: one more when it moves down
        // among its own siblings.
        const int destination = oldParent == newParent && newRow > oldRow ? newRow + 1 : newRow;
        if (!beginMoveRows(indexOf(oldParent), oldRow, oldRow, indexOf(newParent), destination)) {
            beginResetModel();
            rebuild();
            endResetModel();
            return;
        }
        std::vector<model::ObjectId>& oldSiblings = childrenOf(oldParent);
        oldSiblings.erase(oldSiblings.begin() + oldRow);
        std::vector<model::ObjectId>& siblings = childrenOf(newParent);
        siblings.insert(siblings.begin() + newRow, id);
        parents_[id] = newParent;
        endMoveRows();
    }
    const QModelIndex changed = indexOf(id);
    emit dataChanged(changed, changed, {Qt::DisplayRole, Qt::EditRole});
}

// --- Drag and drop ---------------------------------------------------------------------------------

QStringList SceneTreeModel::mimeTypes() const
{
    return {QString::fromLatin1(kMimeType)};
}

QMimeData* SceneTreeModel::mimeData(const QModelIndexList& indexes) const
{
    QByteArray encoded;
    QDataStream stream(&encoded, QIODevice::WriteOnly);
    for (const QModelIndex& index : indexes)
        if (index.isValid() && index.column() == 0)
            stream << quint64(objectAt(index));
    auto* data = new QMimeData;
    data->setData(QString::fromLatin1(kMimeType), encoded);
    return data;
}

std::vector<model::ObjectId> SceneTreeModel::droppedObjects(const QMimeData* data, model::ObjectId newParent) const
{
    if (data == nullptr || !data->hasFormat(QString::fromLatin1(kMimeType)))
        return {};
    const model::Scene& scene = document_.scene();
    if (newParent != model::kNoObject && document_.object(newParent) == nullptr)
        return {};
    std::vector<model::ObjectId> dragged;
    QDataStream stream(data->data(QString::fromLatin1(kMimeType)));
    while (!stream.atEnd()) {
        quint64 id = 0;
        stream >> id;
        if (stream.status() != QDataStream::Ok)
            return {};
        if (document_.object(id) == nullptr)
            continue;
        if (id == newParent || model::isAncestor(scene, id, newParent))
            return {}; // under itself or its own descendant
        dragged.push_back(id);
    }
    // An object whose ancestor is dragged too moves with it; one already under the parent stays.
    std::erase_if(dragged, [&](model::ObjectId id) {
        return document_.object(id)->parent == newParent
               || std::any_of(dragged.begin(), dragged.end(), [&](model::ObjectId other) { return model::isAncestor(scene, other, id); });
    });
    return dragged;
}

bool SceneTreeModel::canDropMimeData(const QMimeData* data, Qt::DropAction action, int, int, const QModelIndex& parent) const
{
    return action == Qt::MoveAction && !droppedObjects(data, objectAt(parent)).empty();
}

bool SceneTreeModel::dropMimeData(const QMimeData* data, Qt::DropAction action, int, int, const QModelIndex& parent)
{
    const model::ObjectId newParent = objectAt(parent);
    const std::vector<model::ObjectId> dropped = droppedObjects(data, newParent);
    if (action != Qt::MoveAction || dropped.empty())
        return false;
    if (dropped.size() == 1) {
        document_.push(new model::ReparentObjectInPlaceCommand(document_, dropped.front(), newParent));
        return true;
    }
    // One undo step, named for all of them: a macro opened and closed here. Each command takes the
    // object order as it finds it, so they are made one after another.
    QUndoStack& stack = document_.undoStack();
    stack.beginMacro(tr("Reparent %n Objects in Place", nullptr, int(dropped.size())));
    for (model::ObjectId id : dropped)
        document_.push(new model::ReparentObjectInPlaceCommand(document_, id, newParent));
    stack.endMacro();
    return true;
}

} // namespace gyre::app
