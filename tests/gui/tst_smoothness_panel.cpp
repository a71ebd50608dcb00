// The smoothness plots of the bundled sample checked against the track's motion evaluated here: the
// position curve is the motion of the chosen point, the velocity and acceleration curves are its
// central differences in units/s and units/s², and choosing another point changes the curves.
// Tabbed behind another dock, the panel samples and replots nothing until it is brought to the front
// (issue 18).

#include "app/main_window.h"
#include "app/sketch/magnitude_plot.h"
#include "app/sketch/sphere_view.h"
#include "app/smoothness_panel.h"
#include "gui_test_support.h"
#include "model/commands/set_keyframe_position_command.h"
#include "model/track_evaluation.h"

#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QTest>
#include <qcustomplot.h>

#include <cmath>
#include <memory>

using namespace gyre;
using Quantity = app::SmoothnessPanel::Quantity;
using Component = app::SmoothnessPanel::Component;

namespace {

// Sample indices spread over the range, ends included.
constexpr int kCheckedSamples[] = {0, 1, 333, 1000, 1517, 1998, 1999};

double valueAt(const app::SmoothnessPanel& panel, Quantity quantity, Component component, int sample)
{
    return panel.graph(quantity, component)->data()->at(sample)->value;
}

double timeAt(const app::SmoothnessPanel& panel, int sample)
{
    return panel.graph(Quantity::Position, Component::X)->data()->at(sample)->key;
}

} // namespace

class TestSmoothnessPanel : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }

    void init()
    {
        window_ = std::make_unique<app::MainWindow>();
        window_->show();
        // The window opens with the inspector in front of the panel, which then samples nothing.
        dock("smoothnessDock")->raise();
        panel_ = window_->findChild<app::SmoothnessPanel*>();
        QVERIFY(panel_ != nullptr);
        QSignalSpy updated(panel_, &app::SmoothnessPanel::curvesUpdated);
        window_->openBundledSample();
        window_->playback().pause();
        QVERIFY(updated.wait(5000));
        QCOMPARE(panel_->graph(Quantity::Position, Component::X)->dataCount(), app::SmoothnessPanel::kSampleCount);
    }

    void cleanup() { window_.reset(); }

    // One edit of the track builds its motion once: the viewport, the sphere, the speed plot and these
    // plots all sample the document's one motion of it (Document::motion).
    void sharesOneMotionPerChangeWithTheOtherViews()
    {
        model::Document& document = window_->document();
        QSignalSpy smoothness(panel_, &app::SmoothnessPanel::curvesUpdated);
        QSignalSpy speed(window_->findChild<app::MagnitudePlot*>(), &app::MagnitudePlot::curvesUpdated);
        QSignalSpy sphere(window_->findChild<app::SphereView*>(), &app::SphereView::curvesUpdated);
        const std::size_t builds = document.motionBuilds();
        document.push(new model::SetKeyframePositionCommand(document, window_->selection().object(), 0, {0.5, 0.0, 0.0}));
        QVERIFY(smoothness.wait(5000));
        QTRY_VERIFY_WITH_TIMEOUT(!speed.isEmpty() && !sphere.isEmpty(), 5000);
        QCOMPARE(document.motionBuilds(), builds + 1);
    }

    void thePositionCurveIsTheTrackMotionOfTheOrigin()
    {
        const model::TrackMotion motion(window_->selection().selectedObject()->track);
        const model::Scene& scene = window_->document().scene();
        QCOMPARE(timeAt(*panel_, 0), scene.startTime);
        QCOMPARE(timeAt(*panel_, app::SmoothnessPanel::kSampleCount - 1), scene.endTime);
        for (int sample : kCheckedSamples) {
            const double t = timeAt(*panel_, sample);
            const Eigen::Vector3d expected = motion.at(t).position;
            QCOMPARE(valueAt(*panel_, Quantity::Position, Component::X, sample), expected.x());
            QCOMPARE(valueAt(*panel_, Quantity::Position, Component::Y, sample), expected.y());
            QCOMPARE(valueAt(*panel_, Quantity::Position, Component::Z, sample), expected.z());
            QCOMPARE(valueAt(*panel_, Quantity::Position, Component::Magnitude, sample), expected.norm());
        }
    }

    void theDerivativesAreCentralDifferencesOverTime()
    {
        const model::TrackMotion motion(window_->selection().selectedObject()->track);
        const double step = timeAt(*panel_, 1) - timeAt(*panel_, 0);
        for (int sample : kCheckedSamples) {
            const double t = timeAt(*panel_, sample);
            const Eigen::Vector3d before = motion.at(t - step).position;
            const Eigen::Vector3d middle = motion.at(t).position;
            const Eigen::Vector3d after = motion.at(t + step).position;
            const Eigen::Vector3d velocity = (after - before) / (2.0 * step);
            const Eigen::Vector3d acceleration = (after - 2.0 * middle + before) / (step * step);
            for (Component component : {Component::X, Component::Y, Component::Z}) {
                const auto axis = static_cast<Eigen::Index>(component);
                // The panel's sample times are start + k·Δ, which can differ from t ± Δ here in the
                // last bit; the difference quotients magnify that by 1/Δ and 1/Δ².
                QVERIFY(std::abs(valueAt(*panel_, Quantity::Velocity, component, sample) - velocity[axis]) < 1e-8);
                QVERIFY(std::abs(valueAt(*panel_, Quantity::Acceleration, component, sample) - acceleration[axis]) <
                        1e-4);
            }
        }
    }

    void theVelocityAgreesWithAFineDerivative()
    {
        // The sample's keys are a second apart and subdivided `levels` times, so the polyscrew's
        // joints, where the velocity may kink, are 2^-levels s apart. Between them the motion is one
        // screw, smooth, and the panel's difference over Δ ≈ 3 ms measures what one over 1 µs does.
        const model::MotionTrack& track = window_->selection().selectedObject()->track;
        const model::TrackMotion motion(track);
        const double jointsPerSecond = std::ldexp(1.0, track.subdivision.levels);
        constexpr double h = 1e-6;
        int checked = 0;
        for (int sample = 0; sample < app::SmoothnessPanel::kSampleCount; ++sample) {
            const double t = timeAt(*panel_, sample);
            const double fromJoint = std::abs(t * jointsPerSecond - std::round(t * jointsPerSecond));
            if (fromJoint < 0.25)
                continue;
            const Eigen::Vector3d fine = (motion.at(t + h).position - motion.at(t - h).position) / (2.0 * h);
            const double speed = valueAt(*panel_, Quantity::Velocity, Component::Magnitude, sample);
            QVERIFY2(std::abs(speed - fine.norm()) < 1e-3 * std::max(1.0, fine.norm()),
                     qPrintable(QStringLiteral("at %1 s: %2 against %3").arg(t).arg(speed).arg(fine.norm())));
            ++checked;
        }
        QVERIFY(checked > app::SmoothnessPanel::kSampleCount / 3);
    }

    void anotherPointChangesTheCurves()
    {
        const int sample = 1517; // about 4.55 s, where the block is turned
        const double originX = valueAt(*panel_, Quantity::Position, Component::X, sample);
        QSignalSpy updated(panel_, &app::SmoothnessPanel::curvesUpdated);
        panel_->findChild<QDoubleSpinBox*>(QStringLiteral("pointXBox"))->setValue(2.0);
        QVERIFY(updated.wait(5000));
        QCOMPARE(panel_->point(), Eigen::Vector3d(2.0, 0.0, 0.0));

        const model::TrackMotion motion(window_->selection().selectedObject()->track);
        const double t = timeAt(*panel_, sample);
        const Eigen::Vector3d expected = motion.at(t).apply(Eigen::Vector3d(2.0, 0.0, 0.0));
        QCOMPARE(valueAt(*panel_, Quantity::Position, Component::X, sample), expected.x());
        QVERIFY(std::abs(valueAt(*panel_, Quantity::Position, Component::X, sample) - originX) > 1e-3);
    }

    void aPanelTabbedAwayDoesNothingWhileAKeyIsDraggedUntilShown()
    {
        constexpr int kInterval = app::SelectedTrackSampler<model::PointTrajectory>::kIntervalMilliseconds;
        dock("inspectorDock")->raise();
        // Qt keeps a dock tabbed behind another visible, out of the window.
        QTRY_VERIFY(panel_->visibleRegion().isEmpty());
        QVERIFY(panel_->isVisible());
        // Curves asked for while the panel was in front may still be on their way (a posted sampling
        // is shown when it ends): the drag starts once none is.
        QTRY_VERIFY_WITH_TIMEOUT(!panel_->isSampling(), 30000);
        QSignalSpy updated(panel_, &app::SmoothnessPanel::curvesUpdated);
        QSignalSpy replotted(panel_->plot(), &QCustomPlot::afterReplot);
        model::Document& document = window_->document();
        const model::ObjectId object = window_->selection().object();
        const Eigen::Vector3d start = document.object(object)->track.keys[0].pose.position;
        // Each move of the drag longer than the sampler's interval.
        for (int move = 1; move <= 5; ++move) {
            document.undoStack().push(new model::SetKeyframePositionCommand(
                document, object, 0, start + Eigen::Vector3d(0.1 * move, 0.0, 0.0)));
            QVERIFY(!updated.wait(2 * kInterval));
        }
        QCOMPARE(replotted.count(), 0);

        dock("smoothnessDock")->raise();
        QVERIFY(updated.wait(5000));
        QCOMPARE(replotted.count(), 1);
        const model::TrackMotion motion(document.object(object)->track);
        QCOMPARE(valueAt(*panel_, Quantity::Position, Component::X, 0), motion.at(timeAt(*panel_, 0)).position.x());
        // Once: nothing more is asked for.
        QVERIFY(!updated.wait(2 * kInterval));
        QCOMPARE(updated.count(), 1);
    }

private:
    QDockWidget* dock(const char* name) const { return window_->findChild<QDockWidget*>(QString::fromLatin1(name)); }

    std::unique_ptr<app::MainWindow> window_;
    app::SmoothnessPanel* panel_ = nullptr;
};

QTEST_MAIN(TestSmoothnessPanel)
#include "tst_smoothness_panel.moc"
