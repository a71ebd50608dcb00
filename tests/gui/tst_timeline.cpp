// The timeline driven with the mouse on the bundled sample (keys at 0, 1, ..., 5 s, 30 fps): dragging
// a key marker retimes the key by the distance dragged, one undo step per drag, and stops before its
// neighbour; clicking the ruler scrubs without an undo step; clicking a marker selects the key. The
// bar above it edits the time range as one undo step. The ruler and the markers are drawn into a cached
// pixmap, redrawn when a key or the range changes and not when only the current time moves.

#include "app/main_window.h"
#include "app/timeline_widget.h"
#include "gui_test_support.h"
#include "model/commands/replace_keyframes_command.h"
#include "model/commands/set_interpolation_command.h"
#include "model/commands/set_time_range_command.h"
#include "model/key_edits.h"
#include "model/object_mass.h"

#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QImage>
#include <QMouseEvent>
#include <QTest>

#include <cmath>
#include <memory>

using namespace gyre;

namespace {

constexpr std::size_t kDraggedKey = 2; // at 2 s, between keys at 1 s and 3 s

// Presses at `from`, moves in steps to `to` with the left button held, and releases there.
void dragWithLeftButton(QWidget* widget, const QPoint& from, const QPoint& to, Qt::KeyboardModifiers modifiers = {})
{
    QTest::mousePress(widget, Qt::LeftButton, modifiers, from);
    constexpr int kSteps = 10;
    for (int step = 1; step <= kSteps; ++step) {
        const QPointF at = QPointF(from) + QPointF(to - from) * step / kSteps;
        // QTest::mouseMove does not say which buttons are held; a drag needs them.
        QMouseEvent move(QEvent::MouseMove, at, widget->mapToGlobal(at), Qt::NoButton, Qt::LeftButton, modifiers);
        QApplication::sendEvent(widget, &move);
    }
    QTest::mouseRelease(widget, Qt::LeftButton, modifiers, to);
}

} // namespace

class TestTimeline : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }

    void init()
    {
        window_ = test::showMainWindow(test::WindowWait::Exposed, [](app::MainWindow& window) { window.openBundledSample(); });
        timeline_ = window_->findChild<app::TimelineWidget*>();
        QVERIFY(timeline_ != nullptr);
        QVERIFY(timeline_->isVisible());
        QCOMPARE(keyTime(kDraggedKey), 2.0);
    }

    void cleanup() { window_.reset(); }

    void draggingAKeyRetimesItAsOneUndoStep()
    {
        QUndoStack& stack = window_->document().undoStack();
        const int stepsBefore = stack.count();
        const QPoint from = *timeline_->keyMarkerCentre(kDraggedKey);
        dragWithLeftButton(timeline_, from, from + QPoint(pixelsFor(0.5), 0));
        QCOMPARE(keyTime(kDraggedKey), 2.5);
        QCOMPARE(window_->selection().key(), std::optional(kDraggedKey));
        QCOMPARE(stack.count(), stepsBefore + 1);

        stack.undo();
        QCOMPARE(keyTime(kDraggedKey), 2.0);
        stack.redo();
        QCOMPARE(keyTime(kDraggedKey), 2.5);

        // The next drag of the same key is a step of its own, though the model merges such moves.
        const QPoint again = *timeline_->keyMarkerCentre(kDraggedKey);
        dragWithLeftButton(timeline_, again, again - QPoint(pixelsFor(0.2), 0));
        QCOMPARE(keyTime(kDraggedKey), 2.3);
        QCOMPARE(stack.count(), stepsBefore + 2);
        stack.undo();
        QCOMPARE(keyTime(kDraggedKey), 2.5);
    }

    void aDragTowardANeighbourStopsBeforeIt()
    {
        const QPoint from = *timeline_->keyMarkerCentre(kDraggedKey);
        dragWithLeftButton(timeline_, from, from + QPoint(pixelsFor(2.5), 0));
        // The last frame before the neighbour at 3 s: frame 89 at 30 fps.
        QCOMPARE(keyTime(kDraggedKey), 89.0 / 30.0);
        QCOMPARE(keyTime(kDraggedKey + 1), 3.0);

        // Unsnapped (Shift), it comes closer, still short of the neighbour.
        const QPoint left = *timeline_->keyMarkerCentre(kDraggedKey);
        dragWithLeftButton(timeline_, left, left - QPoint(pixelsFor(2.5), 0), Qt::ShiftModifier);
        QVERIFY(keyTime(kDraggedKey) > 1.0);
        QVERIFY(keyTime(kDraggedKey) < 1.0 + 1.0 / 30.0);
        QCOMPARE(keyTime(kDraggedKey - 1), 1.0);
    }

    void clickingTheRulerScrubsWithoutAnUndoStep()
    {
        const int stepsBefore = window_->document().undoStack().count();
        window_->playback().play();
        const QPoint onRuler(static_cast<int>(std::lround(timeline_->xForTime(2.5))), timeline_->rulerRect().center().y());
        QTest::mouseClick(timeline_, Qt::LeftButton, {}, onRuler);
        QVERIFY(!window_->playback().isPlaying());
        QCOMPARE(window_->document().scene().currentTime, 2.5);
        QCOMPARE(window_->document().undoStack().count(), stepsBefore);
        QVERIFY(!window_->document().isModified());
    }

    void clickingAMarkerSelectsItsKey()
    {
        const int stepsBefore = window_->document().undoStack().count();
        QTest::mouseClick(timeline_, Qt::LeftButton, {}, *timeline_->keyMarkerCentre(4));
        QCOMPARE(window_->selection().key(), std::optional<std::size_t>(4));
        QCOMPARE(keyTime(4), 4.0);
        QCOMPARE(window_->document().undoStack().count(), stepsBefore);
    }

    void theTimeBarSetsTheRangeAsOneUndoStep()
    {
        auto* end = window_->findChild<QDoubleSpinBox*>(QStringLiteral("endTimeBox"));
        QVERIFY(end != nullptr);
        QCOMPARE(end->value(), 6.0);
        const int stepsBefore = window_->document().undoStack().count();
        end->setValue(8.0);
        QCOMPARE(window_->document().scene().endTime, 8.0);
        QCOMPARE(window_->document().undoStack().count(), stepsBefore + 1);
        // An end before the start is refused, and the box shows the scene's end again.
        end->setValue(-1.0);
        QCOMPARE(window_->document().scene().endTime, 8.0);
        QCOMPARE(end->value(), 8.0);
        window_->document().undoStack().undo();
        QCOMPARE(window_->document().scene().endTime, 6.0);
        QCOMPARE(end->value(), 6.0);
    }

    // The time bar sets g and the up axis, one undo step each; a ballistic track's centre of mass then
    // follows x(t) = x0 + v0·t + ½·g⃗·t², g⃗ = −g·up, through both keys' centres.
    void theTimeBarSetsGravityAndABallisticCentreFollowsIt()
    {
        model::Document& document = window_->document();
        const model::ObjectId id = window_->selection().object();
        QVERIFY(id != model::kNoObject);
        const Pose launch{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.0, 0.0, 1.0)};
        const Pose landing{Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Eigen::Vector3d(1.0, 2.0, 3.0).normalized())),
                           Eigen::Vector3d(2.0, -1.0, 0.5)};
        document.push(new model::ReplaceKeyframesCommand(document, {{id, {{1.0, launch}, {2.5, landing}}}},
                                                         model::ReplaceKeyframesCommand::Edit::Paste));
        document.push(new model::SetInterpolationCommand(document, id, InterpolationMethod::Ballistic));

        auto* gravity = window_->findChild<QDoubleSpinBox*>(QStringLiteral("gravityBox"));
        auto* up = window_->findChild<QComboBox*>(QStringLiteral("upAxisBox"));
        QVERIFY(gravity != nullptr && up != nullptr);
        QCOMPARE(gravity->value(), 9.81);
        QCOMPARE(up->currentIndex(), static_cast<int>(model::UpDirection::PlusZ));
        QUndoStack& stack = document.undoStack();
        const int stepsBefore = stack.count();
        gravity->setFocus();
        gravity->selectAll();
        QTest::keyClicks(gravity, QStringLiteral("3.7"));
        QTest::keyClick(gravity, Qt::Key_Return);
        QCOMPARE(document.scene().gravity.acceleration, 3.7);
        QCOMPARE(stack.count(), stepsBefore + 1);
        up->setFocus();
        QTest::keyClick(up, Qt::Key_Up); // from +Z to −Y
        QCOMPARE(document.scene().gravity.up, model::UpDirection::MinusY);
        QCOMPARE(stack.count(), stepsBefore + 2);

        const model::SceneObject& object = *document.object(id);
        const Eigen::Vector3d centreOfMass = model::objectMassProperties(object).properties.centre;
        const auto centreAt = [&](double time) {
            const Pose pose = document.motion(id)->motion().at(time);
            return Eigen::Vector3d(pose.position + pose.orientation * centreOfMass);
        };
        const Eigen::Vector3d x0 = launch.position + launch.orientation * centreOfMass;
        const Eigen::Vector3d x1 = landing.position + landing.orientation * centreOfMass;
        const auto parabola = [&](const Eigen::Vector3d& acceleration, double t) {
            const double duration = 1.5;
            const Eigen::Vector3d v0 = (x1 - x0 - 0.5 * acceleration * duration * duration) / duration;
            return Eigen::Vector3d(x0 + v0 * t + 0.5 * acceleration * t * t);
        };
        for (const double t : {0.3, 0.75, 1.2}) {
            const Eigen::Vector3d expected = parabola(Eigen::Vector3d(0.0, 3.7, 0.0), t);
            QVERIFY2((centreAt(1.0 + t) - expected).norm() < 1e-9, qPrintable(QString::number(t)));
        }

        // Undone, the centre falls along −Z at 3.7 m/s² again; twice, at 9.81 m/s².
        stack.undo();
        QCOMPARE(up->currentIndex(), static_cast<int>(model::UpDirection::PlusZ));
        QVERIFY((centreAt(1.75) - parabola(Eigen::Vector3d(0.0, 0.0, -3.7), 0.75)).norm() < 1e-9);
        stack.undo();
        QCOMPARE(gravity->value(), 9.81);
        QVERIFY((centreAt(1.75) - parabola(Eigen::Vector3d(0.0, 0.0, -9.81), 0.75)).norm() < 1e-9);
    }

    void movingTheCurrentTimeRedrawsOnlyTheCursor()
    {
        window_->document().setCurrentTime(0.0);
        timeline_->grab(); // whatever the window's set-up left to redraw
        const int builds = timeline_->staticLayerBuilds();
        for (double seconds : {0.5, 1.5, 2.5, 3.5}) {
            window_->document().setCurrentTime(seconds);
            const QImage shot = timeline_->grab().toImage();
            // The cursor's red line crosses the key lane above the markers.
            const QColor cursor = pixelAt(shot, QPointF(timeline_->xForTime(seconds), timeline_->keyLaneRect().top() + 3));
            QVERIFY2(cursor.red() > 150 && cursor.green() < 120, qPrintable(cursor.name()));
        }
        QCOMPARE(timeline_->staticLayerBuilds(), builds);
    }

    void addingAKeyDrawsItsMarker()
    {
        model::Document& document = window_->document();
        document.setCurrentTime(0.0); // the cursor away from the new key
        const QPointF centre(timeline_->xForTime(2.5), timeline_->keyLaneRect().center().y());
        QCOMPARE(markerPixels(timeline_->grab().toImage(), centre), 0);
        const int builds = timeline_->staticLayerBuilds();

        model::Keyframe key = window_->selection().selectedObject()->track.keys[kDraggedKey];
        key.time = 2.5; // between the keys at 2 s and 3 s
        const model::ObjectId object = window_->selection().object();
        document.undoStack().push(new model::ReplaceKeyframesCommand(
            document, {{object, model::withKeys(document.object(object)->track.keys, {key})}}, model::ReplaceKeyframesCommand::Edit::Insert));
        QVERIFY(markerPixels(timeline_->grab().toImage(), centre) > 0);
        QCOMPARE(timeline_->staticLayerBuilds(), builds + 1);

        document.undoStack().undo();
        QCOMPARE(markerPixels(timeline_->grab().toImage(), centre), 0);
        QCOMPARE(timeline_->staticLayerBuilds(), builds + 2);
    }

    void changingTheRangeOrTheSizeRedrawsTheMarkers()
    {
        model::Document& document = window_->document();
        document.setCurrentTime(0.0);
        const QPoint before = *timeline_->keyMarkerCentre(4);
        QVERIFY(markerPixels(timeline_->grab().toImage(), before) > 0);
        const int builds = timeline_->staticLayerBuilds();

        // Twice the range: the key at 4 s moves left, where no key was.
        const model::Scene& scene = document.scene();
        document.undoStack().push(
            new model::SetTimeRangeCommand(document, {scene.fps, scene.startTime, 2.0 * scene.endTime}));
        const QPoint after = *timeline_->keyMarkerCentre(4);
        QVERIFY(after.x() < before.x() - 20);
        QImage shot = timeline_->grab().toImage();
        QVERIFY(markerPixels(shot, after) > 0);
        QCOMPARE(markerPixels(shot, before), 0);
        QCOMPARE(timeline_->staticLayerBuilds(), builds + 1);

        // Narrower: the markers follow the new width.
        timeline_->resize(timeline_->width() - 200, timeline_->height());
        const QPoint narrower = *timeline_->keyMarkerCentre(4);
        QVERIFY(narrower.x() < after.x());
        shot = timeline_->grab().toImage();
        QVERIFY(markerPixels(shot, narrower) > 0);
        QCOMPARE(timeline_->staticLayerBuilds(), builds + 2);
    }

private:
    // The colour of the grabbed widget at a widget point, whatever the device pixel ratio.
    static QColor pixelAt(const QImage& shot, const QPointF& point)
    {
        const QPointF pixel = point * shot.devicePixelRatio();
        return shot.pixelColor(static_cast<int>(std::floor(pixel.x())), static_cast<int>(std::floor(pixel.y())));
    }

    // How many pixels within a marker's half-width of `centre` differ from the key lane's background:
    // none where no marker is drawn, the diamond's outline and fill where one is.
    int markerPixels(const QImage& shot, const QPointF& centre) const
    {
        const QColor background = timeline_->palette().color(QPalette::Base);
        int count = 0;
        for (int dy = -4; dy <= 4; ++dy)
            for (int dx = -4; dx <= 4; ++dx)
                if (pixelAt(shot, centre + QPointF(dx, dy)) != background)
                    ++count;
        return count;
    }

    double keyTime(std::size_t key) const
    {
        return window_->selection().selectedObject()->track.keys[key].time;
    }

    // The width of `seconds` on the ruler, to the nearest pixel.
    int pixelsFor(double seconds) const
    {
        return static_cast<int>(std::lround(timeline_->xForTime(seconds) - timeline_->xForTime(0.0)));
    }

    std::unique_ptr<app::MainWindow> window_;
    app::TimelineWidget* timeline_ = nullptr;
};

QTEST_MAIN(TestTimeline)
#include "tst_timeline.moc"
