// The Graph Editor dock in the real window, on a top tipped 90° about x and spun about the world's
// z axis by 120° a second, keyed every second to a full turn at 3 s, slerp between keys. Its curves
// are checked against that motion written out here: with extrinsic xyz angles R = Rz(e3)·Ry(e2)·Rx(e1)
// = Rz(120°·t)·Rx(90°), so e1 = 90°, e2 = 0 and e3 = 120°·t unwrapped (a ramp, not a saw-tooth); the
// quaternion is Rz(60°·t as a half angle)·Rx(90°); ω is (0, 0, 2π/3) rad/s in the world and
// Rx(90°)⁻¹ of it, (0, 2π/3, 0), in the top's own frame. Dragging a key on an Euler channel turns
// that key by that angle alone, in one undo step; the channel list hides a curve; Motion ▸ Euler
// Filter flips a key stored with the far sign and is one undo step.

#include "app/graph_editor/graph_editor_panel.h"
#include "app/main_window.h"
#include "gui_test_support.h"
#include "inspected_window.h"
#include "model/commands/set_keyframe_orientation_command.h"

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QListView>
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
constexpr double kSpinDegreesPerSecond = 120.0;
constexpr int kKeyCount = 4; // at 0, 1, 2, 3 s: 0°, 120°, 240°, 360°
constexpr double kSpinEnd = 3.0;

Eigen::Quaterniond tipped() { return Eigen::Quaterniond(Eigen::AngleAxisd(kPi / 2.0, Eigen::Vector3d::UnitX())); }

// The top's orientation at `time`, written out: q(t) = (cos(θ/2) + sin(θ/2)·k)·Rx(90°), θ = 120°·t,
// on the sign the first key starts on and continuous after it.
Eigen::Quaterniond expectedOrientation(double time)
{
    const double angle = kSpinDegreesPerSecond * std::min(time, kSpinEnd) / kDegrees;
    return Eigen::Quaterniond(std::cos(angle / 2.0), 0.0, 0.0, std::sin(angle / 2.0)) * tipped();
}

model::SceneObject spinningTop()
{
    model::SceneObject object;
    object.id = 1; // the batch's own id; the document gives it another
    object.name = QStringLiteral("top");
    object.track.interpolation = InterpolationMethod::Slerp;
    for (int key = 0; key < kKeyCount; ++key)
        object.track.keys.push_back(model::Keyframe{double(key), Pose{expectedOrientation(key), Eigen::Vector3d::Zero()}, true});
    return object;
}

double valueAt(const QCPGraph* graph, int sample) { return graph->data()->at(sample)->value; }
double timeAt(const QCPGraph* graph, int sample) { return graph->data()->at(sample)->key; }

} // namespace

class TestGraphEditor : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }

    void init()
    {
        window_ = test::showMainWindow(test::WindowWait::Exposed, [this](app::MainWindow& window) {
            object_ = test::importAtStart(window.document(), {spinningTop()}, model::TimeRange{24.0, 0.0, 4.0}).front();
        });
        window_->selection().selectObject(object_);
        panel_ = window_->findChild<app::GraphEditorPanel*>();
        QVERIFY(panel_ != nullptr);
        // Closed, the editor samples nothing until it is opened and in front.
        QSignalSpy updated(panel_, &app::GraphEditorPanel::curvesUpdated);
        auto* dock = window_->findChild<QDockWidget*>(QStringLiteral("graphEditorDock"));
        QVERIFY(dock->isHidden()); // closed until View ▸ Panels opens it
        dock->toggleViewAction()->trigger();
        dock->raise();
        QVERIFY(updated.wait(5000));
        QTRY_VERIFY_WITH_TIMEOUT(panel_->graph(Channel::EulerThird)->dataCount() > 0, 5000);
    }

    void cleanup() { window_.reset(); }

    void channelsAreTheSpinWrittenOut()
    {
        // Every channel in the test, world and local ω in turn.
        for (std::size_t c = 0; c < model::kChannelCount; ++c)
            panel_->channels().setShown(static_cast<Channel>(c), true);
        for (const auto frame : {model::VelocityFrame::World, model::VelocityFrame::Local}) {
            QSignalSpy updated(panel_, &app::GraphEditorPanel::curvesUpdated);
            QComboBox* chooser = panel_->velocityFrameChooser();
            if (chooser->currentData().toInt() != static_cast<int>(frame)) {
                test::choose(chooser, chooser->findData(static_cast<int>(frame)));
                QVERIFY(updated.wait(5000));
            }
            const QCPGraph* spin = panel_->graph(Channel::EulerThird);
            QVERIFY(spin->dataCount() >= app::GraphEditorPanel::kSampleCount - 1);
            const double speed = kSpinDegreesPerSecond / kDegrees;
            const Eigen::Vector3d expectedVelocity =
                frame == model::VelocityFrame::World ? Eigen::Vector3d(0.0, 0.0, speed) : Eigen::Vector3d(0.0, speed, 0.0);
            for (int sample = 0; sample < spin->dataCount(); ++sample) {
                const double time = timeAt(spin, sample);
                const auto near = [&](Channel channel, double expected, double tolerance) {
                    const double shown = valueAt(panel_->graph(channel), sample);
                    if (std::abs(shown - expected) > tolerance)
                        qFatal("channel %d at %g s shows %.12g, expected %.12g", int(channel), time, shown, expected);
                };
                near(Channel::EulerFirst, 90.0, 1e-6);
                near(Channel::EulerSecond, 0.0, 1e-6);
                near(Channel::EulerThird, kSpinDegreesPerSecond * std::min(time, kSpinEnd), 1e-6);
                const Eigen::Quaterniond q = expectedOrientation(time);
                near(Channel::QuaternionW, q.w(), 1e-9);
                near(Channel::QuaternionX, q.x(), 1e-9);
                near(Channel::QuaternionY, q.y(), 1e-9);
                near(Channel::QuaternionZ, q.z(), 1e-9);
                // The central difference of ω straddles a key within its step: away from the keys only.
                const bool nearKey = std::abs(time - std::round(time)) < 2e-5;
                if (!nearKey) {
                    const Eigen::Vector3d velocity = time < kSpinEnd ? expectedVelocity : Eigen::Vector3d::Zero();
                    near(Channel::AngularVelocityX, velocity.x(), 1e-6);
                    near(Channel::AngularVelocityY, velocity.y(), 1e-6);
                    near(Channel::AngularVelocityZ, velocity.z(), 1e-6);
                    near(Channel::AngularSpeed, velocity.norm(), 1e-6);
                }
                near(Channel::PositionX, 0.0, 0.0);
            }
        }
        // A key on each channel, at the key's time and value.
        QCOMPARE(panel_->keyGraph(Channel::EulerThird)->dataCount(), kKeyCount);
        QCOMPARE(timeAt(panel_->keyGraph(Channel::EulerThird), 2), 2.0);
        QVERIFY(std::abs(valueAt(panel_->keyGraph(Channel::EulerThird), 3) - 360.0) < 1e-6);
        // e2 = 0 is 90° from gimbal lock throughout: nothing shaded.
        QVERIFY(panel_->gimbalZones().empty());
    }

    // In the extrinsic zyx order R = Rx(e3)·Ry(e2)·Rz(e1), whose first row ends in sin e2; the top's
    // R = Rz(θ)·Rx(90°) has sin θ there. So e2 = θ reaches gimbal lock (±90°) at θ = 90° and 270°,
    // at 0.75 s and 2.25 s, the centres of the two shaded zones.
    void gimbalLockZonesFollowTheOrder()
    {
        QSignalSpy updated(panel_, &app::GraphEditorPanel::curvesUpdated);
        // Typed, as the popup of twelve orders at the window's bottom edge scrolls.
        panel_->orderChooser()->setFocus();
        QTest::keyClicks(panel_->orderChooser(), QStringLiteral("ZYX"));
        QCOMPARE(panel_->orderChooser()->currentData().toString(), QStringLiteral("zyx"));
        QVERIFY(updated.wait(5000));
        QCOMPARE(panel_->gimbalZones().size(), std::size_t(2));
        for (const QCPItemRect* zone : panel_->gimbalZones()) {
            const double middle = (zone->topLeft->coords().x() + zone->bottomRight->coords().x()) / 2.0;
            const double angle = kSpinDegreesPerSecond * middle;
            QVERIFY2(std::abs(angle - 90.0) < 1.0 || std::abs(angle - 270.0) < 1.0, qPrintable(QString::number(angle)));
        }
        // The inspector's chooser follows: one convention for both.
        auto* inspectorOrder = window_->findChild<QComboBox*>(QStringLiteral("eulerOrderCombo"));
        QCOMPARE(inspectorOrder->currentData().toString(), QStringLiteral("zyx"));
    }

    void draggingAKeyOnAnEulerChannelTurnsItInOneStep()
    {
        model::Document& document = window_->document();
        QCustomPlot* plot = panel_->plot();
        const Eigen::Quaterniond before = document.object(object_)->track.keys[1].pose.orientation;
        // On whole pixels, as the mouse events are.
        const QPointF key = QPointF(plot->xAxis->coordToPixel(1.0), plot->yAxis->coordToPixel(120.0)).toPoint();
        const QPointF to = key + QPointF(0.0, -40.0);
        const double raised = plot->yAxis->pixelToCoord(to.y()) - plot->yAxis->pixelToCoord(key.y());
        QVERIFY(raised > 1.0);
        test::dragAlong(plot, test::straightPath(key, to, 8));
        QCOMPARE(document.undoStack().count(), 1);
        QCOMPARE(window_->selection().key(), std::optional<std::size_t>(1));
        // The key's z angle rose by what the mouse did; x stayed 90° and y 0: Rz(120° + Δ)·Rx(90°).
        const double angle = (kSpinDegreesPerSecond + raised) / kDegrees;
        const Eigen::Quaterniond expected =
            Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ())) * tipped();
        const Eigen::Quaterniond after = document.object(object_)->track.keys[1].pose.orientation;
        QVERIFY2(std::abs(std::abs(after.dot(expected)) - 1.0) < 1e-9, qPrintable(QString::number(after.dot(expected))));
        // Kept on the side the key was stored on.
        QVERIFY(after.dot(before) > 0.0);
        // The plot did not pan while the key moved.
        QVERIFY(std::abs(plot->yAxis->coordToPixel(120.0) - key.y()) < 0.5);
        document.undoStack().undo();
        QCOMPARE(document.object(object_)->track.keys[1].pose.orientation.coeffs(), before.coeffs());
    }

    void theChannelListHidesACurve()
    {
        QListView* list = panel_->channelList();
        QVERIFY(panel_->graph(Channel::EulerFirst)->visible());
        list->setFocus();
        list->setCurrentIndex(panel_->channels().indexOf(Channel::EulerFirst));
        QTest::keyClick(list, Qt::Key_Space);
        QVERIFY(!panel_->graph(Channel::EulerFirst)->visible());
        QVERIFY(!panel_->keyGraph(Channel::EulerFirst)->visible());
        QVERIFY(panel_->graph(Channel::EulerSecond)->visible());
        QVERIFY(!panel_->graph(Channel::QuaternionW)->visible());
        list->setCurrentIndex(panel_->channels().indexOf(Channel::QuaternionW));
        QTest::keyClick(list, Qt::Key_Space);
        QVERIFY(panel_->graph(Channel::QuaternionW)->visible());
    }

    void eulerFilterFlipsAKeyStoredOnTheFarSideInOneStep()
    {
        model::Document& document = window_->document();
        auto* filter = window_->findChild<QAction*>(QStringLiteral("actionEulerFilter"));
        QVERIFY(filter != nullptr);
        QVERIFY(!filter->isEnabled()); // the keys are continuous: nothing to do
        // Key 2 stored as −q: the same rotation, and the same motion.
        const Eigen::Quaterniond q = document.object(object_)->track.keys[2].pose.orientation;
        const Eigen::Quaterniond negated(-q.w(), -q.x(), -q.y(), -q.z());
        QSignalSpy updated(panel_, &app::GraphEditorPanel::curvesUpdated);
        document.push(new model::SetKeyframeOrientationCommand(document, object_, 2, negated));
        QVERIFY(filter->isEnabled());
        QVERIFY(updated.wait(5000));
        // The quaternion channel draws the key as stored, off its continuous curve.
        QCOMPARE(valueAt(panel_->keyGraph(Channel::QuaternionW), 2), negated.w());
        QCOMPARE(document.undoStack().count(), 1);

        filter->trigger();
        QCOMPARE(document.undoStack().count(), 2);
        QCOMPARE(document.undoStack().text(1), QStringLiteral("Apply Euler Filter"));
        QCOMPARE(document.object(object_)->track.keys[2].pose.orientation.coeffs(), q.coeffs());
        QVERIFY(!filter->isEnabled());
        QVERIFY(updated.wait(5000));
        QVERIFY(std::abs(valueAt(panel_->keyGraph(Channel::QuaternionW), 2) - q.w()) < 1e-12);

        document.undoStack().undo();
        QCOMPARE(document.object(object_)->track.keys[2].pose.orientation.coeffs(), negated.coeffs());
        QVERIFY(filter->isEnabled());
    }

    void homeFramesAllAndFFramesTheSelectedKey()
    {
        QCustomPlot* plot = panel_->plot();
        plot->xAxis->setRange(1.5, 1.6);
        window_->selection().selectKey(object_, 1);
        window_->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(window_.get()));
        plot->setFocus();
        QTest::keyClick(plot, Qt::Key_F);
        QCOMPARE(plot->xAxis->range().lower, 0.0);
        QCOMPARE(plot->xAxis->range().upper, 2.0);
        // Home, the window's Frame Scene elsewhere, frames the plot while it has the focus.
        QTest::keyClick(plot, Qt::Key_Home);
        QCOMPARE(plot->xAxis->range().lower, 0.0);
        QCOMPARE(plot->xAxis->range().upper, 4.0);
        // The shown curves fit: the ramp's 0° to 360° inside the value range.
        QVERIFY(plot->yAxis->range().lower <= 0.0 && plot->yAxis->range().upper >= 360.0);
    }

    // Shift+click selects keys 1 and 2 of the spin; G moves them 6 frames later and raises their z angle
    // with the pointer, one undo step; Esc puts them back with no step; S with the current time at 3 s
    // halves their distance from it, and cannot take them before the scene's start; a Shift+drag box adds key 3.
    void gAndSMoveAndScaleTheSelectedKeys()
    {
        model::Document& document = window_->document();
        QUndoStack& stack = document.undoStack();
        QCustomPlot* plot = panel_->plot();
        window_->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(window_.get()));
        const auto at = [&](double time, double degrees) {
            return QPointF(plot->xAxis->coordToPixel(time), plot->yAxis->coordToPixel(degrees)).toPoint();
        };
        QTest::mouseClick(plot, Qt::LeftButton, Qt::ShiftModifier, at(1.0, 120.0));
        QTest::mouseClick(plot, Qt::LeftButton, Qt::ShiftModifier, at(2.0, 240.0));
        QCOMPARE(window_->selection().keysOf(object_), (std::vector<std::size_t>{1, 2}));
        QCOMPARE(panel_->selectedKeyGraph(Channel::EulerThird)->dataCount(), 2);
        const auto keys = [&] { return document.object(object_)->track.keys; };
        const std::vector<model::Keyframe> before = keys();

        // G, the pointer 6 frames (0.25 s) right and 40 pixels up, a click keeps it.
        plot->setFocus();
        const QPoint start = at(1.5, 180.0);
        test::sendMove(plot, start, Qt::NoButton);
        QTest::keyClick(plot, Qt::Key_G);
        const QPoint end = QPoint(at(1.75, 180.0).x(), start.y() - 40);
        const double raised = plot->yAxis->pixelToCoord(end.y()) - plot->yAxis->pixelToCoord(start.y());
        for (const QPointF& point : test::straightPath(start, end, 6))
            test::sendMove(plot, point, Qt::NoButton);
        QTest::mouseClick(plot, Qt::LeftButton, Qt::NoModifier, end);
        QCOMPARE(stack.count(), 1);
        QCOMPARE(keys()[1].time, 1.25);
        QCOMPARE(keys()[2].time, 2.25);
        for (std::size_t key : {1, 2}) {
            const double angle = (kSpinDegreesPerSecond * double(key) + raised) / kDegrees;
            const Eigen::Quaterniond expected = Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ())) * tipped();
            QVERIFY(std::abs(std::abs(keys()[key].pose.orientation.dot(expected)) - 1.0) < 1e-9);
        }
        QCOMPARE(keys()[3].time, 3.0);
        QSignalSpy updated(panel_, &app::GraphEditorPanel::curvesUpdated);
        stack.undo();
        QCOMPARE(keys()[1].time, 1.0);
        QCOMPARE(keys()[2].pose.orientation.coeffs(), before[2].pose.orientation.coeffs());
        QVERIFY(updated.wait(5000));

        // G then Esc: the keys as they were, no step.
        const int steps = stack.index();
        test::sendMove(plot, start, Qt::NoButton);
        QTest::keyClick(plot, Qt::Key_G);
        test::sendMove(plot, end, Qt::NoButton);
        QCOMPARE(keys()[1].time, 1.25);
        QTest::keyClick(plot, Qt::Key_Escape);
        QCOMPARE(keys()[1].time, 1.0);
        QCOMPARE(stack.index(), steps);
        QCOMPARE(stack.count(), steps); // no step left behind (the undone G's redo went with the new edit)

        // S about 3 s: the pointer from 2 s to 2.5 s halves the distances, key 1 to 2 s and key 2 to 2.5 s.
        document.setCurrentTime(3.0);
        test::sendMove(plot, at(2.0, 180.0), Qt::NoButton);
        QTest::keyClick(plot, Qt::Key_S);
        test::sendMove(plot, at(2.5, 180.0), Qt::NoButton);
        QTest::mouseClick(plot, Qt::LeftButton, Qt::NoModifier, at(2.5, 180.0));
        QCOMPARE(stack.index(), steps + 1);
        QCOMPARE(stack.undoText(), QStringLiteral("Scale Keyframes"));
        QCOMPARE(keys()[1].time, 2.0);
        QCOMPARE(keys()[2].time, 2.5);
        QCOMPARE(keys()[3].time, 3.0);
        stack.undo();
        QVERIFY(updated.wait(5000));

        // S that would take key 1 before the scene's start (3 − 3·(3 − 1) = −3 s): the keys stay; Esc leaves no step.
        QCOMPARE(document.scene().startTime, 0.0);
        test::sendMove(plot, at(2.0, 180.0), Qt::NoButton);
        QTest::keyClick(plot, Qt::Key_S);
        test::sendMove(plot, at(0.0, 180.0), Qt::NoButton);
        QCOMPARE(keys()[1].time, 1.0);
        QCOMPARE(keys()[2].time, 2.0);
        QTest::keyClick(plot, Qt::Key_Escape);
        QCOMPARE(stack.index(), steps);

        // A Shift+drag box about the key at 3 s adds it.
        const QPoint corner = at(3.0, 360.0);
        QTest::mousePress(plot, Qt::LeftButton, Qt::ShiftModifier, corner - QPoint(15, 15));
        test::sendMove(plot, corner, Qt::LeftButton);
        test::sendMove(plot, corner + QPoint(15, 15), Qt::LeftButton);
        QTest::mouseRelease(plot, Qt::LeftButton, Qt::ShiftModifier, corner + QPoint(15, 15));
        QCOMPARE(window_->selection().keysOf(object_), (std::vector<std::size_t>{1, 2, 3}));
    }

private:
    std::unique_ptr<app::MainWindow> window_;
    app::GraphEditorPanel* panel_ = nullptr;
    model::ObjectId object_ = model::kNoObject;
};

QTEST_MAIN(TestGraphEditor)
#include "tst_graph_editor.moc"
