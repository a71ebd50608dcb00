// The small behaviours of the main window an animator relies on, driven on the real window: Ctrl+H
// brings the undo history to the front and closes it again; scrolling over a panel changes no setting;
// pausing rests on a frame, so K keys there; a track made a screw track is open; the speed plot and the
// sphere can be given room; the fit says what it applied; the frame rate shows only while the view moves;
// Object ▸ Add makes a shape, and a new project has an object to key.

#include "app/main_window.h"
#include "app/sketch/fit_controller.h"
#include "app/sketch/magnitude_plot.h"
#include "app/sketch/sphere_view.h"
#include "app/viewport/skeleton.h"
#include "app/viewport/viewport.h"
#include "gui_test_support.h"
#include "inspected_window.h"
#include "model/commands/reparent_object_command.h"
#include "model/primitive_meshes.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QTest>
#include <QTimer>
#include <QUndoStack>
#include <QUndoView>
#include <QWheelEvent>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

using namespace gyre;

namespace {

// The main window on a bundled sample, paused, shown and active, with the first layout of a new user.
class SampleWindow {
public:
    explicit SampleWindow(const char* sample = "l-cycle")
    {
        window_.show();
        window_.openSample(QStringLiteral(":/samples/%1.gyre").arg(QLatin1String(sample)));
        window_.playback().pause();
        window_.activateWindow();
        if (!QTest::qWaitForWindowActive(&window_))
            qFatal("The main window did not become active");
        // The first layout waits for the event loop (MainWindow::restoreLayout).
        QTest::qWait(0);
    }

    app::MainWindow& window() { return window_; }
    model::Document& document() { return window_.document(); }
    const model::MotionTrack& track() { return document().scene().objects.front().track; }

    template <class Widget>
    Widget* child(const char* name)
    {
        auto* widget = window_.findChild<Widget*>(QLatin1String(name));
        if (widget == nullptr)
            qFatal("The main window has no %s", name);
        return widget;
    }

private:
    app::MainWindow window_;
};

bool onFrame(double time, double fps)
{
    return std::abs(time * fps - std::round(time * fps)) < 1e-9;
}

// One notch of the wheel turned up over the middle of `widget`, as sent to it.
void turnWheel(QWidget* widget)
{
    const QPointF middle(widget->width() / 2.0, widget->height() / 2.0);
    QWheelEvent wheel(middle, widget->mapToGlobal(middle), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(widget, &wheel);
}

bool inFront(const QDockWidget* dock)
{
    return dock->isVisible() && !dock->visibleRegion().isEmpty();
}

} // namespace

class TestWindowManners : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }

    void ctrlHBringsTheUndoHistoryToTheFrontAndClosesIt()
    {
        SampleWindow sample;
        auto* history = sample.child<QDockWidget>("historyDock");
        auto* action = sample.child<QAction>("actionUndoHistory");
        QVERIFY(history->isHidden());

        // Opened, it is tabbed with the inspector: Ctrl+H shows it in front, and it stays there.
        QTest::keyClick(&sample.window(), Qt::Key_H, Qt::ControlModifier);
        QTRY_VERIFY(inFront(history));
        QVERIFY(history->findChild<QUndoView*>()->isVisible());
        QVERIFY(action->isChecked());
        QTest::qWait(50);
        QVERIFY(inFront(history));

        // Behind the inspector again, Ctrl+H brings it back to the front rather than closing it.
        sample.child<QDockWidget>("inspectorDock")->raise();
        QTRY_VERIFY(!inFront(history));
        QVERIFY(action->isChecked()); // open, though behind
        QTest::keyClick(&sample.window(), Qt::Key_H, Qt::ControlModifier);
        QTRY_VERIFY(inFront(history));

        // In front, Ctrl+H closes it, as View ▸ Panels does; and the menu's item opens it again.
        QTest::keyClick(&sample.window(), Qt::Key_H, Qt::ControlModifier);
        QVERIFY(history->isHidden());
        QVERIFY(!action->isChecked());
        action->trigger();
        QTRY_VERIFY(inFront(history));
        QVERIFY(action->isChecked());
        // The panel's own entry in View ▸ Panels and the Edit menu's agree.
        QVERIFY(history->toggleViewAction()->isChecked());
        history->toggleViewAction()->trigger();
        QVERIFY(history->isHidden());
        QVERIFY(!action->isChecked());
    }

    void theWheelChangesNoSettingOfABoxWithoutFocus()
    {
        SampleWindow sample("pen");
        // Every spin box and combo box of the window takes the focus by click or Tab, not by the wheel.
        int boxes = 0;
        for (QWidget* widget : sample.window().findChildren<QWidget*>()) {
            if (qobject_cast<QAbstractSpinBox*>(widget) == nullptr && qobject_cast<QComboBox*>(widget) == nullptr)
                continue;
            widget->ensurePolished();
            QVERIFY2(widget->focusPolicy() == Qt::StrongFocus, qPrintable(widget->objectName()));
            ++boxes;
        }
        QVERIFY(boxes >= 8);

        sample.child<QDockWidget>("fitDock")->raise();
        auto* delta = sample.child<QDoubleSpinBox>("deltaSpin");
        QTRY_VERIFY(delta->isVisible() && !delta->visibleRegion().isEmpty());
        auto* scheme = sample.child<QComboBox>("schemeCombo");
        const double shownDelta = delta->value();
        const int shownScheme = scheme->currentIndex();
        const int steps = sample.document().undoStack().count();
        for (int notch = 0; notch < 8; ++notch) {
            turnWheel(delta);
            turnWheel(scheme);
        }
        QCOMPARE(delta->value(), shownDelta);
        QCOMPARE(scheme->currentIndex(), shownScheme);
        QCOMPARE(sample.document().undoStack().count(), steps);
        QVERIFY(!delta->hasFocus());

        // Clicked into, the box takes the wheel: a step up, one undo step.
        delta->setFocus(Qt::MouseFocusReason);
        QTRY_VERIFY(delta->hasFocus());
        turnWheel(delta);
        QVERIFY(delta->value() > shownDelta);
        QCOMPARE(sample.document().undoStack().count(), steps + 1);
        QCOMPARE(sample.track().sketch.delta, delta->value());
    }

    void pausingRestsOnAFrameSoAKeyLandsOnIt()
    {
        SampleWindow sample;
        const double fps = sample.document().scene().fps;
        auto* play = sample.child<QAction>("actionPlay");
        play->trigger();
        QVERIFY(sample.window().playback().isPlaying());
        // Playing passes between frames.
        QTRY_VERIFY(!onFrame(sample.document().scene().currentTime, fps));
        play->trigger();
        QVERIFY(!sample.window().playback().isPlaying());
        const double paused = sample.document().scene().currentTime;
        QVERIFY2(onFrame(paused, fps), qPrintable(QString::number(paused * fps, 'g', 12)));

        // K keys the frame the time bar names.
        sample.child<QAction>("actionAddKeyframe")->trigger();
        const std::vector<model::Keyframe>& keys = sample.track().keys;
        QVERIFY(std::any_of(keys.begin(), keys.end(), [&](const model::Keyframe& key) { return key.time == paused; }));
        QCOMPARE(sample.window().selection().selectedKey()->time, paused);
    }

    void objectAddMakesASelectedShapeInOneStep()
    {
        SampleWindow sample;
        model::Document& document = sample.document();
        const std::size_t objects = document.scene().objects.size();
        const int steps = document.undoStack().count();
        sample.child<QAction>("actionAdd-box")->trigger();
        QCOMPARE(document.scene().objects.size(), objects + 1);
        const model::SceneObject& box = document.scene().objects.back();
        QCOMPARE(box.name, QStringLiteral("Box"));
        QVERIFY(box.mesh != nullptr);
        QCOMPARE(box.mesh->indices.size(), std::size_t(36)); // six faces of two triangles
        QCOMPARE(box.parent, model::kNoObject);
        QVERIFY(box.track.keys.empty());
        QCOMPARE(sample.window().selection().object(), box.id);
        QCOMPARE(document.undoStack().count(), steps + 1);
        QCOMPARE(document.undoStack().text(steps), QStringLiteral("Add Box"));

        // A second box is named apart. The block has its mesh, as every added shape: it exports as one,
        // and a block put under another is no joint of a skeleton.
        sample.child<QAction>("actionAdd-box")->trigger();
        QCOMPARE(document.scene().objects.back().name, QStringLiteral("Box.001"));
        sample.child<QAction>("actionAdd-block")->trigger();
        QCOMPARE(document.scene().objects.back().name, QStringLiteral("Block"));
        QVERIFY(document.scene().objects.back().mesh != nullptr);
        QCOMPARE(document.scene().objects.back().mesh->positions.size(),
                 model::primitiveMesh(model::Primitive::Block).positions.size());
        const model::ObjectId firstBlock = document.scene().objects.back().id;
        sample.child<QAction>("actionAdd-block")->trigger();
        document.push(new model::ReparentObjectCommand(document, document.scene().objects.back().id, firstBlock));
        const std::vector<bool> joints = model::findJoints(document.scene());
        QVERIFY(std::none_of(joints.begin(), joints.end(), [](bool joint) { return joint; }));
        document.undoStack().undo();
        document.undoStack().undo();

        // K keys the new object where it stands.
        sample.window().selection().selectObject(firstBlock); // the second block, selected, is gone
        sample.child<QAction>("actionAddKeyframe")->trigger();
        QCOMPARE(document.scene().objects.back().track.keys.size(), std::size_t(1));

        for (int step = 0; step < 4; ++step)
            document.undoStack().undo();
        QCOMPARE(document.scene().objects.size(), objects);
    }

    void aNewProjectHoldsOneObjectToKey()
    {
        SampleWindow sample;
        sample.child<QAction>("actionNew")->trigger();
        model::Document& document = sample.document();
        QCOMPARE(document.scene().objects.size(), std::size_t(1));
        const model::SceneObject& block = document.scene().objects.front();
        QCOMPARE(block.name, QStringLiteral("Block"));
        QVERIFY(block.mesh != nullptr);
        QVERIFY(block.track.keys.empty());
        QVERIFY(!document.isModified());
        QVERIFY(document.filePath().isEmpty());
        QCOMPARE(document.undoStack().count(), 0);
        QTRY_COMPARE(sample.window().selection().object(), block.id);

        sample.child<QAction>("actionAddKeyframe")->trigger();
        QCOMPARE(document.scene().objects.front().track.keys.size(), std::size_t(1));
        QVERIFY(document.isModified());
    }

    void aNewScrewTrackIsOpenUntilCyclicIsTicked()
    {
        SampleWindow sample("pen");
        QCOMPARE(sample.track().interpolation, InterpolationMethod::Hermite);
        QVERIFY(sample.track().subdivision.cyclic); // what every track starts with
        sample.child<QDockWidget>("screwBenderDock")->raise();
        auto* method = sample.child<QComboBox>("interpolationCombo");
        QTRY_VERIFY(method->isVisible());
        const int steps = sample.document().undoStack().count();
        test::choose(method, method->findData(static_cast<int>(InterpolationMethod::Screw)));
        QCOMPARE(sample.track().interpolation, InterpolationMethod::Screw);
        QVERIFY(!sample.track().subdivision.cyclic);
        QVERIFY(sample.child<QRadioButton>("openRadio")->isChecked());
        QCOMPARE(sample.document().undoStack().count(), steps + 1);

        // One undo step puts back both.
        sample.document().undoStack().undo();
        QCOMPARE(sample.track().interpolation, InterpolationMethod::Hermite);
        QVERIFY(sample.track().subdivision.cyclic);
        sample.document().undoStack().redo();

        // Ticked cyclic, it is a cycle.
        sample.child<QRadioButton>("cyclicRadio")->click();
        QVERIFY(sample.track().subdivision.cyclic);
        QCOMPARE(sample.track().interpolation, InterpolationMethod::Screw);

        // A track whose subdivision was set keeps it when it becomes a screw track.
        test::choose(method, method->findData(static_cast<int>(InterpolationMethod::Slerp)));
        sample.child<QSpinBox>("levelsSpin")->setValue(3);
        test::choose(method, method->findData(static_cast<int>(InterpolationMethod::Screw)));
        QCOMPARE(sample.track().interpolation, InterpolationMethod::Screw);
        QCOMPARE(sample.track().subdivision.levels, 3);
        QVERIFY(sample.track().subdivision.cyclic);
    }

    void theSpeedPlotAndTheSphereCanBeGivenRoom()
    {
        SampleWindow sample;
        auto* speed = sample.window().findChild<app::MagnitudePlot*>();
        QVERIFY(speed != nullptr);
        auto* sphereDock = sample.child<QDockWidget>("sphereDock");
        auto* speedDock = sample.child<QDockWidget>("magnitudeDock");
        // Each dragged as tall as it goes (resizeDocks stops at what the neighbours need).
        sample.window().resizeDocks({speedDock}, {2000}, Qt::Vertical);
        QTRY_VERIFY2(speed->plotArea().height() >= 200,
                     qPrintable(QStringLiteral("the speed plot's area is %1 px tall").arg(speed->plotArea().height())));
        sample.window().resizeDocks({sphereDock}, {2000}, Qt::Vertical);
        auto* sphere = sphereDock->findChild<app::SphereView*>();
        QVERIFY(sphere != nullptr);
        QTRY_VERIFY2(sphere->height() >= 200, qPrintable(QStringLiteral("the sphere is %1 px tall").arg(sphere->height())));
    }

    void theFitSaysWhatItApplied()
    {
        SampleWindow sample("pen");
        sample.child<QDockWidget>("fitDock")->raise();
        auto* fit = sample.child<QPushButton>("fitButton");
        QTRY_VERIFY(fit->isVisible() && fit->isEnabled());
        auto* controller = sample.window().findChild<app::FitController*>();
        QVERIFY(controller != nullptr);
        QSignalSpy ended(controller, &app::FitController::fitEnded);

        // A δ no fit meets: it says so, and that its last result was applied.
        auto* delta = sample.child<QDoubleSpinBox>("deltaSpin");
        delta->setValue(delta->minimum());
        QCOMPARE(sample.track().sketch.delta, delta->minimum());
        const int steps = sample.document().undoStack().count();
        QTest::mouseClick(fit, Qt::LeftButton);
        QVERIFY(ended.wait(60000));
        const QString message = ended.last().at(0).toString();
        QVERIFY2(message.contains(QStringLiteral("result was applied")), qPrintable(message));
        QVERIFY2(!message.contains(QStringLiteral("variable frame")), qPrintable(message));
        QCOMPARE(sample.window().statusBar()->currentMessage(), message);
        QCOMPARE(sample.document().undoStack().count(), steps + 1);
        QVERIFY(!sample.track().sketch.fittedCurve.empty());
    }

    void theFrameRateShowsOnlyWhileTheViewMoves()
    {
        SampleWindow sample;
        auto* viewport = sample.window().findChild<app::Viewport*>();
        QVERIFY(viewport != nullptr);
        auto* rate = sample.child<QLabel>("frameRateLabel");

        // Idle, the window redraws now and then: a rate is measured, and not shown.
        QSignalSpy stats(viewport, &app::Viewport::frameStatsChanged);
        QTimer redraw;
        connect(&redraw, &QTimer::timeout, viewport, qOverload<>(&QWidget::update));
        redraw.start(200);
        QVERIFY(stats.wait(10000));
        QVERIFY(stats.last().at(0).toDouble() < 10.0);
        QVERIFY(!rate->isVisible());
        redraw.stop();

        // Playing, it shows; paused, it goes.
        sample.child<QAction>("actionPlay")->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(rate->isVisible(), 10000);
        QVERIFY2(rate->text().contains(QStringLiteral("fps")), qPrintable(rate->text()));
        sample.child<QAction>("actionPlay")->trigger();
        QVERIFY(!rate->isVisible());

        // Orbiting, it shows; released, it goes.
        const QPoint from = viewport->rect().center();
        QTest::mousePress(viewport, Qt::LeftButton, {}, from);
        QVERIFY(viewport->isDragging());
        for (int step = 1; !rate->isVisible() && step < 400; ++step) {
            test::sendMove(viewport, from + QPointF(step % 100, 0), Qt::LeftButton);
            QTest::qWait(5);
        }
        QVERIFY(rate->isVisible());
        QTest::mouseRelease(viewport, Qt::LeftButton, {}, from + QPoint(50, 0));
        QVERIFY(!rate->isVisible());
    }
};

QTEST_MAIN(TestWindowManners)
#include "tst_window_manners.moc"
