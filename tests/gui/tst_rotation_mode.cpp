// An object's rotation mode in the real window: the Inspector's Rotation Mode chooser puts the object in Euler
// mode (one undo step), the angle fields then come first and store what is typed, so two keys typed 0° and 720°
// about z are two turns; the bake of that spin, unwrapped, grows through 360° at the middle and ends at 720°, as
// the automatic-tangent cubic written out here says. In the Graph Editor the z channel is a ramp to 720°, and
// dragging its key sets the stored angle, in one undo step. Motion ▸ Euler Filter makes the stored angles of
// every selected Euler-mode object continuous, in one undo step, and leaves their orientations; with keys
// selected, it filters only those, each made continuous with the key before it, and leaves the others bit for bit.

#include "app/graph_editor/graph_editor_panel.h"
#include "app/main_window.h"
#include "gui_test_support.h"
#include "inspected_window.h"
#include "model/commands/import_objects_command.h"
#include "model/commands/replace_keyframes_command.h"
#include "model/track_evaluation.h"

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QLayout>
#include <QSignalSpy>
#include <QTest>
#include <qcustomplot.h>

#include <cmath>
#include <memory>
#include <numbers>

using namespace gyre;
using model::Channel;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegrees = 180.0 / kPi;
constexpr double kFirst = 0.5; // the keys' times, seconds
constexpr double kLast = 2.5;

model::SceneObject unturnedBlock()
{
    model::SceneObject object;
    object.id = 1;
    object.name = QStringLiteral("spinner");
    for (const double time : {kFirst, kLast})
        object.track.keys.push_back(model::Keyframe{time, Pose{}, true});
    return object;
}

// The z angle of the euler-cubic spin from 0° to 720°: flat at both keys (the first and last), so with
// u = (t − t₀)/(t₁ − t₀) the Hermite cubic is 720°·(3u² − 2u³).
double spinDegrees(double time)
{
    const double u = std::clamp((time - kFirst) / (kLast - kFirst), 0.0, 1.0);
    return 720.0 * (3.0 * u * u - 2.0 * u * u * u);
}

// An object in Euler mode (extrinsic xyz) whose keys, one a second, store these angles in degrees; `id` is its
// id in an import batch.
model::SceneObject eulerKeyed(model::ObjectId id, const QString& name, const std::vector<Eigen::Vector3d>& degrees)
{
    model::SceneObject object;
    object.id = id;
    object.name = name;
    object.track.rotationMode = {model::RotationMode::Kind::Euler, {}};
    object.track.interpolation = InterpolationMethod::EulerCubic;
    for (std::size_t key = 0; key < degrees.size(); ++key) {
        const Eigen::Vector3d angles = degrees[key] / kDegrees;
        model::Keyframe keyframe{double(key), Pose{quaternionFromEulerAngles(angles, {}), Eigen::Vector3d::Zero()}, true};
        keyframe.eulerAngles = angles;
        object.track.keys.push_back(keyframe);
    }
    return object;
}

} // namespace

class TestRotationMode : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }

    void init()
    {
        window_ = test::showMainWindow(test::WindowWait::Active, [this](app::MainWindow& window) {
            object_ = test::importAtStart(window.document(), {unturnedBlock()}, model::TimeRange{24.0, 0.0, 3.0}).front();
        });
        window_->selection().selectKey(object_, 0);
    }

    void cleanup() { window_.reset(); }

    void aSpinTypedInEulerModeBakesTwoTurns()
    {
        model::Document& document = window_->document();
        auto* mode = window_->findChild<QComboBox*>(QStringLiteral("rotationModeCombo"));
        QVERIFY(mode != nullptr);
        test::choose(mode, mode->findText(QStringLiteral("Euler angles")));
        QCOMPARE(document.undoStack().count(), 1);
        QCOMPARE(document.undoStack().undoText(), QStringLiteral("Set Rotation Mode"));
        const model::MotionTrack& track = document.object(object_)->track;
        QVERIFY(track.rotationMode.isEuler());
        QCOMPARE(track.interpolation, InterpolationMethod::EulerCubic);
        QCOMPARE(*track.keys[0].eulerAngles, Eigen::Vector3d::Zero());

        // The angle fields come before the quaternion's.
        auto* euler = window_->findChild<QWidget*>(QStringLiteral("eulerGroup"));
        auto* quaternion = window_->findChild<QWidget*>(QStringLiteral("quaternionGroup"));
        QLayout* fields = euler->parentWidget()->layout();
        QVERIFY(fields->indexOf(euler) < fields->indexOf(quaternion));

        auto* third = window_->findChild<QLineEdit*>(QStringLiteral("euler3Edit"));
        window_->selection().selectKey(object_, 0);
        test::enter(third, QStringLiteral("0"));
        window_->selection().selectKey(object_, 1);
        test::enter(third, QStringLiteral("720"));
        QCOMPARE(document.undoStack().count(), 2); // 0 was already stored: no step
        QCOMPARE(*document.object(object_)->track.keys[1].eulerAngles, Eigen::Vector3d(0.0, 0.0, 720.0 / kDegrees));
        QCOMPARE(third->text(), QStringLiteral("720"));
        // The orientation is the identity, two whole turns.
        QVERIFY(std::abs(std::abs(document.object(object_)->track.keys[1].pose.orientation.w()) - 1.0) < 1e-12);

        const std::vector<model::TimedPose> baked =
            model::bakeTrack(document.object(object_)->track, {kFirst, kLast, 24.0});
        std::vector<Eigen::Quaterniond> rotations;
        for (const model::TimedPose& sample : baked)
            rotations.push_back(sample.pose.orientation);
        const std::vector<Eigen::Vector3d> unwrapped = unwrappedEulerAngles(rotations, {});
        double previous = -1.0;
        for (std::size_t i = 0; i < baked.size(); ++i) {
            const double degrees = unwrapped[i].z() * kDegrees;
            QVERIFY2(std::abs(degrees - spinDegrees(baked[i].time)) < 1e-6, qPrintable(QString::number(baked[i].time)));
            QVERIFY(degrees >= previous);
            previous = degrees;
            QVERIFY(unwrapped[i].head<2>().norm() < 1e-9);
        }
        // At the middle a whole turn (the identity) with one turn behind it; at the end two.
        const auto middle = std::find_if(baked.begin(), baked.end(),
                                         [](const model::TimedPose& sample) { return sample.time >= 1.5 - 1e-9; });
        QVERIFY(std::abs(middle->time - 1.5) < 1e-9);
        QVERIFY(std::abs(unwrapped[static_cast<std::size_t>(middle - baked.begin())].z() * kDegrees - 360.0) < 1e-6);
        QVERIFY(std::abs(std::abs(middle->pose.orientation.w()) - 1.0) < 1e-12);
        QVERIFY(std::abs(unwrapped.back().z() * kDegrees - 720.0) < 1e-6);

        document.undoStack().undo();
        QCOMPARE(*document.object(object_)->track.keys[1].eulerAngles, Eigen::Vector3d::Zero());
    }

    void draggingAKeyOnAnEulerChannelSetsItsStoredAngle()
    {
        model::Document& document = window_->document();
        auto* mode = window_->findChild<QComboBox*>(QStringLiteral("rotationModeCombo"));
        test::choose(mode, mode->findText(QStringLiteral("Euler angles")));
        window_->selection().selectKey(object_, 1);
        test::enter(window_->findChild<QLineEdit*>(QStringLiteral("euler3Edit")), QStringLiteral("720"));
        document.undoStack().clear();

        auto* panel = window_->findChild<app::GraphEditorPanel*>();
        QSignalSpy updated(panel, &app::GraphEditorPanel::curvesUpdated);
        auto* dock = window_->findChild<QDockWidget*>(QStringLiteral("graphEditorDock"));
        dock->toggleViewAction()->trigger();
        dock->raise();
        QVERIFY(updated.wait(5000));
        QTRY_VERIFY_WITH_TIMEOUT(panel->graph(Channel::EulerThird)->dataCount() > 0, 5000);
        // The z channel is the ramp the angles make, its keys at 0° and 720°.
        const QCPGraph* spin = panel->graph(Channel::EulerThird);
        for (int sample = 0; sample < spin->dataCount(); ++sample) {
            const double time = spin->data()->at(sample)->key;
            QVERIFY2(std::abs(spin->data()->at(sample)->value - spinDegrees(time)) < 1e-6, qPrintable(QString::number(time)));
        }
        QVERIFY(std::abs(panel->keyGraph(Channel::EulerThird)->data()->at(1)->value - 720.0) < 1e-6);

        QCustomPlot* plot = panel->plot();
        const QPointF key = QPointF(plot->xAxis->coordToPixel(kLast), plot->yAxis->coordToPixel(720.0)).toPoint();
        const QPointF to = key + QPointF(0.0, -30.0);
        const double raised = plot->yAxis->pixelToCoord(to.y()) - plot->yAxis->pixelToCoord(key.y());
        QVERIFY(raised > 1.0);
        test::dragAlong(plot, test::straightPath(key, to, 6));
        QCOMPARE(document.undoStack().count(), 1);
        QCOMPARE(document.undoStack().undoText(), QStringLiteral("Rotate Keyframe"));
        const Eigen::Vector3d stored = *document.object(object_)->track.keys[1].eulerAngles;
        QVERIFY2(std::abs(stored.z() * kDegrees - (720.0 + raised)) < 1e-6, qPrintable(QString::number(stored.z() * kDegrees)));
        QVERIFY(stored.head<2>().norm() < 1e-12);
        document.undoStack().undo();
        QCOMPARE(*document.object(object_)->track.keys[1].eulerAngles, Eigen::Vector3d(0.0, 0.0, 720.0 / kDegrees));
    }

    void theEulerFilterUnwrapsEverySelectedObjectsAnglesInOneStep()
    {
        model::Document& document = window_->document();
        // A spin about z through 0°, 170°, 190°, 350°, 500° stored wrapped, 350° as its twin (180°, 180°, 170°)
        // = (e1 + 180°, 180° − e2, e3 + 180°); a turn about x to 300° stored as −60° after 170°; and a tilt
        // whose angles are continuous already.
        const std::vector<Eigen::Vector3d> spin{{0, 0, 0}, {0, 0, 170}, {0, 0, -170}, {180, 180, 170}, {0, 0, 140}};
        const std::vector<Eigen::Vector3d> spinRamp{{0, 0, 0}, {0, 0, 170}, {0, 0, 190}, {0, 0, 350}, {0, 0, 500}};
        const std::vector<Eigen::Vector3d> tilt{{0, 0, 0}, {-60, 0, 0}, {-150, 0, 0}};
        const std::vector<Eigen::Vector3d> turn{{0, 0, 0}, {170, 0, 0}, {-60, 0, 0}};
        const std::vector<Eigen::Vector3d> turnRamp{{0, 0, 0}, {170, 0, 0}, {300, 0, 0}};
        const std::vector<model::ObjectId> ids = importAndSelect(
            {eulerKeyed(1, QStringLiteral("spin"), spin), eulerKeyed(2, QStringLiteral("turn"), turn), eulerKeyed(3, QStringLiteral("tilt"), tilt)});
        QAction* filter = eulerFilter();
        window_->selection().selectObjects({ids[2]}, ids[2]);
        QVERIFY(!filter->isEnabled()); // the tilt's angles are continuous already
        window_->selection().selectObjects({ids[2], ids[0], ids[1]}, ids[2]);
        QVERIFY(filter->isEnabled());
        const model::MotionTrack spinBefore = document.object(ids[0])->track;
        const model::MotionTrack turnBefore = document.object(ids[1])->track;

        filter->trigger();
        QCOMPARE(document.undoStack().count(), 1);
        QCOMPARE(document.undoStack().undoText(), QStringLiteral("Apply Euler Filter"));
        QVERIFY(!filter->isEnabled());
        const auto check = [&](model::ObjectId id, const model::MotionTrack& before, const std::vector<Eigen::Vector3d>& ramp) {
            const model::MotionTrack& after = document.object(id)->track;
            QVERIFY(after.rotationMode.isEuler());
            for (std::size_t key = 0; key < ramp.size(); ++key) {
                const Eigen::Vector3d degrees = *after.keys[key].eulerAngles * kDegrees;
                QVERIFY2((degrees - ramp[key]).norm() < 1e-9,
                         qPrintable(QStringLiteral("key %1: %2 %3 %4").arg(key).arg(degrees.x()).arg(degrees.y()).arg(degrees.z())));
                const double dot = after.keys[key].pose.orientation.dot(before.keys[key].pose.orientation);
                QVERIFY(std::abs(std::abs(dot) - 1.0) < 1e-12);
            }
        };
        check(ids[0], spinBefore, spinRamp);
        check(ids[1], turnBefore, turnRamp);
        check(ids[2], document.object(ids[2])->track, tilt);

        document.undoStack().undo();
        for (std::size_t key = 0; key < spin.size(); ++key)
            QCOMPARE(*document.object(ids[0])->track.keys[key].eulerAngles, *spinBefore.keys[key].eulerAngles);
        for (std::size_t key = 0; key < turn.size(); ++key)
            QCOMPARE(*document.object(ids[1])->track.keys[key].eulerAngles, *turnBefore.keys[key].eulerAngles);
        QVERIFY(filter->isEnabled());
    }

    void theEulerFilterFollowsEveryEditOfASelectedObject()
    {
        // Two continuous tracks selected: nothing to filter. The keys of the one that is not active are then
        // edited, the turn's 300° stored as −60°, and the edit undone and redone: the action follows each,
        // though each object's answer is remembered while its keys stay the same.
        model::Document& document = window_->document();
        const std::vector<Eigen::Vector3d> tilt{{0, 0, 0}, {-60, 0, 0}, {-150, 0, 0}};
        const std::vector<Eigen::Vector3d> turnRamp{{0, 0, 0}, {170, 0, 0}, {300, 0, 0}};
        const std::vector<model::ObjectId> ids =
            importAndSelect({eulerKeyed(1, QStringLiteral("tilt"), tilt), eulerKeyed(2, QStringLiteral("turn"), turnRamp)});
        QAction* filter = eulerFilter();
        QVERIFY(!filter->isEnabled());

        std::vector<model::Keyframe> keys = document.object(ids[1])->track.keys;
        keys[2].eulerAngles = Eigen::Vector3d(-60.0, 0.0, 0.0) / kDegrees;
        keys[2].pose.orientation = quaternionFromEulerAngles(*keys[2].eulerAngles, {});
        document.push(new model::ReplaceKeyframesCommand(document, {{ids[1], keys}}, model::ReplaceKeyframesCommand::Edit::Move));
        QVERIFY(filter->isEnabled());
        document.undoStack().undo();
        QVERIFY(!filter->isEnabled());
        document.undoStack().redo();
        QVERIFY(filter->isEnabled());
        // The tilt alone selected, then both again.
        window_->selection().selectObjects({ids[0]}, ids[0]);
        QVERIFY(!filter->isEnabled());
        window_->selection().selectObjects({ids[0], ids[1]}, ids[0]);
        QVERIFY(filter->isEnabled());
        // Other keys of the same, unchanged keys: the turn's 170°, continuous, then its −60°.
        window_->selection().selectKeys({{ids[1], 1}}, false);
        QVERIFY(!filter->isEnabled());
        window_->selection().selectKeys({{ids[1], 2}}, false);
        QVERIFY(filter->isEnabled());
    }

    void theEulerFilterOnSelectedKeysFiltersThoseAlone()
    {
        model::Document& document = window_->document();
        // The spin of theEulerFilterUnwrapsEverySelectedObjectsAnglesInOneStep and a key after it, stored wrapped;
        // the turn to 300° stored as −60°.
        const std::vector<Eigen::Vector3d> spin{{0, 0, 0}, {0, 0, 170}, {0, 0, -170}, {180, 180, 170}, {0, 0, 140}, {0, 0, -60}};
        const std::vector<Eigen::Vector3d> turn{{0, 0, 0}, {170, 0, 0}, {-60, 0, 0}};
        const std::vector<model::ObjectId> ids =
            importAndSelect({eulerKeyed(1, QStringLiteral("spin"), spin), eulerKeyed(2, QStringLiteral("turn"), turn)});
        QAction* filter = eulerFilter();
        // The spin's first key (none before it) and a key already continuous with the one before: nothing to do.
        window_->selection().selectKeys({{ids[0], 0}, {ids[0], 1}}, false);
        QVERIFY(!filter->isEnabled());
        // Keys 2 and 3 of the spin, a run: 3 follows 2 as filtered. Key 4 of the spin (140° after 350°) and the
        // turn's keys are not selected, so they stay as they are though they jump.
        window_->selection().selectKeys({{ids[0], 2}, {ids[0], 3}}, false);
        QVERIFY(filter->isEnabled());
        const model::MotionTrack spinBefore = document.object(ids[0])->track;
        const model::MotionTrack turnBefore = document.object(ids[1])->track;

        filter->trigger();
        QCOMPARE(document.undoStack().count(), 1);
        QCOMPARE(document.undoStack().undoText(), QStringLiteral("Apply Euler Filter"));
        const model::MotionTrack& after = document.object(ids[0])->track;
        const std::vector<Eigen::Vector3d> expected{{0, 0, 0}, {0, 0, 170}, {0, 0, 190}, {0, 0, 350}, {0, 0, 140}, {0, 0, -60}};
        for (std::size_t key = 0; key < spin.size(); ++key) {
            const Eigen::Vector3d degrees = *after.keys[key].eulerAngles * kDegrees;
            QVERIFY2((degrees - expected[key]).norm() < 1e-9,
                     qPrintable(QStringLiteral("key %1: %2 %3 %4").arg(key).arg(degrees.x()).arg(degrees.y()).arg(degrees.z())));
            const double dot = after.keys[key].pose.orientation.dot(spinBefore.keys[key].pose.orientation);
            QVERIFY(std::abs(std::abs(dot) - 1.0) < 1e-12);
            if (key == 2 || key == 3) {
                // Continuous with the key before: each angle within half a turn of it, in its hemisphere.
                const Eigen::Vector3d step = *after.keys[key].eulerAngles - *after.keys[key - 1].eulerAngles;
                QVERIFY(step.cwiseAbs().maxCoeff() < kPi);
                QVERIFY(after.keys[key].pose.orientation.dot(after.keys[key - 1].pose.orientation) >= 0.0);
            } else {
                QCOMPARE(after.keys[key].time, spinBefore.keys[key].time);
                QVERIFY(after.keys[key].pose.orientation.coeffs() == spinBefore.keys[key].pose.orientation.coeffs());
                QVERIFY(*after.keys[key].eulerAngles == *spinBefore.keys[key].eulerAngles);
            }
        }
        for (std::size_t key = 0; key < turn.size(); ++key) {
            QVERIFY(document.object(ids[1])->track.keys[key].pose.orientation.coeffs() ==
                    turnBefore.keys[key].pose.orientation.coeffs());
            QVERIFY(*document.object(ids[1])->track.keys[key].eulerAngles == *turnBefore.keys[key].eulerAngles);
        }

        // With no key selected, the whole tracks of the selected objects, as before, in one more undo step: the spin
        // on from 350° (140° → 500°, −60° → 660°) and the turn to 300°, their orientations the same rotations.
        window_->selection().deselectKeys();
        QVERIFY(filter->isEnabled());
        const model::MotionTrack spinKeysFiltered = document.object(ids[0])->track;
        filter->trigger();
        QCOMPARE(document.undoStack().count(), 2);
        QCOMPARE(document.undoStack().index(), 2);
        QCOMPARE(document.undoStack().undoText(), QStringLiteral("Apply Euler Filter"));
        QVERIFY(!filter->isEnabled());
        const auto expectRamp = [&](model::ObjectId id, const model::MotionTrack& before, const std::vector<Eigen::Vector3d>& ramp) {
            const model::MotionTrack& whole = document.object(id)->track;
            for (std::size_t key = 0; key < ramp.size(); ++key) {
                const Eigen::Vector3d degrees = *whole.keys[key].eulerAngles * kDegrees;
                QVERIFY2((degrees - ramp[key]).norm() < 1e-9,
                         qPrintable(QStringLiteral("key %1: %2 %3 %4").arg(key).arg(degrees.x()).arg(degrees.y()).arg(degrees.z())));
                QVERIFY(std::abs(std::abs(whole.keys[key].pose.orientation.dot(before.keys[key].pose.orientation)) - 1.0) < 1e-12);
                if (key > 0)
                    QVERIFY(whole.keys[key].pose.orientation.dot(whole.keys[key - 1].pose.orientation) >= 0.0);
            }
        };
        expectRamp(ids[0], spinBefore, {{0, 0, 0}, {0, 0, 170}, {0, 0, 190}, {0, 0, 350}, {0, 0, 500}, {0, 0, 660}});
        if (QTest::currentTestFailed())
            return;
        expectRamp(ids[1], turnBefore, {{0, 0, 0}, {170, 0, 0}, {300, 0, 0}});
        if (QTest::currentTestFailed())
            return;

        // One undo takes back the whole tracks' step, the next the selected keys'.
        document.undoStack().undo();
        for (std::size_t key = 0; key < spin.size(); ++key)
            QVERIFY(*document.object(ids[0])->track.keys[key].eulerAngles == *spinKeysFiltered.keys[key].eulerAngles);
        for (std::size_t key = 0; key < turn.size(); ++key)
            QVERIFY(*document.object(ids[1])->track.keys[key].eulerAngles == *turnBefore.keys[key].eulerAngles);
        document.undoStack().undo();
        for (std::size_t key = 0; key < spin.size(); ++key) {
            QVERIFY(document.object(ids[0])->track.keys[key].pose.orientation.coeffs() ==
                    spinBefore.keys[key].pose.orientation.coeffs());
            QVERIFY(*document.object(ids[0])->track.keys[key].eulerAngles == *spinBefore.keys[key].eulerAngles);
        }
        QCOMPARE(document.undoStack().index(), 0);
    }

private:
    // Imports `objects` in one step, which is then forgotten, and selects them all, the first active.
    std::vector<model::ObjectId> importAndSelect(std::vector<model::SceneObject> objects)
    {
        model::Document& document = window_->document();
        auto* import = new model::ImportObjectsCommand(document, std::move(objects));
        document.push(import);
        const std::vector<model::ObjectId> ids = import->ids();
        document.undoStack().clear();
        window_->selection().selectObjects(ids, ids.front());
        return ids;
    }

    QAction* eulerFilter() const
    {
        auto* action = window_->findChild<QAction*>(QStringLiteral("actionEulerFilter"));
        if (action == nullptr)
            qFatal("no Euler Filter action");
        return action;
    }

    std::unique_ptr<app::MainWindow> window_;
    model::ObjectId object_ = model::kNoObject;
};

QTEST_MAIN(TestRotationMode)
#include "tst_rotation_mode.moc"
