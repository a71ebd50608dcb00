// Key editing in the real main window, driven with the mouse and the keyboard: several keys and
// objects selected (timeline, Outliner), deleted and keyed at once, copied and pasted as keys or as a
// pose through the clipboard, and moved together on the timeline's dope-sheet rows. Each edit is one
// undo step that undo takes back whole. The scene: "Top" keyed at 0, 1, 2, 3 s turning about z,
// "Leaf" keyed at 0, 2, 4 s turning about x, 30 frames a second over 0 to 10 s.

#include "app/main_window.h"
#include "app/outliner/outliner_panel.h"
#include "app/timeline_widget.h"
#include "app/viewport/viewport.h"
#include "gui_test_support.h"
#include "model/commands/delete_object_command.h"
#include "model/key_clipboard.h"
#include "model/project_file.h"
#include "model/track_evaluation.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QJsonDocument>
#include <QMimeData>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeView>

#include <Eigen/Geometry>

#include <cmath>
#include <memory>
#include <numbers>

using namespace gyre;

namespace {

constexpr model::ObjectId kTop = 1;
constexpr model::ObjectId kLeaf = 2;

model::Keyframe keyAbout(double time, const Eigen::Vector3d& axis, double degrees)
{
    model::Keyframe key;
    key.time = time;
    key.pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0, axis));
    key.pose.position = axis;
    return key;
}

model::Scene twoObjects()
{
    model::Scene scene;
    scene.fps = 30.0;
    scene.endTime = 10.0;
    model::SceneObject top{kTop, QStringLiteral("Top"), nullptr, model::kNoObject, {}, true};
    for (int k = 0; k < 4; ++k)
        top.track.keys.edit().push_back(keyAbout(k, Eigen::Vector3d::UnitZ(), 30.0 * k));
    model::SceneObject leaf{kLeaf, QStringLiteral("Leaf"), nullptr, model::kNoObject, {}, true};
    for (int k = 0; k < 3; ++k)
        leaf.track.keys.edit().push_back(keyAbout(2.0 * k, Eigen::Vector3d::UnitX(), 45.0 * k));
    scene.objects = {top, leaf};
    scene.nextObjectId = 3;
    return scene;
}

bool sameRotation(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    return std::abs(std::abs(a.dot(b)) - 1.0) < 1e-12;
}

} // namespace

class TestKeyEditing : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }

    void init()
    {
        const QString path = dir_.filePath(QStringLiteral("two.gyre"));
        model::writeProject(path, twoObjects());
        window_ = test::showMainWindow(test::WindowWait::Active,
                                       [&path](app::MainWindow& window) { QVERIFY(window.openProject(path)); });
        timeline_ = window_->findChild<app::TimelineWidget*>();
        QVERIFY(timeline_ != nullptr && timeline_->isVisible());
        timeline_->setFocus();
        QApplication::clipboard()->clear();
    }

    void cleanup() { window_.reset(); }

    void copyingAPoseOntoAnotherObjectKeysItThere()
    {
        select(kTop);
        document().setCurrentTime(1.5);
        QVERIFY(selection().keys().empty());
        QTest::keyClick(timeline_, Qt::Key_C, Qt::ControlModifier);
        const Pose pose = document().motion(kTop)->motion().at(1.5);
        // The clipboard's text is the readable JSON.
        const QJsonDocument text = QJsonDocument::fromJson(QApplication::clipboard()->text().toUtf8());
        QCOMPARE(text["format"].toString(), QStringLiteral("gyre-keys"));
        QCOMPARE(text["pose"].toBool(), true);

        select(kLeaf);
        document().setCurrentTime(3.0);
        const int steps = stack().count();
        QTest::keyClick(timeline_, Qt::Key_V, Qt::ControlModifier);
        QCOMPARE(stack().count(), steps + 1);
        QCOMPARE(keys(kLeaf).size(), std::size_t{4});
        const model::Keyframe& pasted = keys(kLeaf)[2];
        QCOMPARE(pasted.time, 3.0);
        QVERIFY(sameRotation(pasted.pose.orientation, pose.orientation));
        QVERIFY(pasted.pose.position.isApprox(pose.position));
        QVERIFY(sameRotation(document().motion(kLeaf)->motion().at(3.0).orientation, pose.orientation));
        QVERIFY(selection().isKeySelected(kLeaf, 2));

        stack().undo();
        QCOMPARE(keys(kLeaf).size(), std::size_t{3});
        QCOMPARE(keys(kLeaf)[2].time, 4.0);
    }

    void threeCopiedKeysPasteAtAnotherTime()
    {
        select(kTop);
        // Shift+click three markers.
        for (std::size_t key : {1, 2, 3})
            QTest::mouseClick(timeline_, Qt::LeftButton, Qt::ShiftModifier, *timeline_->keyMarkerCentre(key));
        QCOMPARE(selection().keysOf(kTop), (std::vector<std::size_t>{1, 2, 3}));
        QTest::keyClick(timeline_, Qt::Key_C, Qt::ControlModifier);

        document().setCurrentTime(6.0);
        const std::vector<model::Keyframe> before = keys(kTop);
        const int steps = stack().count();
        QTest::keyClick(timeline_, Qt::Key_V, Qt::ControlModifier);
        QCOMPARE(stack().count(), steps + 1);
        const std::vector<model::Keyframe> after = keys(kTop);
        QCOMPARE(after.size(), std::size_t{7});
        for (std::size_t k = 0; k < 3; ++k) {
            QCOMPARE(after[4 + k].time, 6.0 + static_cast<double>(k));
            QVERIFY(sameRotation(after[4 + k].pose.orientation, before[1 + k].pose.orientation));
        }
        QCOMPARE(selection().keysOf(kTop), (std::vector<std::size_t>{4, 5, 6}));

        // Pasted again one second earlier, they replace the keys at the same times.
        document().setCurrentTime(5.0);
        QTest::keyClick(timeline_, Qt::Key_V, Qt::ControlModifier);
        QCOMPARE(keys(kTop).size(), std::size_t{8});
        QVERIFY(sameRotation(keys(kTop)[5].pose.orientation, before[2].pose.orientation)); // at 6 s

        stack().undo();
        stack().undo();
        QCOMPARE(keys(kTop).size(), before.size());
    }

    void textThatIsNotGyresKeysChangesNothing()
    {
        select(kTop);
        document().setCurrentTime(4.0);
        const QByteArray project = model::projectBytes(document().scene());
        const int steps = stack().count();
        // Any text, then Gyre's format with one bad key after a good one: neither pastes anything.
        QByteArray halfGood = model::keyClipboardJson({false, {{QStringLiteral("Top"), {keys(kTop)[0], keys(kTop)[1]}}}});
        const QByteArray good("\"constrained\": true");
        halfGood.replace(halfGood.lastIndexOf(good), good.size(), "\"constrained\": 3");
        for (const QByteArray& text : {QByteArray("not keys at all"), QByteArray("{\"format\": 1}"), halfGood}) {
            window_->statusBar()->clearMessage();
            QApplication::clipboard()->setText(QString::fromUtf8(text));
            QTest::keyClick(timeline_, Qt::Key_V, Qt::ControlModifier);
            QCOMPARE(stack().count(), steps);
            QCOMPARE(model::projectBytes(document().scene()), project);
            QVERIFY2(window_->statusBar()->currentMessage().startsWith(QStringLiteral("Cannot paste")), text.constData());
        }
    }

    void boxSelectThenDeleteRemovesExactlyThoseKeys()
    {
        select(kTop);
        const int y = timeline_->keyLaneRect().center().y();
        const auto xAt = [&](double seconds) { return timeline_->xForTime(seconds); };
        // A box from between the keys at 0 and 1 s to between those at 2 and 3 s.
        test::dragAlong(timeline_, test::straightPath(QPointF(xAt(0.5), y - 10), QPointF(xAt(2.5), y + 10), 8));
        QCOMPARE(selection().keysOf(kTop), (std::vector<std::size_t>{1, 2}));
        QCOMPARE(keys(kTop).size(), std::size_t{4}); // a box, not a scrub or a drag of keys

        const int steps = stack().count();
        QTest::keyClick(timeline_, Qt::Key_X);
        QCOMPARE(stack().count(), steps + 1);
        QCOMPARE(keys(kTop).size(), std::size_t{2});
        QCOMPARE(keys(kTop)[0].time, 0.0);
        QCOMPARE(keys(kTop)[1].time, 3.0);
        QVERIFY(selection().keys().empty());
        stack().undo();
        QCOMPARE(keys(kTop).size(), std::size_t{4});
        QCOMPARE(keys(kTop)[2].time, 2.0);
    }

    void insertKeyKeysEverySelectedObject()
    {
        // Top, then Ctrl+click Leaf in the Outliner.
        auto* outliner = window_->findChild<app::OutlinerPanel*>();
        QVERIFY(outliner != nullptr);
        QTreeView* tree = outliner->tree();
        const auto rowOf = [&](model::ObjectId id) {
            return tree->visualRect(outliner->filteredModel().mapFromSource(outliner->sceneModel().indexOf(id))).center();
        };
        QTest::mouseClick(tree->viewport(), Qt::LeftButton, Qt::NoModifier, rowOf(kTop));
        QTest::mouseClick(tree->viewport(), Qt::LeftButton, Qt::ControlModifier, rowOf(kLeaf));
        QCOMPARE(selection().objects(), (std::vector<model::ObjectId>{kTop, kLeaf}));
        QCOMPARE(selection().object(), kLeaf);

        document().setCurrentTime(2.5);
        const Pose top = document().motion(kTop)->motion().at(2.5);
        const Pose leaf = document().motion(kLeaf)->motion().at(2.5);
        const int steps = stack().count();
        timeline_->setFocus();
        QTest::keyClick(timeline_, Qt::Key_K);
        QCOMPARE(stack().count(), steps + 1);
        QCOMPARE(keys(kTop).size(), std::size_t{5});
        QCOMPARE(keys(kLeaf).size(), std::size_t{4});
        QCOMPARE(keys(kTop)[3].time, 2.5);
        QCOMPARE(keys(kLeaf)[2].time, 2.5);
        QVERIFY(sameRotation(keys(kTop)[3].pose.orientation, top.orientation));
        QVERIFY(sameRotation(keys(kLeaf)[2].pose.orientation, leaf.orientation));
        QCOMPARE(selection().key(), std::optional<std::size_t>(2)); // Leaf's, the active object's
        QVERIFY(selection().isKeySelected(kTop, 3));
        stack().undo();
        QCOMPARE(keys(kTop).size(), std::size_t{4});
        QCOMPARE(keys(kLeaf).size(), std::size_t{3});
    }

    void ctrlClickInTheViewportAddsAndRemovesObjects()
    {
        auto* viewport = window_->findChild<app::Viewport*>();
        QVERIFY(viewport != nullptr);
        select(kTop);
        const std::optional<QPointF> leaf = viewport->objectScreenPosition(kLeaf);
        const std::optional<QPointF> top = viewport->objectScreenPosition(kTop);
        QVERIFY(leaf && top);
        QTest::mouseClick(viewport, Qt::LeftButton, Qt::ControlModifier, leaf->toPoint());
        QCOMPARE(selection().objects(), (std::vector<model::ObjectId>{kTop, kLeaf}));
        QCOMPARE(selection().object(), kLeaf);
        QCOMPARE(timeline_->rows(), (std::vector<model::ObjectId>{kTop, kLeaf}));
        QTest::mouseClick(viewport, Qt::LeftButton, Qt::ControlModifier, top->toPoint());
        QCOMPARE(selection().objects(), std::vector<model::ObjectId>{kLeaf});
        // A plain click selects one object again.
        QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, top->toPoint());
        QCOMPARE(selection().objects(), std::vector<model::ObjectId>{kTop});
    }

    void selectedKeysOfTwoObjectsMoveTogetherOnTheDopeSheet()
    {
        selection().selectObjects({kTop, kLeaf}, kTop);
        QCOMPARE(timeline_->rows(), (std::vector<model::ObjectId>{kTop, kLeaf}));
        // Top's key at 1 s, then Leaf's at 2 s with Shift, each in its own row.
        QTest::mouseClick(timeline_, Qt::LeftButton, Qt::NoModifier, *timeline_->keyMarkerCentre(kTop, 1));
        QTest::mouseClick(timeline_, Qt::LeftButton, Qt::ShiftModifier, *timeline_->keyMarkerCentre(kLeaf, 1));
        QCOMPARE(selection().keys(), (std::set<app::KeyRef>{{kTop, 1}, {kLeaf, 1}}));

        const int steps = stack().count();
        const double pixelsPerSecond = timeline_->xForTime(1.0) - timeline_->xForTime(0.0);
        const QPointF from = *timeline_->keyMarkerCentre(kTop, 1);
        test::dragAlong(timeline_, test::straightPath(from, from + QPointF(0.5 * pixelsPerSecond, 0), 10));
        QCOMPARE(stack().count(), steps + 1);
        QCOMPARE(keys(kTop)[1].time, 1.5);
        QCOMPARE(keys(kLeaf)[1].time, 2.5);

        // Far to the right, both stop where Top's key would come within a frame of its neighbour at 2 s.
        const QPointF again = *timeline_->keyMarkerCentre(kTop, 1);
        test::dragAlong(timeline_, test::straightPath(again, again + QPointF(3.0 * pixelsPerSecond, 0), 10));
        QCOMPARE(stack().count(), steps + 2);
        QCOMPARE(keys(kTop)[1].time, 59.0 / 30.0);
        QCOMPARE(keys(kLeaf)[1].time, 89.0 / 30.0);
        QCOMPARE(keys(kTop)[2].time, 2.0);

        stack().undo();
        QCOMPARE(keys(kTop)[1].time, 1.5);
        stack().undo();
        QCOMPARE(keys(kTop)[1].time, 1.0);
        QCOMPARE(keys(kLeaf)[1].time, 2.0);
        // A click on one of the selected keys, without a drag, selects it alone.
        QTest::mouseClick(timeline_, Qt::LeftButton, Qt::NoModifier, *timeline_->keyMarkerCentre(kLeaf, 1));
        QCOMPARE(selection().keys(), (std::set<app::KeyRef>{{kLeaf, 1}}));
        QCOMPARE(selection().object(), kLeaf);
    }

    void selectAllAndNoneAndTheSelectionFollowsTheDocument()
    {
        select(kTop);
        QTest::keyClick(timeline_, Qt::Key_A, Qt::ControlModifier);
        QCOMPARE(selection().keysOf(kTop), (std::vector<std::size_t>{0, 1, 2, 3}));
        QTest::keyClick(timeline_, Qt::Key_A, Qt::AltModifier);
        QVERIFY(selection().keys().empty());

        // Keys that an undo takes away leave the selection; so does a deleted object with its keys.
        selection().selectObjects({kTop, kLeaf}, kTop);
        document().setCurrentTime(5.0);
        QTest::keyClick(timeline_, Qt::Key_Insert);
        QCOMPARE(selection().keys(), (std::set<app::KeyRef>{{kTop, 4}, {kLeaf, 3}}));
        stack().undo();
        QVERIFY(selection().keys().empty());
        selection().selectKeys({{kTop, 1}, {kLeaf, 2}}, false, app::KeyRef{kLeaf, 2});
        QCOMPARE(selection().object(), kLeaf);
        document().push(new model::DeleteObjectCommand(document(), kLeaf));
        QCOMPARE(selection().objects(), std::vector<model::ObjectId>{kTop});
        QCOMPARE(selection().object(), kTop);
        QCOMPARE(selection().keys(), (std::set<app::KeyRef>{{kTop, 1}}));
        QCOMPARE(timeline_->rows(), std::vector<model::ObjectId>{kTop});
    }

private:
    model::Document& document() { return window_->document(); }
    QUndoStack& stack() { return window_->document().undoStack(); }
    app::Selection& selection() { return window_->selection(); }
    const std::vector<model::Keyframe>& keys(model::ObjectId id) { return document().object(id)->track.keys; }
    void select(model::ObjectId id) { selection().selectObject(id); }

    QTemporaryDir dir_;
    std::unique_ptr<app::MainWindow> window_;
    app::TimelineWidget* timeline_ = nullptr;
};

QTEST_MAIN(TestKeyEditing)
#include "tst_key_editing.moc"
