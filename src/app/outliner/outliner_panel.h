#pragma once
// The Outliner: the scene's hierarchy as a tree (SceneTreeModel) under a filter box, which shows the
// objects whose names contain its text together with their ancestors. Its selection follows the
// app's Selection and sets it, so the viewport and the outliner show the same object. F2 or a double
// click renames the object in place; Delete deletes the selected objects with their descendants;
// dragging objects onto another makes them its children, onto empty space top-level objects, where
// they stay in the world. Every edit is one undo step.

#include "app/outliner/scene_tree_model.h"
#include "app/selection.h"
#include "model/document.h"

#include <QSortFilterProxyModel>
#include <QWidget>

#include <cstddef>
#include <vector>

class QLineEdit;
class QTreeView;

namespace gyre::app {

class OutlinerPanel final : public QWidget {
    Q_OBJECT

public:
    OutlinerPanel(model::Document& document, Selection& selection, QWidget* parent = nullptr);

    SceneTreeModel& sceneModel() { return model_; }
    QSortFilterProxyModel& filteredModel() { return filtered_; }
    QTreeView* tree() const { return tree_; }
    QLineEdit* filterBox() const { return filter_; }

    // Deletes the objects selected in the tree, with their descendants, as one undo step.
    void deleteSelectedObjects();

    // A scene of at most this many objects, a skeleton or a few props, opens with every row
    // expanded, and objects added to it show expanded; a larger one shows its top level, so that
    // its thousands of rows are opened where the artist looks.
    static constexpr std::size_t kExpandedObjects = 200;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    // The selected objects, without those whose ancestor is selected too.
    std::vector<model::ObjectId> selectedObjects() const;
    bool isSmallScene() const;
    void showSelection();
    void selectCurrentObject();

    model::Document& document_;
    Selection& selection_;
    SceneTreeModel model_;
    QSortFilterProxyModel filtered_;
    QLineEdit* filter_ = nullptr;
    QTreeView* tree_ = nullptr;
    bool showingSelection_ = false; // while the tree follows Selection, it does not set it back
};

} // namespace gyre::app
