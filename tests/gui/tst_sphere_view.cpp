// The sphere view and the pattern pad driven with the mouse on a document made here: a top that spins
// about its tilted axis while that axis precesses about z, keyed every 0.05 s for 3 s, so that the
// direction of its angular velocity circles z and each direction belongs to one time. A stroke drawn
// over that curve arrives in one undo step with the times of the curve under its ends; turning the
// sphere changes nothing in the document; erasing the middle of a stroke splits it; the pad sets the
// pattern; Escape takes back a stroke being drawn. All but the current-time dot is drawn into cached
// images, redrawn when the curves or the view change and not when only the time moves or a key moves
// without turning; a hidden view samples nothing while the scene plays, and catches up when shown.

#include "app/playback.h"
#include "app/selection.h"
#include "app/sketch/direction_sketch_panel.h"
#include "app/sketch/pattern_pad.h"
#include "app/sketch/sphere_view.h"
#include "fit/angular_velocity_target.h"
#include "gui_test_support.h"
#include "model/sketch_fit_problem.h"
#include "model/commands/add_stroke_command.h"
#include "model/commands/set_keyframe_position_command.h"
#include "model/commands/apply_fit_result_command.h"
#include "model/commands/import_objects_command.h"
#include "model/commands/replace_keyframes_command.h"
#include "model/document.h"
#include "model/key_edits.h"
#include "model/track_evaluation.h"

#include <QApplication>
#include <QDir>
#include <QImage>
#include <QMouseEvent>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

// The bundled samples are compiled into gyre_app; registering them must happen outside any namespace.
static void registerResources()
{
    Q_INIT_RESOURCE(gyre);
}

using namespace gyre;
using Tool = app::SphereView::Tool;

namespace {

constexpr double kPrecessionRate = std::numbers::pi / 2.0; // rad/s about z
constexpr double kSpinRate = 2.0 * std::numbers::pi;        // rad/s about the top's own axis
constexpr double kTilt = 40.0 * std::numbers::pi / 180.0;
constexpr double kKeySpacing = 0.05;
constexpr double kLastKey = 3.0;

// q(t) = Rz(Ω t) · Rx(tilt) · Rz(s t).
model::SceneObject precessingTop()
{
    model::SceneObject top;
    top.id = 1;
    top.name = QStringLiteral("top");
    for (int k = 0; k * kKeySpacing <= kLastKey + 1e-9; ++k) {
        const double t = k * kKeySpacing;
        model::Keyframe key;
        key.time = t;
        key.pose.orientation = Eigen::AngleAxisd(kPrecessionRate * t, Eigen::Vector3d::UnitZ())
                               * Eigen::AngleAxisd(kTilt, Eigen::Vector3d::UnitX())
                               * Eigen::AngleAxisd(kSpinRate * t, Eigen::Vector3d::UnitZ());
        top.track.keys.push_back(key);
    }
    return top;
}

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

void moveWithButton(QWidget* widget, const QPointF& at, Qt::MouseButton button)
{
    // QTest::mouseMove does not say which buttons are held; a drag needs them.
    QMouseEvent move(QEvent::MouseMove, at, widget->mapToGlobal(at), Qt::NoButton, button, {});
    QApplication::sendEvent(widget, &move);
}

// Presses at the first point, moves through the others with `button` held, releases at the last.
void dragThrough(QWidget* widget, const std::vector<QPointF>& points, Qt::MouseButton button = Qt::LeftButton)
{
    QTest::mousePress(widget, button, {}, points.front().toPoint());
    for (std::size_t i = 1; i < points.size(); ++i)
        moveWithButton(widget, points[i].toPoint(), button);
    QTest::mouseRelease(widget, button, {}, points.back().toPoint());
}

} // namespace

class TestSphereView : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        test::useTestSettings();
        registerResources();
    }

    void init()
    {
        document_ = std::make_unique<model::Document>();
        auto* import = new model::ImportObjectsCommand(*document_, {precessingTop()});
        document_->undoStack().push(import);
        object_ = import->ids().front();
        document_->undoStack().clear();
        selection_ = std::make_unique<app::Selection>(*document_);
        selection_->selectObject(object_);
        motion_ = std::make_unique<model::TrackMotion>(track());

        panel_ = std::make_unique<app::DirectionSketchPanel>(*document_, *selection_);
        panel_->resize(520, 640);
        view_ = panel_->sphereView();
        QSignalSpy updated(view_, &app::SphereView::curvesUpdated);
        panel_->show();
        QVERIFY(QTest::qWaitForWindowExposed(panel_.get()));
        QVERIFY(updated.wait(5000));
        QVERIFY(!view_->curves().motion.empty());
        QVERIFY(view_->message().isEmpty());
    }

    void cleanup()
    {
        panel_.reset();
        selection_.reset();
        document_.reset();
    }

    void aDrawnStrokeIsTimedByTheCurveUnderItsEnds()
    {
        QUndoStack& stack = document_->undoStack();
        const std::vector<Eigen::Vector3d> aims = curveDirections(1.0, 2.2);
        dragThrough(view_, pixelsOf(aims));

        QCOMPARE(stack.count(), 1);
        QCOMPARE(stack.undoText(), QStringLiteral("Add Stroke"));
        QCOMPARE(strokes().size(), std::size_t(1));
        const model::DirectionStroke drawn = strokes().front();
        QCOMPARE(drawn.points.size(), aims.size());
        // A pixel of the pointer's rounding, on the sphere's radius.
        const double pixel = 1.0 / view_->sphereRadius();
        for (std::size_t i = 0; i < aims.size(); ++i) {
            QVERIFY(std::abs(drawn.points[i].norm() - 1.0) < 1e-12);
            QVERIFY2(angleBetween(drawn.points[i], aims[i]) < 1.5 * pixel,
                     qPrintable(QStringLiteral("point %1 is %2 rad off").arg(i).arg(angleBetween(drawn.points[i], aims[i]))));
        }

        // The ends take the times of the curve under them, within what a pixel moves along it.
        QCOMPARE(drawn.times.size(), drawn.points.size());
        QVERIFY2(std::abs(drawn.times.front() - 1.0) < 0.02, qPrintable(QString::number(drawn.times.front())));
        QVERIFY2(std::abs(drawn.times.back() - 2.2) < 0.02, qPrintable(QString::number(drawn.times.back())));
        // Between them, time goes with arc length.
        std::vector<double> arc{0.0};
        for (std::size_t i = 1; i < drawn.points.size(); ++i)
            arc.push_back(arc.back() + angleBetween(drawn.points[i - 1], drawn.points[i]));
        const double span = drawn.times.back() - drawn.times.front();
        for (std::size_t i = 0; i < drawn.points.size(); ++i)
            QVERIFY(std::abs((drawn.times[i] - drawn.times.front()) / span - arc[i] / arc.back()) < 1e-9);

        stack.undo();
        QVERIFY(strokes().empty());
        stack.redo();
        QCOMPARE(strokes().size(), std::size_t(1));
        QCOMPARE(strokes().front().points, drawn.points);
        QCOMPARE(strokes().front().times, drawn.times);
    }

    void aStrokeAgainstTheCurvesTimeOrWithinAFrameStaysUntimed()
    {
        // Backwards: from 2.2 s to 1.0 s along the curve.
        std::vector<Eigen::Vector3d> backwards = curveDirections(1.0, 2.2);
        std::reverse(backwards.begin(), backwards.end());
        dragThrough(view_, pixelsOf(backwards));
        QCOMPARE(strokes().size(), std::size_t(1));
        QVERIFY(strokes().front().points.size() > 2);
        QVERIFY(strokes().front().times.empty());

        // Out from the curve at 1.5 s and back to it: both ends at the same time.
        const Eigen::Vector3d onCurve = direction(1.5);
        const QPointF start = view_->projectToWidget(onCurve);
        dragThrough(view_, {start, start + QPointF(40, 0), start + QPointF(40, 40), start + QPointF(0, 1)});
        QCOMPARE(strokes().size(), std::size_t(2));
        QVERIFY(strokes().back().points.size() > 2);
        QVERIFY(strokes().back().times.empty());
        QCOMPARE(document_->undoStack().count(), 2);
    }

    void turningTheSphereChangesOnlyTheView()
    {
        const Eigen::Vector3d xAxis = Eigen::Vector3d::UnitX();
        for (Qt::MouseButton button : {Qt::RightButton, Qt::MiddleButton}) {
            const QPointF before = view_->projectToWidget(xAxis);
            const QPointF centre(view_->width() / 2.0, view_->height() / 2.0);
            dragThrough(view_, {centre, centre + QPointF(30, 10), centre + QPointF(60, 20)}, button);
            const QPointF after = view_->projectToWidget(xAxis);
            QVERIFY2(std::hypot(after.x() - before.x(), after.y() - before.y()) > 10.0,
                     qPrintable(QStringLiteral("x moved %1 px").arg(std::hypot(after.x() - before.x(), after.y() - before.y()))));
        }
        QCOMPARE(document_->undoStack().count(), 0);
        QVERIFY(!document_->isModified());
        QVERIFY(strokes().empty());

        // The left button draws, and with the Pattern tool it turns too.
        view_->patternAction()->trigger();
        QCOMPARE(view_->tool(), Tool::Pattern);
        const QPointF before = view_->projectToWidget(xAxis);
        const QPointF centre(view_->width() / 2.0, view_->height() / 2.0);
        dragThrough(view_, {centre, centre - QPointF(50, 0)});
        QVERIFY(view_->projectToWidget(xAxis) != before);
        QCOMPARE(document_->undoStack().count(), 0);
    }

    void erasingTheMiddleOfAStrokeSplitsItInOneStep()
    {
        // Eleven points 20 px apart across the middle of the sphere, timed 1 s to 2 s.
        const QPointF centre(view_->width() / 2.0, view_->height() / 2.0);
        model::DirectionStroke stroke;
        for (int i = 0; i <= 10; ++i) {
            stroke.points.push_back(view_->sphereAt(centre + QPointF(20.0 * (i - 5), 0.0)));
            stroke.times.push_back(1.0 + 0.1 * i);
        }
        document_->push(new model::AddStrokeCommand(*document_, object_, stroke));
        QUndoStack& stack = document_->undoStack();
        QCOMPARE(stack.count(), 1);

        view_->eraseAction()->trigger();
        QCOMPARE(view_->tool(), Tool::Erase);
        dragThrough(view_, {centre, centre + QPointF(0, 3), centre + QPointF(0, -3)});

        QCOMPARE(stack.count(), 2);
        QCOMPARE(strokes().size(), std::size_t(2));
        for (std::size_t part = 0; part < 2; ++part) {
            const model::DirectionStroke& piece = strokes()[part];
            QCOMPARE(piece.points.size(), std::size_t(5));
            for (std::size_t i = 0; i < 5; ++i) {
                const std::size_t original = part * 6 + i; // point 5 is gone
                QVERIFY(angleBetween(piece.points[i], stroke.points[original]) < 1e-12);
                QCOMPARE(piece.times[i], stroke.times[original]);
            }
        }

        stack.undo();
        QCOMPARE(strokes().size(), std::size_t(1));
        QCOMPARE(strokes().front().points.size(), std::size_t(11));
        stack.redo();
        QCOMPARE(strokes().size(), std::size_t(2));

        // Erasing all that is left of a piece takes the piece away, again in one step.
        std::vector<QPointF> overFirstPiece;
        for (int i = 0; i <= 4; ++i)
            overFirstPiece.push_back(centre + QPointF(20.0 * (i - 5), 0.0));
        dragThrough(view_, overFirstPiece);
        QCOMPARE(stack.count(), 3);
        QCOMPARE(strokes().size(), std::size_t(1));
        QCOMPARE(strokes().front().times.front(), 1.6);
        stack.undo();
        QCOMPARE(strokes().size(), std::size_t(2));
    }

    void thePadSetsThePatternAndTheRepeat()
    {
        QUndoStack& stack = document_->undoStack();
        view_->patternAction()->trigger();
        app::PatternPad* pad = panel_->patternPad();
        QVERIFY(pad->isVisible());
        app::PatternCanvas* canvas = pad->canvas();
        QCOMPARE(pad->repeatBox()->value(), 0);

        // One wave, drawn left to right.
        std::vector<Eigen::Vector2d> wave;
        for (int i = 0; i <= 24; ++i) {
            const double x = 0.1 + 0.05 * i;
            wave.emplace_back(x, 0.25 * std::sin(2.0 * std::numbers::pi * i / 24.0));
        }
        std::vector<QPointF> pixels;
        for (const Eigen::Vector2d& point : wave)
            pixels.push_back(canvas->toWidget(point));
        dragThrough(canvas, pixels);

        QCOMPARE(stack.count(), 1);
        QCOMPARE(stack.undoText(), QStringLiteral("Draw Pattern"));
        const model::SketchState& sketch = document_->object(object_)->track.sketch;
        QCOMPARE(sketch.pattern.size(), wave.size());
        const double pixel = 1.0 / canvas->height();
        for (std::size_t i = 0; i < wave.size(); ++i)
            QVERIFY((sketch.pattern[i] - wave[i]).norm() < pixel);
        QCOMPARE(sketch.patternRepeat, app::PatternPad::kDefaultRepeat);
        QCOMPARE(pad->repeatBox()->value(), app::PatternPad::kDefaultRepeat);

        // Edits of the repeat count merge into one step.
        pad->repeatBox()->setValue(11);
        pad->repeatBox()->setValue(13);
        QCOMPARE(document_->object(object_)->track.sketch.patternRepeat, 13);
        QCOMPARE(stack.count(), 2);
        stack.undo();
        QCOMPARE(document_->object(object_)->track.sketch.patternRepeat, app::PatternPad::kDefaultRepeat);
        QCOMPARE(pad->repeatBox()->value(), app::PatternPad::kDefaultRepeat);
        stack.undo();
        QVERIFY(document_->object(object_)->track.sketch.pattern.empty());
        QCOMPARE(pad->repeatBox()->value(), 0);
        stack.redo();
        stack.redo();

        // Clear: no pattern, repeat 0, one step.
        QTest::mouseClick(pad->clearButton(), Qt::LeftButton);
        QCOMPARE(stack.count(), 3);
        QVERIFY(document_->object(object_)->track.sketch.pattern.empty());
        QCOMPARE(document_->object(object_)->track.sketch.patternRepeat, 0);
    }

    void theSphereShowsTheStrokeWithThePatternApplied()
    {
        dragThrough(view_, pixelsOf(curveDirections(1.0, 2.2)));
        view_->patternAction()->trigger();
        app::PatternCanvas* canvas = panel_->patternPad()->canvas();
        std::vector<QPointF> zigzag;
        for (int i = 0; i <= 8; ++i)
            zigzag.push_back(canvas->toWidget(Eigen::Vector2d(0.1 + 0.1 * i, i % 2 == 0 ? 0.0 : 0.3)));
        dragThrough(canvas, zigzag);
        const model::DirectionStroke drawn = strokes().front();
        // Eight repetitions of a zigzag leave the drawn curve: the target, once the pattern's answer
        // arrives, has more points and wanders off the stroke.
        const auto farthestFromStroke = [&] {
            double farthest = 0.0;
            for (const fit::TimedVector& sample : view_->curves().targetStrokes.front()) {
                double nearest = std::numbers::pi;
                for (const Eigen::Vector3d& point : drawn.points)
                    nearest = std::min(nearest, angleBetween(sample.value, point));
                farthest = std::max(farthest, nearest);
            }
            return farthest;
        };
        const auto& targets = view_->curves().targetStrokes;
        QTRY_VERIFY_WITH_TIMEOUT(targets.size() == 1 && targets.front().size() > drawn.points.size() && farthestFromStroke() > 0.01, 5000);
    }

    void aFitShowsTheMotionBeforeAndAfterOverItsSpan()
    {
        // A fit of 1 s to 2 s by hand: the top's orientations at the ends, turning about z alone.
        model::FitResult fitted{{}, track().keys};
        for (double t : {1.0, 2.0}) {
            const Eigen::Quaterniond q = motion_->at(t).orientation;
            const Eigen::Quaterniond omega(0.0, 0.0, 0.0, 3.0);
            const Eigen::Quaterniond derivative = Eigen::Quaterniond((omega * q).coeffs() * 0.5); // q′ = ½ωq
            fitted.curve.push_back({t, q, derivative});
        }
        QSignalSpy updated(view_, &app::SphereView::curvesUpdated);
        document_->push(new model::ApplyFitResultCommand(*document_, object_, fitted));
        QVERIFY(updated.wait(5000));

        const app::SphereCurves& curves = view_->curves();
        QVERIFY(curves.fitSpan.has_value());
        QCOMPARE(curves.fitSpan->first, 1.0);
        QCOMPARE(curves.fitSpan->second, 2.0);
        QVERIFY(!curves.beforeFit.empty());
        for (const app::DirectionRun& run : curves.beforeFit)
            for (const fit::TimedVector& sample : run)
                QVERIFY(sample.time >= 1.0 && sample.time <= 2.0);
        // Inside the span the motion is the fit's, and the grey curve the motion through the keys.
        const model::TrackMotion withFit(track());
        const Eigen::Vector3d achieved = *app::directionAt(curves.motion, 1.5);
        const Eigen::Vector3d before = *app::directionAt(curves.beforeFit, 1.5);
        QVERIFY(angleBetween(achieved, withFit.angularVelocity(1.5).normalized()) < 1e-3);
        QVERIFY(angleBetween(before, direction(1.5)) < 1e-3);
        QVERIFY(angleBetween(achieved, before) > 0.1);

        document_->undoStack().undo();
        QVERIFY(updated.wait(5000));
        QVERIFY(!view_->curves().fitSpan);
        QVERIFY(view_->curves().beforeFit.empty());
    }

    void escapeTakesBackTheStrokeBeingDrawn()
    {
        QUndoStack& stack = document_->undoStack();
        const std::vector<QPointF> pixels = pixelsOf(curveDirections(1.0, 2.0));
        QTest::mousePress(view_, Qt::LeftButton, {}, pixels.front().toPoint());
        for (std::size_t i = 1; i < pixels.size() / 2; ++i)
            moveWithButton(view_, pixels[i], Qt::LeftButton);
        QCOMPARE(strokes().size(), std::size_t(1)); // in the document while it is drawn
        QTest::keyClick(view_, Qt::Key_Escape);
        QVERIFY(strokes().empty());
        // The pen goes on, but the stroke is over.
        for (std::size_t i = pixels.size() / 2; i < pixels.size(); ++i)
            moveWithButton(view_, pixels[i], Qt::LeftButton);
        QTest::mouseRelease(view_, Qt::LeftButton, {}, pixels.back().toPoint());
        QVERIFY(strokes().empty());
        QCOMPARE(stack.index(), 0);
        QVERIFY(!document_->isModified());
    }

    void theSpinningTopSampleAfterItsFit()
    {
        // The paper's Fig. 3: the top's sketch with its wobble pattern, fitted, the fit in red over
        // the steady precession in grey.
        document_->loadAsUntitled(QStringLiteral(":/samples/spinning-top.gyre"));
        QVERIFY(selection_->selectedObject() != nullptr);
        const model::ObjectId top = selection_->object();
        const model::SketchFitProblem problem = model::sketchFitProblem(document_->object(top)->track, {});
        const fit::FitResult result = model::fitSketch(problem);
        document_->push(
            new model::ApplyFitResultCommand(*document_, top, model::appliedFitResult(document_->object(top)->track, result)));
        document_->setCurrentTime(6.0);
        const app::SphereCurves& curves = view_->curves();
        QTRY_VERIFY_WITH_TIMEOUT(curves.fitSpan.has_value() && !curves.beforeFit.empty() && !curves.targetStrokes.empty(), 5000);
        panel_->resize(500, 540); // a shown widget gets its resize event at once
        // Turned to look down at the pole, about which the top's axis turns.
        const QPointF centre(view_->width() / 2.0, view_->height() / 2.0);
        const QPointF pole = view_->projectToWidget(Eigen::Vector3d::UnitZ());
        const QPointF target = centre - QPointF(0.0, 0.3 * view_->sphereRadius());
        dragThrough(view_, {pole, target}, Qt::RightButton);
        const QPointF turned = view_->projectToWidget(Eigen::Vector3d::UnitZ());
        QVERIFY2(QLineF(turned, target).length() < 0.5 * QLineF(pole, target).length(),
                 qPrintable(QStringLiteral("the pole is at (%1, %2)").arg(turned.x()).arg(turned.y())));
        // The README's picture of the sphere (scripts/user-guide-screenshots.sh).
        const QString folder = qEnvironmentVariable("GYRE_GUIDE_IMAGES");
        if (!folder.isEmpty())
            QVERIFY(view_->grab().save(QDir(folder).filePath(QStringLiteral("sphere-view.png"))));
    }

    void withoutASelectionItSaysSo()
    {
        selection_->clear();
        QVERIFY(view_->message().contains(QStringLiteral("Select an object")));
        const int steps = document_->undoStack().count();
        const QPointF centre(view_->width() / 2.0, view_->height() / 2.0);
        dragThrough(view_, {centre, centre + QPointF(40, 0), centre + QPointF(80, 0)});
        QCOMPARE(document_->undoStack().count(), steps);
    }

    void movingTheCurrentTimeRedrawsOnlyTheDot()
    {
        view_->grab(); // whatever the set-up left to redraw
        const int builds = view_->layerBuilds();
        for (double seconds : {1.2, 1.6, 2.0}) {
            document_->setCurrentTime(seconds);
            const QImage shot = view_->grab().toImage();
            const Eigen::Vector3d dot = *app::directionAt(view_->curves().motion, seconds);
            QVERIFY(view_->facesViewer(dot));
            const QPointF pixel = view_->projectToWidget(dot) * view_->devicePixelRatioF();
            const QColor colour = shot.pixelColor(pixel.toPoint());
            // The dot's gold, not the orange of the curve under it.
            QVERIFY2(colour.red() > 200 && colour.green() > 180 && colour.blue() < 90, qPrintable(colour.name()));
        }
        QCOMPARE(view_->layerBuilds(), builds);

        // Turning the sphere redraws the layers once, however many moves the paint follows.
        const QPointF centre(view_->width() / 2.0, view_->height() / 2.0);
        dragThrough(view_, {centre, centre + QPointF(20, 0), centre + QPointF(40, 10)}, Qt::RightButton);
        view_->grab();
        QCOMPARE(view_->layerBuilds(), builds + 1);

        // New curves redraw them too.
        QSignalSpy updated(view_, &app::SphereView::curvesUpdated);
        addKeyAfterTheLast();
        QVERIFY(updated.wait(5000));
        view_->grab();
        QCOMPARE(view_->layerBuilds(), builds + 2);
    }

    void aKeyMovedButNotTurnedRedrawsNothing()
    {
        view_->grab(); // whatever the set-up left to redraw
        const int builds = view_->layerBuilds();
        QSignalSpy updated(view_, &app::SphereView::curvesUpdated);
        document_->undoStack().push(
            new model::SetKeyframePositionCommand(*document_, object_, 10, Eigen::Vector3d(0.5, 0.0, 0.0)));
        QVERIFY(updated.wait(5000));
        view_->grab();
        QCOMPARE(view_->layerBuilds(), builds);
    }

    void aHiddenViewSamplesNothingWhilePlayingUntilShown()
    {
        app::Playback playback(*document_);
        QSignalSpy updated(view_, &app::SphereView::curvesUpdated);
        QSignalSpy frames(document_.get(), &model::Document::currentTimeChanged);
        panel_->hide();
        const int builds = view_->layerBuilds();
        playback.play();
        addKeyAfterTheLast(); // the motion now runs to 3.5 s
        // Ten frames of playback, far longer than the sampler's interval.
        while (frames.count() < 10)
            QVERIFY(frames.wait(5000));
        QCOMPARE(updated.count(), 0);
        QCOMPARE(view_->layerBuilds(), builds);
        QVERIFY(lastMotionTime() <= kLastKey + 1e-9);

        panel_->show();
        QVERIFY(updated.wait(5000));
        QVERIFY(lastMotionTime() > kLastKey + 0.25);
        playback.pause();
    }

private:
    // A key at 3.5 s turned on from the last one, so that the motion goes on past kLastKey.
    void addKeyAfterTheLast()
    {
        model::Keyframe key = track().keys.back();
        key.time = kLastKey + 0.5;
        key.pose.orientation = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitY()) * key.pose.orientation;
        document_->undoStack().push(new model::ReplaceKeyframesCommand(*document_, {{object_, model::withKeys(track().keys, {key})}},
                                                                       model::ReplaceKeyframesCommand::Edit::Insert));
    }

    double lastMotionTime() const
    {
        double last = -std::numeric_limits<double>::infinity();
        for (const app::DirectionRun& run : view_->curves().motion)
            if (!run.empty())
                last = std::max(last, run.back().time);
        return last;
    }

    const model::MotionTrack& track() const { return document_->object(object_)->track; }
    const std::vector<model::DirectionStroke>& strokes() const { return track().sketch.directionStrokes; }

    Eigen::Vector3d direction(double time) const { return motion_->angularVelocity(time).normalized(); }

    // The direction of ω every 0.1 s from `from` to `to`, all on the front of the sphere.
    std::vector<Eigen::Vector3d> curveDirections(double from, double to) const
    {
        std::vector<Eigen::Vector3d> directions;
        for (double t = from; t <= to + 1e-9; t += 0.1) {
            directions.push_back(direction(t));
            if (!view_->facesViewer(directions.back()))
                qFatal("the direction at %g s is behind the sphere", t);
        }
        return directions;
    }

    std::vector<QPointF> pixelsOf(const std::vector<Eigen::Vector3d>& directions) const
    {
        std::vector<QPointF> pixels;
        for (const Eigen::Vector3d& d : directions)
            pixels.push_back(view_->projectToWidget(d));
        return pixels;
    }

    std::unique_ptr<model::Document> document_;
    std::unique_ptr<app::Selection> selection_;
    std::unique_ptr<model::TrackMotion> motion_;
    std::unique_ptr<app::DirectionSketchPanel> panel_;
    app::SphereView* view_ = nullptr;
    model::ObjectId object_ = model::kNoObject;
};

QTEST_MAIN(TestSphereView)
#include "tst_sphere_view.moc"
