// The magnitude plot on a Hermite track that turns 90° about z every second (keys at 0, 1, ..., 5 s):
// its current curve is the speed of that turn, measured here from the orientations; strokes drawn with
// the mouse become the sketch's magnitude curve, one undo step each, a later stroke replacing only its
// own span; the window's edges and grip drag the fit window by the dragged amount, clamped to the
// keys; a fit applied to the track shows as the fitted curve beside the motion before it. A key moved
// but not turned costs no replot, and a plot off screen samples nothing until it is shown (issue 18).

#include "app/selection.h"
#include "app/sketch/magnitude_plot.h"
#include "gui_test_support.h"
#include "model/commands/apply_fit_result_command.h"
#include "model/commands/retime_keyframes_command.h"
#include "model/commands/set_keyframe_orientation_command.h"
#include "model/commands/set_keyframe_position_command.h"
#include "model/commands/set_fit_window_command.h"
#include "model/commands/set_magnitude_curve_command.h"
#include "model/commands/toggle_keyframe_constraint_command.h"
#include "model/document.h"
#include "model/track_evaluation.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QLabel>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QTest>
#include <qcustomplot.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

using namespace gyre;
using Curve = app::MagnitudePlot::Curve;

namespace {

constexpr int kKeyCount = 6;
constexpr double kQuarterTurn = std::numbers::pi / 2.0;

Eigen::Quaterniond turnAboutZ(double angle)
{
    return Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()));
}

// Keys every second, each a quarter turn about z past the one before.
model::SceneObject spinningObject()
{
    model::SceneObject object;
    object.id = 1;
    object.name = QStringLiteral("top");
    object.track.interpolation = InterpolationMethod::Hermite;
    for (int key = 0; key < kKeyCount; ++key) {
        const Pose pose{turnAboutZ(key * kQuarterTurn), Eigen::Vector3d::Zero()};
        object.track.keys.push_back(model::Keyframe{double(key), pose, true});
    }
    return object;
}

// The angle about z of an orientation that turns about z only, unwrapped near `near`.
double angleAboutZ(const Eigen::Quaterniond& q, double near)
{
    const double angle = 2.0 * std::atan2(q.z(), q.w());
    return angle + 2.0 * std::numbers::pi * std::round((near - angle) / (2.0 * std::numbers::pi));
}

// Presses at `points.front()` (to the nearest pixel), moves through the rest with the left button
// held, releases at the last.
void dragThrough(QWidget* widget, const std::vector<QPointF>& points)
{
    QTest::mousePress(widget, Qt::LeftButton, {}, points.front().toPoint());
    for (const QPointF& at : std::vector(points.begin() + 1, points.end())) {
        // QTest::mouseMove does not say which buttons are held; a drag needs them.
        QMouseEvent move(QEvent::MouseMove, at, widget->mapToGlobal(at), Qt::NoButton, Qt::LeftButton, {});
        QApplication::sendEvent(widget, &move);
    }
    QTest::mouseRelease(widget, Qt::LeftButton, {}, points.back().toPoint());
}

struct Aim {
    double time;
    double magnitude;
};

} // namespace

class TestMagnitudePlot : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }

    void init()
    {
        document_ = std::make_unique<model::Document>();
        object_ = test::importAtStart(*document_, {spinningObject()}, model::TimeRange{24.0, 0.0, 6.0}).front();
        selection_ = std::make_unique<app::Selection>(*document_);
        selection_->selectObject(object_);
        plot_ = std::make_unique<app::MagnitudePlot>(*document_, *selection_);
        plot_->resize(700, 300);
        QSignalSpy updated(plot_.get(), &app::MagnitudePlot::curvesUpdated);
        plot_->show();
        QVERIFY(QTest::qWaitForWindowExposed(plot_.get()));
        QVERIFY(updated.wait(5000));
        QCOMPARE(plot_->graph(Curve::Current)->dataCount(), app::MagnitudePlot::kSampleCount);
    }

    void cleanup()
    {
        plot_.reset();
        selection_.reset();
        document_.reset();
    }

    void theCurrentCurveIsTheSpeedOfTheTurn()
    {
        const model::TrackMotion motion(track());
        constexpr double h = 1e-4;
        int checked = 0;
        for (const QCPGraphData& sample : *plot_->graph(Curve::Current)->data()) {
            // Inside the keys' span, away from its ends where the one-sided derivatives change the speed.
            if (sample.key < 0.5 || sample.key > kKeyCount - 1.5)
                continue;
            const double before = angleAboutZ(motion.at(sample.key - h).orientation, sample.key * kQuarterTurn);
            const double after = angleAboutZ(motion.at(sample.key + h).orientation, sample.key * kQuarterTurn);
            const double speed = (after - before) / (2.0 * h);
            QVERIFY2(std::abs(sample.value - speed) < 1e-5,
                     qPrintable(QStringLiteral("at %1 s: %2 against %3").arg(sample.key).arg(sample.value).arg(speed)));
            ++checked;
        }
        QVERIFY(checked > app::MagnitudePlot::kSampleCount / 2);
        // A quarter turn a second: over the inner keys [1, 4] the curve integrates to three quarter turns.
        double turned = 0.0;
        const auto& data = *plot_->graph(Curve::Current)->data();
        for (int k = 1; k < data.size(); ++k) {
            const double from = std::max(data.at(k - 1)->key, 1.0);
            const double to = std::min(data.at(k)->key, 4.0);
            if (to > from)
                turned += (to - from) * (data.at(k - 1)->value + data.at(k)->value) / 2.0;
        }
        QVERIFY2(std::abs(turned - 3.0 * kQuarterTurn) < 1e-2, qPrintable(QString::number(turned)));
        // The keys are on the curve, all constrained.
        QCOMPARE(plot_->graph(Curve::ConstrainedKeys)->dataCount(), kKeyCount);
        QCOMPARE(plot_->graph(Curve::FreeKeys)->dataCount(), 0);
        QCOMPARE(plot_->graph(Curve::ConstrainedKeys)->data()->at(2)->value, motion.angularVelocity(2.0).norm());
    }

    void aFreedKeyIsDrawnHollow()
    {
        QSignalSpy updated(plot_.get(), &app::MagnitudePlot::curvesUpdated);
        document_->undoStack().push(new model::ToggleKeyframeConstraintCommand(*document_, object_, 2));
        QVERIFY(updated.wait(5000));
        const QCPGraph* constrained = plot_->graph(Curve::ConstrainedKeys);
        const QCPGraph* free = plot_->graph(Curve::FreeKeys);
        QCOMPARE(constrained->dataCount(), kKeyCount - 1);
        QCOMPARE(free->dataCount(), 1);
        QCOMPARE(free->data()->at(0)->key, 2.0);
        QCOMPARE(constrained->scatterStyle().brush().color(), constrained->scatterStyle().pen().color());
        QVERIFY(free->scatterStyle().brush().color() != free->scatterStyle().pen().color());
    }

    void aStrokeDrawsTheMagnitudeCurveAsOneUndoStep()
    {
        const std::vector<Aim> aims{{1.0, 1.0}, {1.5, 1.4}, {2.0, 1.6}, {2.5, 1.2}, {3.0, 0.8}, {3.5, 0.5}};
        draw(aims);
        const std::vector<model::MagnitudePoint>& curve = track().sketch.magnitude;
        QCOMPARE(curve.size(), aims.size());
        for (std::size_t k = 0; k < aims.size(); ++k) {
            QVERIFY2(std::abs(curve[k].time - aims[k].time) <= secondsPerPixel(),
                     qPrintable(QStringLiteral("%1 against %2").arg(curve[k].time).arg(aims[k].time)));
            QVERIFY(std::abs(curve[k].magnitude - aims[k].magnitude) <= radiansPerSecondPerPixel());
        }
        QUndoStack& stack = document_->undoStack();
        QCOMPARE(stack.count(), 1);
        QCOMPARE(stack.text(0), QStringLiteral("Draw Magnitude Curve"));
        QCOMPARE(plot_->graph(Curve::Sketched)->dataCount(), int(aims.size()));
        const std::vector<model::MagnitudePoint> drawn = curve;
        stack.undo();
        QVERIFY(track().sketch.magnitude.empty());
        QCOMPARE(plot_->graph(Curve::Sketched)->dataCount(), 0);
        stack.redo();
        QCOMPARE(track().sketch.magnitude.size(), drawn.size());
        QCOMPARE(track().sketch.magnitude.back().magnitude, drawn.back().magnitude);
    }

    void aSecondStrokeReplacesOnlyItsSpan()
    {
        draw({{1.0, 0.5}, {2.0, 0.5}, {3.0, 0.5}, {4.0, 0.5}, {5.0, 0.5}});
        const std::vector<model::MagnitudePoint> first = track().sketch.magnitude;
        draw({{2.5, 1.5}, {3.0, 1.5}, {3.5, 1.5}});
        QCOMPARE(document_->undoStack().count(), 2);
        const std::vector<model::MagnitudePoint>& curve = track().sketch.magnitude;
        // 1, 2 kept; 2.5, 3, 3.5 drawn; 3 of the first replaced; 4, 5 kept.
        QCOMPARE(curve.size(), std::size_t(7));
        QCOMPARE(curve[0].time, first[0].time);
        QCOMPARE(curve[1].time, first[1].time);
        for (std::size_t k = 2; k < 5; ++k)
            QVERIFY(std::abs(curve[k].magnitude - 1.5) <= radiansPerSecondPerPixel());
        QCOMPARE(curve[5].time, first[3].time);
        QCOMPARE(curve[6].magnitude, first[4].magnitude);
        document_->undoStack().undo();
        QCOMPARE(track().sketch.magnitude.size(), first.size());
        QCOMPARE(track().sketch.magnitude[2].time, first[2].time);
    }

    void goingBackErasesWhatTheStrokeDrewAndNegativeBecomesZero()
    {
        draw({{1.0, 1.0}, {2.0, 1.0}, {3.0, 1.0}, {2.0, -1.0}});
        const std::vector<model::MagnitudePoint>& curve = track().sketch.magnitude;
        QCOMPARE(curve.size(), std::size_t(2));
        QVERIFY(std::abs(curve.back().time - 2.0) <= secondsPerPixel());
        QCOMPARE(curve.back().magnitude, 0.0);
        QCOMPARE(document_->undoStack().count(), 1);
    }

    void clearMagnitudeIsOneUndoStep()
    {
        QVERIFY(!plot_->clearMagnitudeAction()->isEnabled());
        draw({{1.0, 1.0}, {2.0, 1.0}});
        QVERIFY(plot_->clearMagnitudeAction()->isEnabled());
        plot_->clearMagnitudeAction()->trigger();
        QVERIFY(track().sketch.magnitude.empty());
        QCOMPARE(document_->undoStack().count(), 2);
        document_->undoStack().undo();
        QCOMPARE(track().sketch.magnitude.size(), std::size_t(2));
    }

    void draggingAnEdgeMovesThatEndAsOneUndoStep()
    {
        setWindow(1.0, 3.0);
        QVERIFY(plot_->shownWindowIsOwn());
        dragBy(edge(1.0), 0.5);
        QVERIFY(std::abs(window().first - 1.5) <= secondsPerPixel());
        QCOMPARE(window().second, 3.0);
        QUndoStack& stack = document_->undoStack();
        QCOMPARE(stack.count(), 1);
        QCOMPARE(stack.text(0), QStringLiteral("Set Fit Window"));
        stack.undo();
        QCOMPARE(window(), std::pair(1.0, 3.0));
        stack.redo();
        QVERIFY(std::abs(window().first - 1.5) <= secondsPerPixel());

        // Past the last key, the end stops at it; the start stops at the first.
        dragBy(edge(3.0), 4.0);
        QCOMPARE(window().second, double(kKeyCount - 1));
        QCOMPARE(stack.count(), 2);
        dragBy(edge(window().first), -4.0);
        QCOMPARE(window().first, 0.0);
        QCOMPARE(stack.count(), 3);
    }

    void draggingTheGripMovesTheWindowAtItsLength()
    {
        setWindow(1.0, 3.0);
        dragBy(grip(2.0), 1.0);
        QVERIFY(std::abs(window().first - 2.0) <= secondsPerPixel());
        QVERIFY(std::abs(window().second - window().first - 2.0) < 1e-9);
        QCOMPARE(document_->undoStack().count(), 1);
        dragBy(grip(3.0), 5.0);
        QCOMPARE(window(), std::pair(3.0, 5.0));
        QCOMPARE(document_->undoStack().count(), 2);
        document_->undoStack().undo();
        QVERIFY(std::abs(window().first - 2.0) <= secondsPerPixel());
    }

    void withoutAWindowTheBandIsImpliedAndThePanToolSetsOne()
    {
        QVERIFY(!plot_->shownWindowIsOwn());
        QCOMPARE(plot_->shownWindow(), std::optional(std::pair(0.0, double(kKeyCount - 1))));
        plot_->panAction()->trigger();
        dragBy(edge(0.0), 1.0);
        QVERIFY(track().sketch.window.has_value());
        QVERIFY(plot_->shownWindowIsOwn());
        QVERIFY(std::abs(window().first - 1.0) <= secondsPerPixel());
        document_->undoStack().undo();
        QVERIFY(!track().sketch.window.has_value());
    }

    void theFirstStrokeDrawsOverTheImpliedBandsEdgeAndGrip()
    {
        // The implied window spans the keys, 0 to 5 s: a stroke from its start edge, in its grip strip,
        // draws and leaves the window alone.
        QVERIFY(!plot_->shownWindowIsOwn());
        const QPointF start = grip(0.0);
        const double topMagnitude = plot_->valueAt(start).second;
        draw({{0.0, topMagnitude}, {1.0, topMagnitude}, {2.0, topMagnitude}});
        QVERIFY(!track().sketch.window.has_value());
        QCOMPARE(track().sketch.magnitude.size(), std::size_t(3));
        QVERIFY(std::abs(track().sketch.magnitude.front().time) <= secondsPerPixel());
        QCOMPARE(document_->undoStack().count(), 1);
        QCOMPARE(document_->undoStack().text(0), QStringLiteral("Draw Magnitude Curve"));
    }

    void theHeightFollowsTheMotionUnlessZoomedByHand()
    {
        // Keys twice as close turn twice as fast: the curve doubles, and the value axis follows it.
        const double highestBefore = highest(Curve::Current);
        QVERIFY(plot_->plot()->yAxis->range().upper >= highestBefore);
        retime(0.5);
        QVERIFY(highest(Curve::Current) > 1.9 * highestBefore);
        QVERIFY2(plot_->plot()->yAxis->range().upper >= highest(Curve::Current),
                 qPrintable(QStringLiteral("%1 shown for a curve up to %2")
                                .arg(plot_->plot()->yAxis->range().upper)
                                .arg(highest(Curve::Current))));
        QCOMPARE(plot_->plot()->yAxis->range().lower, 0.0);

        // Panned by hand, the view stays where the artist put it while the motion changes...
        plot_->panAction()->trigger();
        const QPointF middle = plot_->plotArea().center();
        dragThrough(plot_->plot(), {middle, middle + QPointF(0, 20), middle + QPointF(0, 40)});
        QVERIFY(plot_->viewMovedByHand());
        const QCPRange panned = plot_->plot()->yAxis->range();
        retime(2.0);
        QCOMPARE(plot_->plot()->yAxis->range().lower, panned.lower);
        QCOMPARE(plot_->plot()->yAxis->range().upper, panned.upper);
        // ...until Fit View (a double-click, or F), which shows the curves again.
        QTest::mouseDClick(plot_->plot(), Qt::LeftButton, {}, middle.toPoint());
        QVERIFY(!plot_->viewMovedByHand());
        QCOMPARE(plot_->plot()->yAxis->range().lower, 0.0);
        QVERIFY(plot_->plot()->yAxis->range().upper >= highest(Curve::Current));
        QVERIFY(plot_->plot()->yAxis->range().upper < 1.5 * highest(Curve::Current));
    }

    void aSketchWithoutAWindowImpliesTheSpanItCovers()
    {
        draw({{1.2, 1.0}, {2.0, 1.0}, {3.0, 1.0}});
        QVERIFY(!track().sketch.window.has_value());
        QVERIFY(!plot_->shownWindowIsOwn());
        const std::pair<double, double> implied = *plot_->shownWindow();
        QCOMPARE(implied.first, track().sketch.magnitude.front().time);
        QCOMPARE(implied.second, track().sketch.magnitude.back().time);
    }

    void aFitShowsAsTheFittedCurveBesideTheMotionBeforeIt()
    {
        QCOMPARE(plot_->graph(Curve::Fitted)->dataCount(), 0);
        // A fit over [1, 3] through the keys' orientations there that eases in and out: at rest at
        // both ends, half a turn in two seconds.
        model::FitResult result;
        result.keys = track().keys;
        result.curve = {HermiteControlPoint{1.0, turnAboutZ(kQuarterTurn), Eigen::Quaterniond(0, 0, 0, 0)},
                        HermiteControlPoint{3.0, turnAboutZ(3.0 * kQuarterTurn), Eigen::Quaterniond(0, 0, 0, 0)}};
        QSignalSpy updated(plot_.get(), &app::MagnitudePlot::curvesUpdated);
        document_->undoStack().push(new model::ApplyFitResultCommand(*document_, object_, result));
        QVERIFY(updated.wait(5000));

        const QCPGraph* fitted = plot_->graph(Curve::Fitted);
        const QCPGraph* beforeFit = plot_->graph(Curve::BeforeFit);
        QCOMPARE(fitted->dataCount(), app::MagnitudePlot::kFittedSampleCount);
        QCOMPARE(fitted->data()->at(0)->key, 1.0);
        QCOMPARE(fitted->data()->at(fitted->dataCount() - 1)->key, 3.0);
        const model::TrackMotion withFit(track());
        model::MotionTrack unfitted = track();
        unfitted.sketch.fittedCurve.clear();
        const model::TrackMotion withoutFit(unfitted);
        for (int sample : {0, 100, 299, 450, app::MagnitudePlot::kFittedSampleCount - 1}) {
            const double t = fitted->data()->at(sample)->key;
            QCOMPARE(fitted->data()->at(sample)->value, withFit.angularVelocity(t).norm());
            QCOMPARE(beforeFit->data()->at(sample)->value, withoutFit.angularVelocity(t).norm());
        }
        // Just after the fit's start (at it the central difference straddles both motions) the fit is
        // nearly at rest, where the keys' motion turns a quarter turn a second (π/2 rad/s at the
        // key: the spline's geodesic derivative there is the steady turn of the two arcs through it).
        QVERIFY(fitted->data()->at(1)->value < 0.05);
        QVERIFY(std::abs(beforeFit->data()->at(1)->value - std::numbers::pi / 2) < 0.05);
        QVERIFY(plot_->plot()->legend->hasItemWithPlottable(fitted));
        QVERIFY(plot_->plot()->legend->hasItemWithPlottable(beforeFit));
    }

    void thePanToolPansWithoutEditingAndDoubleClickFitsTheView()
    {
        plot_->panAction()->trigger();
        QVERIFY(!plot_->drawAction()->isChecked());
        const QPointF from = plot_->pixelFor(2.0, 0.5);
        dragThrough(plot_->plot(), {from, plot_->pixelFor(2.5, 0.5), plot_->pixelFor(3.0, 0.5)});
        // The time under the pointer stays under it: the view moved a second back.
        QVERIFY(std::abs(plot_->plot()->xAxis->range().lower + 1.0) < 2.0 * secondsPerPixel());
        QVERIFY(track().sketch.magnitude.empty());
        QCOMPARE(document_->undoStack().count(), 0);

        QTest::mouseDClick(plot_->plot(), Qt::LeftButton, {}, from.toPoint());
        QCOMPARE(plot_->plot()->xAxis->range().lower, 0.0);
        QCOMPARE(plot_->plot()->xAxis->range().upper, 6.0);
        QCOMPARE(document_->undoStack().count(), 0);
    }

    void withoutASelectionItSaysSo()
    {
        QVERIFY(!plot_->placeholder()->isVisible());
        selection_->clear();
        QVERIFY(plot_->placeholder()->isVisible());
        QVERIFY(!plot_->plot()->isVisible());
        QVERIFY(!plot_->drawAction()->isEnabled());
        selection_->selectObject(object_);
        QVERIFY(plot_->plot()->isVisible());
    }

    void aKeyMovedButNotTurnedCostsNoReplot()
    {
        QSignalSpy updated(plot_.get(), &app::MagnitudePlot::curvesUpdated);
        QSignalSpy replotted(plot_->plot(), &QCustomPlot::afterReplot);
        document_->undoStack().push(
            new model::SetKeyframePositionCommand(*document_, object_, 2, Eigen::Vector3d(0.5, 0.0, 0.0)));
        QVERIFY(updated.wait(5000));
        QCOMPARE(replotted.count(), 0);

        // Turned, it changes the speed: one replot.
        document_->undoStack().push(
            new model::SetKeyframeOrientationCommand(*document_, object_, 2, turnAboutZ(2 * kQuarterTurn + 0.3)));
        QVERIFY(updated.wait(5000));
        QCOMPARE(replotted.count(), 1);
        QCOMPARE(plot_->graph(Curve::ConstrainedKeys)->data()->at(2)->value,
                 model::TrackMotion(track()).angularVelocity(2.0).norm());
    }

    void anOffScreenPlotSamplesAndReplotsNothingUntilShown()
    {
        constexpr int kInterval = app::SelectedTrackSampler<int>::kIntervalMilliseconds;
        plot_->hide();
        QSignalSpy updated(plot_.get(), &app::MagnitudePlot::curvesUpdated);
        QSignalSpy replotted(plot_->plot(), &QCustomPlot::afterReplot);
        // A key turned a little further at each move of a drag, each move longer than the sampler's interval.
        for (int move = 1; move <= 5; ++move) {
            document_->undoStack().push(new model::SetKeyframeOrientationCommand(
                *document_, object_, 2, turnAboutZ(2 * kQuarterTurn + 0.1 * move)));
            QVERIFY(!updated.wait(2 * kInterval));
        }
        QCOMPARE(replotted.count(), 0);

        plot_->show();
        QVERIFY(updated.wait(5000));
        QCOMPARE(plot_->graph(Curve::ConstrainedKeys)->data()->at(2)->value,
                 model::TrackMotion(track()).angularVelocity(2.0).norm());
        // Once: nothing more is asked for.
        QVERIFY(!updated.wait(2 * kInterval));
        QCOMPARE(updated.count(), 1);
    }

    void screenshotWithASketchAndAWindow()
    {
        setWindow(1.0, 4.0);
        // Off the window's edges, which a press there would drag.
        draw({{1.2, 0.9}, {1.6, 1.3}, {2.0, 1.7}, {2.5, 1.9}, {3.0, 1.5}, {3.5, 1.0}, {3.8, 0.8}});
        QVERIFY(!track().sketch.magnitude.empty());
        // A fit over the window that speeds up to 2 rad/s in its middle, three quarter turns in all.
        const auto spinning = [](double time, double angle, double rate) {
            const Eigen::Quaterniond q = turnAboutZ(angle);
            // q′ = ½ω q for ω = rate about z.
            return HermiteControlPoint{time, q, Eigen::Quaterniond(Eigen::Quaterniond(0, 0, 0, rate / 2.0) * q)};
        };
        model::FitResult result;
        result.keys = track().keys;
        result.curve = {spinning(1.0, kQuarterTurn, 1.0), spinning(2.5, kQuarterTurn + 2.4, 2.0),
                        spinning(4.0, 4.0 * kQuarterTurn, 1.0)};
        QSignalSpy updated(plot_.get(), &app::MagnitudePlot::curvesUpdated);
        document_->undoStack().push(new model::ApplyFitResultCommand(*document_, object_, result));
        document_->setCurrentTime(2.2);
        QVERIFY(updated.wait(5000));
        plot_->fitView();
        const QString path = QDir::temp().filePath(QStringLiteral("magnitude-plot.png"));
        QVERIFY(plot_->grab().save(path));
    }

private:
    const model::MotionTrack& track() const { return document_->object(object_)->track; }
    std::pair<double, double> window() const { return *track().sketch.window; }

    double secondsPerPixel() const
    {
        return plot_->valueAt({1.0, 0.0}).first - plot_->valueAt({0.0, 0.0}).first;
    }
    double radiansPerSecondPerPixel() const
    {
        return plot_->valueAt({0.0, 0.0}).second - plot_->valueAt({0.0, 1.0}).second;
    }

    void draw(const std::vector<Aim>& aims)
    {
        std::vector<QPointF> points;
        for (const Aim& aim : aims)
            points.push_back(plot_->pixelFor(aim.time, aim.magnitude));
        dragThrough(plot_->plot(), points);
    }

    double highest(Curve curve) const
    {
        double found = 0.0;
        for (const QCPGraphData& point : *plot_->graph(curve)->data())
            found = std::max(found, point.value);
        return found;
    }

    // Moves every key to `factor` times its time, one undo step, and waits for the new curves.
    void retime(double factor)
    {
        QSignalSpy updated(plot_.get(), &app::MagnitudePlot::curvesUpdated);
        document_->undoStack().push(new model::RetimeKeyframesCommand(*document_, object_, factor, 0.0));
        QVERIFY(updated.wait(5000));
    }

    void setWindow(double start, double end)
    {
        document_->undoStack().push(new model::SetFitWindowCommand(*document_, object_, std::pair(start, end)));
        document_->undoStack().clear();
    }

    // The middle of the window's edge at `time`, and the middle of its grip strip at `time`.
    QPointF edge(double time) const { return {plot_->pixelFor(time, 0.0).x(), double(plot_->plotArea().center().y())}; }
    QPointF grip(double time) const
    {
        return {plot_->pixelFor(time, 0.0).x(), plot_->plotArea().top() + app::MagnitudePlot::kGripHeight / 2.0};
    }

    // Drags from `from` across by `seconds`, in ten moves.
    void dragBy(const QPointF& from, double seconds)
    {
        const QPointF to(plot_->pixelFor(plot_->valueAt(from).first + seconds, 0.0).x(), from.y());
        std::vector<QPointF> points;
        for (int step = 0; step <= 10; ++step)
            points.push_back(from + (to - from) * step / 10.0);
        dragThrough(plot_->plot(), points);
    }

    std::unique_ptr<model::Document> document_;
    std::unique_ptr<app::Selection> selection_;
    std::unique_ptr<app::MagnitudePlot> plot_;
    model::ObjectId object_ = model::kNoObject;
};

QTEST_MAIN(TestMagnitudePlot)
#include "tst_magnitude_plot.moc"
