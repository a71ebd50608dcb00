#include "app/outliner/outliner_panel.h"

#include "model/commands/delete_object_command.h"
#include "model/scene_queries.h"

#include <QEvent>
#include <QItemSelectionModel>
#include <QKeyEvent>
#include <QLineEdit>
#include <QTreeView>
#include <QVBoxLayout>

#include <algorithm>

namespace gyre::app {

OutlinerPanel::OutlinerPanel(model::Document& document, Selection& selection, QWidget* parent)
    : QWidget(parent)
    , document_(document)
    , selection_(selection)
    , model_(document)
{
    filtered_.setSourceModel(&model_);
    filtered_.setRecursiveFilteringEnabled(true); // a match shows its ancestors, so it stays in its place
    filtered_.setFilterCaseSensitivity(Qt::CaseInsensitive);

    filter_ = new QLineEdit(this);
    filter_->setPlaceholderText(tr("Filter by name"));
    filter_->setClearButtonEnabled(true);
    tree_ = new QTreeView(this);
    tree_->setModel(&filtered_);
    tree_->setHeaderHidden(true);
    tree_->setUniformRowHeights(true); // thousands of joints scroll without measuring each row
    tree_->setSelectionMode(QAbstractItemView::ExtendedSelection);
    tree_->setEditTriggers(QAbstractItemView::EditKeyPressed | QAbstractItemView::DoubleClicked);
    tree_->setDragDropMode(QAbstractItemView::InternalMove);
    tree_->setDefaultDropAction(Qt::MoveAction);
    tree_->setDropIndicatorShown(true);
    tree_->installEventFilter(this);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(filter_);
    layout->addWidget(tree_);

    connect(filter_, &QLineEdit::textChanged, this, [this](const QString& text) {
        filtered_.setFilterFixedString(text);
        if (!text.isEmpty())
            tree_->expandAll(); // the matches, not their collapsed ancestors
        showSelection();
    });
    connect(&selection_, &Selection::changed, this, &OutlinerPanel::showSelection);
    // The tree loses its selection when the scene is replaced, and an object selected as it was
    // added is in the tree only afterwards.
    connect(&model_, &QAbstractItemModel::modelReset, this, [this] {
        if (isSmallScene())
            tree_->expandAll();
        showSelection();
    });
    connect(&model_, &QAbstractItemModel::rowsInserted, this, [this](const QModelIndex& under, int first, int last) {
        for (int row = first; row <= last && isSmallScene(); ++row)
            tree_->expand(filtered_.mapFromSource(model_.index(row, 0, under)));
        showSelection();
    });
    connect(tree_->selectionModel(), &QItemSelectionModel::selectionChanged, this, &OutlinerPanel::selectCurrentObject);
    if (isSmallScene())
        tree_->expandAll();
    showSelection();
}

bool OutlinerPanel::isSmallScene() const
{
    return document_.scene().objects.size() <= kExpandedObjects;
}

void OutlinerPanel::showSelection()
{
    const QModelIndex active = filtered_.mapFromSource(model_.indexOf(selection_.object()));
    QItemSelectionModel* chosen = tree_->selectionModel();
    std::vector<model::ObjectId> shown;
    for (const QModelIndex& row : chosen->selectedRows())
        shown.push_back(SceneTreeModel::objectAt(filtered_.mapToSource(row)));
    std::vector<model::ObjectId> selected = selection_.objects();
    std::sort(shown.begin(), shown.end());
    std::sort(selected.begin(), selected.end());
    if (shown == selected && chosen->currentIndex() == active)
        return;
    showingSelection_ = true;
    QItemSelection rows;
    for (model::ObjectId id : selected)
        if (const QModelIndex index = filtered_.mapFromSource(model_.indexOf(id)); index.isValid())
            rows.select(index, index);
    chosen->select(rows, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    if (active.isValid()) {
        chosen->setCurrentIndex(active, QItemSelectionModel::NoUpdate);
        tree_->scrollTo(active); // expands its ancestors
    }
    showingSelection_ = false;
}

void OutlinerPanel::selectCurrentObject()
{
    if (showingSelection_)
        return;
    QItemSelectionModel* chosen = tree_->selectionModel();
    std::vector<model::ObjectId> ids;
    for (const QModelIndex& row : chosen->selectedRows())
        ids.push_back(SceneTreeModel::objectAt(filtered_.mapToSource(row)));
    if (ids.empty())
        return; // as before: the tree emptied by a click keeps the selection
    // The row clicked last is the active object, if it is selected.
    const QModelIndex current = chosen->currentIndex();
    const model::ObjectId active =
        chosen->isSelected(current) ? SceneTreeModel::objectAt(filtered_.mapToSource(current)) : model::kNoObject;
    selection_.selectObjects(ids, active != model::kNoObject ? active : selection_.object());
}

std::vector<model::ObjectId> OutlinerPanel::selectedObjects() const
{
    std::vector<model::ObjectId> ids;
    for (const QModelIndex& row : tree_->selectionModel()->selectedRows())
        ids.push_back(SceneTreeModel::objectAt(filtered_.mapToSource(row)));
    const model::Scene& scene = document_.scene();
    std::erase_if(ids, [&](model::ObjectId id) {
        return std::any_of(ids.begin(), ids.end(), [&](model::ObjectId other) { return model::isAncestor(scene, other, id); });
    });
    return ids;
}

void OutlinerPanel::deleteSelectedObjects()
{
    const std::vector<model::ObjectId> ids = selectedObjects();
    if (ids.empty())
        return;
    if (ids.size() == 1) {
        document_.push(new model::DeleteObjectCommand(document_, ids.front()));
        return;
    }
    // One undo step, named for all of them: a macro opened and closed here.
    QUndoStack& stack = document_.undoStack();
    stack.beginMacro(tr("Delete %n Objects", nullptr, int(ids.size())));
    for (model::ObjectId id : ids)
        document_.push(new model::DeleteObjectCommand(document_, id));
    stack.endMacro();
}

bool OutlinerPanel::eventFilter(QObject* watched, QEvent* event)
{
    // Delete is also Edit ▸ Delete Keyframe's shortcut: in the tree it deletes objects instead. A
    // widget that accepts the shortcut override gets the key press, and the shortcut does not fire.
    // While a name is edited, the editor has the keys, not the tree.
    if (watched == tree_ && (event->type() == QEvent::ShortcutOverride || event->type() == QEvent::KeyPress)) {
        const auto* key = static_cast<QKeyEvent*>(event);
        if (key->key() == Qt::Key_Delete && key->modifiers() == Qt::NoModifier) {
            event->accept();
            if (event->type() == QEvent::KeyPress)
                deleteSelectedObjects();
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace gyre::app
