// The Outliner dock in the real main window: the tree against the document's hierarchy, selection in
// step with the app's (and so the viewport's) both ways, rename in place, the visibility check box,
// Delete, reparenting by drag and drop with the world pose kept at every key, and the filter.
// QAbstractItemModelTester checks the model's consistency through every change, and no change but a
// new scene resets it.

#include "app/main_window.h"
#include "app/outliner/outliner_panel.h"
#include "app/viewport/viewport.h"
#include "gui_test_support.h"
#include "model/commands/import_objects_command.h"
#include "model/scene_queries.h"
#include "model/track_evaluation.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QLineEdit>
#include <QMenu>
#include <QMimeData>
#include <QSignalSpy>
#include <QStyle>
#include <QTest>
#include <QTreeView>
#include <QUndoStack>

#include <Eigen/Geometry>

#include <functional>
#include <memory>
#include <set>
#include <vector>

using namespace gyre;

namespace {

// A joint of the rig: keys at times of its own, turning and moving differently from every other joint.
// The top-level objects stand a few units from the origin, away from the sample's block.
model::SceneObject joint(model::ObjectId id, const char* name, model::ObjectId parent, double phase)
{
    const double away = parent == model::kNoObject ? 6.0 : 0.0;
    model::SceneObject object;
    object.id = id;
    object.name = QString::fromLatin1(name);
    object.parent = parent;
    for (const double time : {0.0, 0.3 + phase, 1.1 + phase / 2, 2.0}) {
        const Eigen::Vector3d axis = Eigen::Vector3d(1.0, phase, 2.0 - time).normalized();
        object.track.keys.push_back({time, {Eigen::Quaterniond(Eigen::AngleAxisd(phase + 0.9 * time, axis)), {time + away, phase + away, 0.5}}, true});
    }
    return object;
}

// A branching rig and a prop, batch ids 1 to 7: Hips (Spine (Head), LeftLeg (LeftFoot), RightLeg), Prop.
std::vector<model::SceneObject> rig()
{
    return {joint(1, "Hips", model::kNoObject, 0.1), joint(2, "Spine", 1, 0.2), joint(3, "Head", 2, 0.35),
            joint(4, "LeftLeg", 1, 0.5), joint(5, "LeftFoot", 4, 0.65), joint(6, "RightLeg", 1, 0.8),
            joint(7, "Prop", model::kNoObject, 0.95)};
}

// The world pose composed up the parent chain, each track evaluated on its own.
Pose worldPose(const model::Scene& scene, model::ObjectId id, double time)
{
    Pose world;
    for (const model::SceneObject* object = model::findObject(scene, id); object != nullptr;
         object = model::findObject(scene, object->parent))
        world = model::TrackMotion(object->track).at(time) * world;
    return world;
}

// The bundled sample with the rig imported into it, the outliner's model under test.
struct Session {
    app::MainWindow window;
    app::OutlinerPanel* outliner = nullptr;
    std::vector<model::ObjectId> rig; // scene ids, in the rig's batch order
    std::unique_ptr<QAbstractItemModelTester> tester;
    std::unique_ptr<QSignalSpy> resets;

    Session()
    {
        window.resize(1400, 900);
        window.show();
        window.openBundledSample();
        window.playback().pause();
        outliner = window.findChild<app::OutlinerPanel*>();
        tester = std::make_unique<QAbstractItemModelTester>(&outliner->sceneModel(),
                                                            QAbstractItemModelTester::FailureReportingMode::QtTest);
        auto* import = new model::ImportObjectsCommand(window.document(), ::rig());
        rig = import->ids();
        window.document().undoStack().push(import);
        resets = std::make_unique<QSignalSpy>(&outliner->sceneModel(), &QAbstractItemModel::modelReset);
    }

    model::Document& document() { return window.document(); }
    QUndoStack& stack() { return window.document().undoStack(); }
    QTreeView& tree() { return *outliner->tree(); }
    // The row of `id` as the tree shows it (through the filter), scrolled into view.
    QModelIndex shown(model::ObjectId id)
    {
        const QModelIndex index = outliner->filteredModel().mapFromSource(outliner->sceneModel().indexOf(id));
        if (index.isValid())
            tree().scrollTo(index);
        return index;
    }
    model::ObjectId objectAt(const QModelIndex& shownIndex)
    {
        return app::SceneTreeModel::objectAt(outliner->filteredModel().mapToSource(shownIndex));
    }
    void clickOn(model::ObjectId id)
    {
        QTest::mouseClick(tree().viewport(), Qt::LeftButton, Qt::NoModifier, tree().visualRect(shown(id)).center());
    }
    // A click on the check box at the start of the row, where the style puts it: a frame margin in.
    void clickCheckBoxOf(model::ObjectId id)
    {
        const QRect row = tree().visualRect(shown(id));
        QStyle* style = tree().style();
        const int margin = style->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, &tree()) + 1;
        const int indicator = style->pixelMetric(QStyle::PM_IndicatorWidth, nullptr, &tree());
        QTest::mouseClick(tree().viewport(), Qt::LeftButton, Qt::NoModifier,
                          QPoint(row.left() + margin + indicator / 2, row.center().y()));
    }
};

} // namespace

class TestOutliner : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }

    void theTreeIsTheDocumentsHierarchy()
    {
        Session session;
        const model::Scene& scene = session.document().scene();
        const app::SceneTreeModel& tree = session.outliner->sceneModel();
        // Every row: the object whose parent is the row's parent, siblings in scene order.
        std::size_t rows = 0;
        const std::function<void(const QModelIndex&)> check = [&](const QModelIndex& parent) {
            std::vector<model::ObjectId> expected;
            for (const model::SceneObject& object : scene.objects)
                if (object.parent == app::SceneTreeModel::objectAt(parent))
                    expected.push_back(object.id);
            QCOMPARE(tree.rowCount(parent), int(expected.size()));
            for (int row = 0; row < tree.rowCount(parent); ++row) {
                const QModelIndex index = tree.index(row, 0, parent);
                QCOMPARE(app::SceneTreeModel::objectAt(index), expected[std::size_t(row)]);
                QCOMPARE(index.data().toString(), session.document().object(expected[std::size_t(row)])->name);
                ++rows;
                check(index);
            }
        };
        check({});
        QCOMPARE(rows, scene.objects.size());
        QCOMPARE(rows, std::size_t{8}); // the sample's block and the rig
        QCOMPARE(tree.rowCount(tree.indexOf(session.rig[0])), 3); // Hips: Spine, LeftLeg, RightLeg
        QCOMPARE(tree.indexOf(session.rig[4]).parent(), tree.indexOf(session.rig[3])); // LeftFoot under LeftLeg
        // The dock is in the window and View ▸ Panels shows and hides it.
        auto* dock = qobject_cast<QDockWidget*>(session.outliner->parentWidget());
        QVERIFY(dock != nullptr && dock->isVisible());
        QAction* toggle = nullptr;
        for (QAction* action : session.window.findChild<QMenu*>(QStringLiteral("menuPanels"))->actions())
            if (action->text() == dock->windowTitle())
                toggle = action;
        QVERIFY(toggle != nullptr);
        toggle->trigger();
        QVERIFY(!dock->isVisible());
        toggle->trigger();
        QVERIFY(dock->isVisible());
        // Opening another project replaces the tree: the one change that resets the model.
        session.window.openSample(QStringLiteral(":/samples/pendulum.gyre"));
        QCOMPARE(session.resets->count(), 1);
        QCOMPARE(tree.rowCount(), 1);
        QCOMPARE(tree.index(0, 0).data().toString(), session.document().scene().objects.front().name);
    }

    void selectionIsInStepWithTheViewportBothWays()
    {
        Session session;
        QVERIFY(QTest::qWaitForWindowExposed(&session.window));
        app::Selection& selection = session.window.selection();
        // The tree sets the app's selection, which the viewport draws.
        session.clickOn(session.rig[4]);
        QCOMPARE(selection.object(), session.rig[4]);
        // The app's selection, set elsewhere, shows in the tree, its collapsed ancestors expanded.
        session.tree().collapseAll();
        selection.selectObject(session.rig[2]);
        QCOMPARE(session.objectAt(session.tree().currentIndex()), session.rig[2]);
        QCOMPARE(session.tree().selectionModel()->selectedRows().size(), 1);
        QVERIFY(session.tree().isExpanded(session.shown(session.rig[1])));
        // A click on the sample's block in the viewport, the rig's import undone, selects it in the tree.
        session.stack().undo();
        auto* viewport = session.window.findChild<app::Viewport*>();
        const model::ObjectId block = session.document().scene().objects.front().id;
        selection.clear();
        QVERIFY(session.tree().selectionModel()->selectedRows().isEmpty());
        session.document().setCurrentTime(0.0);
        QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, viewport->objectScreenPosition(block)->toPoint());
        QCOMPARE(selection.object(), block);
        QCOMPARE(session.objectAt(session.tree().currentIndex()), block);
        // Selecting in the tree the object already selected keeps its selected key.
        selection.selectKey(block, 2);
        session.clickOn(block);
        QCOMPARE(selection.key(), std::optional<std::size_t>(2));
    }

    void renamesInPlaceInOneUndoStep()
    {
        Session session;
        session.window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&session.window));
        session.clickOn(session.rig[1]);
        const int steps = session.stack().count();
        QTest::keyClick(&session.tree(), Qt::Key_F2);
        auto* editor = qobject_cast<QLineEdit*>(QApplication::focusWidget());
        QVERIFY(editor != nullptr);
        QCOMPARE(editor->text(), QStringLiteral("Spine"));
        editor->selectAll();
        QTest::keyClicks(editor, QStringLiteral("Chest"));
        QTest::keyClick(editor, Qt::Key_Return);
        // The delegate commits the editor's text from the event loop.
        QTRY_COMPARE(session.document().object(session.rig[1])->name, QStringLiteral("Chest"));
        QCOMPARE(session.shown(session.rig[1]).data().toString(), QStringLiteral("Chest"));
        QCOMPARE(session.stack().count(), steps + 1);
        session.stack().undo();
        QCOMPARE(session.document().object(session.rig[1])->name, QStringLiteral("Spine"));
        QCOMPARE(session.shown(session.rig[1]).data().toString(), QStringLiteral("Spine"));
        QCOMPARE(session.resets->count(), 0);
    }

    void theCheckBoxHidesAnObjectFromTheViewportInOneUndoStep()
    {
        Session session;
        session.window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&session.window));
        session.stack().undo(); // the rig's import: the sample's block alone, in front of the camera
        auto* viewport = session.window.findChild<app::Viewport*>();
        const model::ObjectId block = session.document().scene().objects.front().id;
        session.document().setCurrentTime(0.0);
        // Where the block is on screen now: the camera follows the scene, so asked before each click.
        const auto onBlock = [&] { return viewport->objectScreenPosition(block)->toPoint(); };
        session.clickOn(block);
        QCOMPARE(session.shown(block).data(Qt::CheckStateRole).value<Qt::CheckState>(), Qt::Checked);
        const int steps = session.stack().index(); // the rig's import, undone, goes when a step is pushed
        session.clickCheckBoxOf(block);
        QVERIFY(!session.document().object(block)->visible);
        QCOMPARE(session.shown(block).data(Qt::CheckStateRole).value<Qt::CheckState>(), Qt::Unchecked);
        QCOMPARE(session.stack().index(), steps + 1);
        QCOMPARE(session.stack().count(), steps + 1);
        QCOMPARE(session.stack().undoText(), QStringLiteral("Hide Object"));
        // Hidden, the block is not picked: a click where it stands selects nothing.
        session.window.selection().clear();
        QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, onBlock());
        QCOMPARE(session.window.selection().object(), model::kNoObject);
        session.stack().undo();
        QVERIFY(session.document().object(block)->visible);
        QCOMPARE(session.shown(block).data(Qt::CheckStateRole).value<Qt::CheckState>(), Qt::Checked);
        QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, onBlock());
        QCOMPARE(session.window.selection().object(), block);
        QCOMPARE(session.resets->count(), 0);
    }

    void deleteRemovesTheObjectInOneUndoStep()
    {
        Session session;
        session.window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&session.window));
        const std::size_t objects = session.document().scene().objects.size();
        const std::size_t blockKeys = session.document().scene().objects.front().track.keys.size();
        session.clickOn(session.rig[3]); // LeftLeg, with LeftFoot under it
        const int steps = session.stack().count();
        QTest::keyClick(&session.tree(), Qt::Key_Delete);
        QCOMPARE(session.document().scene().objects.size(), objects - 2);
        QVERIFY(session.document().object(session.rig[3]) == nullptr);
        QVERIFY(!session.outliner->sceneModel().indexOf(session.rig[4]).isValid());
        QCOMPARE(session.outliner->sceneModel().rowCount(session.outliner->sceneModel().indexOf(session.rig[0])), 2);
        QCOMPARE(session.stack().count(), steps + 1);
        // Delete in the tree deletes objects, not Edit ▸ Delete Keyframe's key.
        QCOMPARE(session.document().scene().objects.front().track.keys.size(), blockKeys);
        session.stack().undo();
        QCOMPARE(session.document().scene().objects.size(), objects);
        QCOMPARE(session.outliner->sceneModel().indexOf(session.rig[4]).parent(), session.outliner->sceneModel().indexOf(session.rig[3]));
        // Several at once, one step.
        session.clickOn(session.rig[2]);
        QTest::mouseClick(session.tree().viewport(), Qt::LeftButton, Qt::ControlModifier,
                          session.tree().visualRect(session.shown(session.rig[6])).center());
        QTest::keyClick(&session.tree(), Qt::Key_Delete);
        QCOMPARE(session.document().scene().objects.size(), objects - 2);
        QCOMPARE(session.stack().count(), steps + 1);
        session.stack().undo();
        QCOMPARE(session.document().scene().objects.size(), objects);
        QCOMPARE(session.resets->count(), 0);
    }

    void droppingOnAnotherObjectKeepsTheWorldPoseAtEveryKey()
    {
        Session session;
        const model::Scene& scene = session.document().scene();
        QAbstractItemModel& shownModel = session.outliner->filteredModel();
        const model::ObjectId leftLeg = session.rig[3];
        const model::ObjectId leftFoot = session.rig[4];
        const model::ObjectId head = session.rig[2];
        // The world poses of an object at the keys of LeftLeg, the object dropped.
        const std::vector<model::Keyframe> legKeys = model::findObject(scene, leftLeg)->track.keys;
        const auto posesAtKeys = [&scene, &legKeys](model::ObjectId id) {
            std::vector<Pose> poses;
            for (const model::Keyframe& key : legKeys)
                poses.push_back(worldPose(scene, id, key.time));
            return poses;
        };
        const auto same = [](const std::vector<Pose>& a, const std::vector<Pose>& b) {
            if (a.size() != b.size())
                return false;
            for (std::size_t i = 0; i < a.size(); ++i)
                if (a[i].orientation.angularDistance(b[i].orientation) > 1e-9 || (a[i].position - b[i].position).norm() > 1e-9) {
                    qWarning("key %zu: %g rad, %g apart", i, a[i].orientation.angularDistance(b[i].orientation),
                             (a[i].position - b[i].position).norm());
                    return false;
                }
            return true;
        };
        const std::vector<Pose> legBefore = posesAtKeys(leftLeg);
        const std::vector<Pose> footBefore = posesAtKeys(leftFoot);

        // LeftLeg dropped on Head, as the view drops it.
        std::unique_ptr<QMimeData> dragged(shownModel.mimeData({session.shown(leftLeg)}));
        QVERIFY(shownModel.canDropMimeData(dragged.get(), Qt::MoveAction, -1, -1, session.shown(head)));
        QSignalSpy moved(&session.outliner->sceneModel(), &QAbstractItemModel::rowsMoved);
        const int steps = session.stack().count();
        QVERIFY(shownModel.dropMimeData(dragged.get(), Qt::MoveAction, -1, -1, session.shown(head)));
        QCOMPARE(session.stack().count(), steps + 1);
        QCOMPARE(model::findObject(scene, leftLeg)->parent, head);
        QCOMPARE(session.outliner->sceneModel().indexOf(leftLeg).parent(), session.outliner->sceneModel().indexOf(head));
        QCOMPARE(moved.count(), 1);
        QVERIFY(same(posesAtKeys(leftLeg), legBefore));
        QVERIFY(same(posesAtKeys(leftFoot), footBefore)); // its child, relative to it, moves with it
        // Re-expressed, not kept: the keys relative to the parent changed.
        QVERIFY(!model::findObject(scene, leftLeg)->track.keys[1].pose.position.isApprox(legKeys[1].pose.position));
        session.stack().undo();
        QCOMPARE(model::findObject(scene, leftLeg)->parent, session.rig[0]);
        const std::vector<model::Keyframe>& restored = model::findObject(scene, leftLeg)->track.keys;
        QCOMPARE(restored.size(), legKeys.size());
        for (std::size_t i = 0; i < legKeys.size(); ++i) // exactly the keys from before
            QVERIFY(restored[i].pose.orientation.coeffs() == legKeys[i].pose.orientation.coeffs()
                    && restored[i].pose.position == legKeys[i].pose.position);
        QCOMPARE(session.outliner->sceneModel().indexOf(leftLeg).parent(), session.outliner->sceneModel().indexOf(session.rig[0]));

        // Onto empty space: no parent, the world pose kept all the same.
        dragged.reset(shownModel.mimeData({session.shown(leftLeg)}));
        QVERIFY(shownModel.dropMimeData(dragged.get(), Qt::MoveAction, -1, -1, QModelIndex()));
        QCOMPARE(model::findObject(scene, leftLeg)->parent, model::kNoObject);
        QVERIFY(same(posesAtKeys(leftLeg), legBefore));
        session.stack().undo();

        // Two objects at once are one undo step; an object cannot go under its own descendant.
        dragged.reset(shownModel.mimeData({session.shown(leftLeg), session.shown(session.rig[5])}));
        QVERIFY(shownModel.dropMimeData(dragged.get(), Qt::MoveAction, -1, -1, session.shown(session.rig[6])));
        QCOMPARE(session.stack().count(), steps + 1);
        QCOMPARE(model::findObject(scene, session.rig[5])->parent, session.rig[6]);
        QVERIFY(same(posesAtKeys(leftLeg), legBefore));
        session.stack().undo();
        const int undone = session.stack().index();
        dragged.reset(shownModel.mimeData({session.shown(session.rig[0])}));
        QVERIFY(!shownModel.canDropMimeData(dragged.get(), Qt::MoveAction, -1, -1, session.shown(leftFoot)));
        QVERIFY(!shownModel.dropMimeData(dragged.get(), Qt::MoveAction, -1, -1, session.shown(leftFoot)));
        QCOMPARE(session.stack().index(), undone);
        QCOMPARE(session.stack().count(), steps + 1); // the undone drop, not discarded by a new step
        QCOMPARE(session.resets->count(), 0);
    }

    void theFilterShowsMatchesWithTheirAncestors()
    {
        Session session;
        QTest::keyClicks(session.outliner->filterBox(), QStringLiteral("lEg"));
        // What should show, from the document: names containing "leg", any case, and their ancestors.
        std::set<model::ObjectId> expected;
        const model::Scene& scene = session.document().scene();
        for (const model::SceneObject& object : scene.objects)
            if (object.name.contains(QStringLiteral("leg"), Qt::CaseInsensitive))
                for (const model::SceneObject* shown = &object; shown != nullptr; shown = model::findObject(scene, shown->parent))
                    expected.insert(shown->id);
        QCOMPARE(expected.size(), std::size_t{3}); // LeftLeg, RightLeg and Hips
        std::set<model::ObjectId> shown;
        const QAbstractItemModel& filtered = session.outliner->filteredModel();
        const std::function<void(const QModelIndex&)> collect = [&](const QModelIndex& parent) {
            for (int row = 0; row < filtered.rowCount(parent); ++row) {
                const QModelIndex index = filtered.index(row, 0, parent);
                shown.insert(session.objectAt(index));
                QVERIFY(session.tree().isExpanded(parent) || !parent.isValid());
                collect(index);
            }
        };
        collect({});
        QVERIFY(shown == expected);
        session.outliner->filterBox()->clear();
        QCOMPARE(filtered.rowCount(), 3); // the block, Hips and Prop
    }
};

QTEST_MAIN(TestOutliner)
#include "tst_outliner.moc"
