// The fit panel, its controller and the status bar's progress on a steady spin about z (keys every
// second over 4 s) whose sketch, made with the model's commands, tilts the spin towards x over 1–3 s.
// Fit applies one undo step that bends ω towards the sketch and keeps the constrained keys; Cancel
// leaves the document as it was; the panel's edits are undo steps; Live previews while a stroke is
// drawn and applies one fit when it ends; a track changed while its fit ran is not applied.

#include "app/selection.h"
#include "app/sketch/fit_controller.h"
#include "app/sketch/fit_panel.h"
#include "app/sketch/fit_progress.h"
#include "app/viewport/viewport.h"
#include "core/torque_free.h"
#include "gui_test_support.h"
#include "model/sketch_fit_problem.h"
#include "model/commands/add_stroke_command.h"
#include "model/commands/edit_stroke_command.h"
#include "model/commands/import_objects_command.h"
#include "model/commands/replace_keyframes_command.h"
#include "model/commands/set_fit_parameter_command.h"
#include "model/commands/set_fit_window_command.h"
#include "model/commands/set_interpolation_command.h"
#include "model/commands/set_keyframe_orientation_command.h"
#include "model/commands/set_keyframe_time_command.h"
#include "model/commands/set_magnitude_curve_command.h"
#include "model/commands/set_mass_override_command.h"
#include "model/commands/toggle_keyframe_constraint_command.h"
#include "model/document.h"
#include "model/gesture.h"
#include "model/key_edits.h"
#include "model/scene_motion.h"
#include "model/track_evaluation.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFrame>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QStatusBar>
#include <QTableWidget>
#include <QTest>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <vector>

using namespace gyre;

namespace {

constexpr double kSpinRate = std::numbers::pi / 2; // rad/s about z
constexpr double kTilt = std::numbers::pi / 3;     // of the sketched direction at its end
// QTRY waits up to three times this when the condition stays false; the test function has 300 s.
constexpr int kFitTimeoutMilliseconds = 60'000;
const QString kApplyFitText = QStringLiteral("Apply angular velocity fit");

// Keys every `spacing` seconds over [0, duration] of a steady spin about z, Hermite.
model::SceneObject spinningObject(double duration, double spacing)
{
    model::SceneObject object;
    object.id = 1;
    object.name = QStringLiteral("Top");
    object.track.interpolation = InterpolationMethod::Hermite;
    const int keys = static_cast<int>(std::lround(duration / spacing)) + 1;
    for (int i = 0; i < keys; ++i) {
        model::Keyframe key;
        key.time = i * spacing;
        key.pose.orientation = Eigen::AngleAxisd(kSpinRate * key.time, Eigen::Vector3d::UnitZ());
        object.track.keys.push_back(key);
    }
    return object;
}

// The sketched direction at `time` in [start, end]: from z, tilting towards x by `tilt` at the end.
Eigen::Vector3d sketchedDirection(double time, double start, double end, double tilt)
{
    const double angle = tilt * (time - start) / (end - start);
    return {std::sin(angle), 0.0, std::cos(angle)};
}

model::DirectionStroke tiltingStroke(double start, double end, double tilt)
{
    model::DirectionStroke stroke;
    constexpr int kPoints = 17;
    for (int i = 0; i < kPoints; ++i) {
        const double time = start + (end - start) * i / (kPoints - 1);
        stroke.points.push_back(sketchedDirection(time, start, end, tilt));
        stroke.times.push_back(time);
    }
    return stroke;
}

// The world angular velocity of the torque-free motion from orientation q0 and world ω0 after each of
// `times` (from 0, increasing), by fixed-step RK4 of Euler's equations in the body frame,
//     I·ω̇ = (I·ω)×ω,   q̇ = ½·q⊗(0, ω),
// at steps of at most `step` seconds; independent of core/torque_free's integrator.
std::vector<Eigen::Vector3d> eulerRk4(const Eigen::Matrix3d& inertia, const Eigen::Quaterniond& q0,
                                      const Eigen::Vector3d& worldOmega0, const std::vector<double>& times, double step)
{
    using State = Eigen::Matrix<double, 7, 1>; // ω body x, y, z; q w, x, y, z
    const Eigen::Matrix3d inverse = inertia.inverse();
    const auto rate = [&](const State& s) {
        const Eigen::Vector3d omega = s.head<3>();
        const Eigen::Quaterniond q(s[3], s[4], s[5], s[6]);
        const Eigen::Quaterniond dq = q * Eigen::Quaterniond(0.0, omega.x(), omega.y(), omega.z());
        State d;
        d.head<3>() = inverse * (inertia * omega).cross(omega);
        d.tail<4>() = 0.5 * Eigen::Vector4d(dq.w(), dq.x(), dq.y(), dq.z());
        return d;
    };
    State state;
    state.head<3>() = q0.conjugate() * worldOmega0;
    state.tail<4>() << q0.w(), q0.x(), q0.y(), q0.z();
    std::vector<Eigen::Vector3d> result;
    double now = 0.0;
    for (const double time : times) {
        const int steps = std::max(1, static_cast<int>(std::ceil((time - now) / step)));
        const double h = (time - now) / steps;
        for (int i = 0; i < steps && h > 0.0; ++i) {
            const State k1 = rate(state);
            const State k2 = rate(state + 0.5 * h * k1);
            const State k3 = rate(state + 0.5 * h * k2);
            const State k4 = rate(state + h * k3);
            state += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        }
        now = time;
        const Eigen::Quaterniond q = Eigen::Quaterniond(state[3], state[4], state[5], state[6]).normalized();
        result.push_back(q * Eigen::Vector3d(state.head<3>()));
    }
    return result;
}

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

bool sameQuaternion(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    return a.coeffs() == b.coeffs();
}

// Keys, constraint flags, orientations, the fitted curve and the fit's parameters, exactly.
bool sameTrack(const model::MotionTrack& a, const model::MotionTrack& b)
{
    if (a.keys.size() != b.keys.size() || a.sketch.fittedCurve.size() != b.sketch.fittedCurve.size())
        return false;
    for (std::size_t i = 0; i < a.keys.size(); ++i)
        if (a.keys[i].time != b.keys[i].time || a.keys[i].constrained != b.keys[i].constrained
            || !sameQuaternion(a.keys[i].pose.orientation, b.keys[i].pose.orientation))
            return false;
    for (std::size_t i = 0; i < a.sketch.fittedCurve.size(); ++i)
        if (a.sketch.fittedCurve[i].time != b.sketch.fittedCurve[i].time
            || !sameQuaternion(a.sketch.fittedCurve[i].value, b.sketch.fittedCurve[i].value))
            return false;
    return a.sketch.alpha == b.sketch.alpha && a.sketch.window == b.sketch.window
           && a.sketch.directionStrokes.size() == b.sketch.directionStrokes.size();
}

} // namespace

class TestFitPanel : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }

    void init()
    {
        document_ = std::make_unique<model::Document>();
        QUndoStack& stack = document_->undoStack();
        auto* import = new model::ImportObjectsCommand(*document_, {spinningObject(4.0, 1.0)});
        stack.push(import);
        object_ = import->ids().front();
        // The sketch, as the sphere view and the magnitude plot make it.
        document_->push(new model::AddStrokeCommand(*document_, object_, tiltingStroke(1.0, 3.0, kTilt)));
        document_->push(new model::SetMagnitudeCurveCommand(*document_, object_, {{1.0, kSpinRate}, {3.0, kSpinRate}}));
        document_->push(new model::SetFitWindowCommand(*document_, object_, std::pair(1.0, 3.0)));

        selection_ = std::make_unique<app::Selection>(*document_);
        selection_->selectObject(object_);
        controller_ = std::make_unique<app::FitController>(*document_, *selection_);
        window_ = std::make_unique<QWidget>();
        auto* layout = new QVBoxLayout(window_.get());
        panel_ = new app::FitPanel(*document_, *selection_, *controller_, window_.get());
        statusBar_ = new QStatusBar(window_.get());
        progress_ = new app::FitProgress(*controller_, *statusBar_);
        statusBar_->addPermanentWidget(progress_);
        layout->addWidget(panel_);
        layout->addWidget(statusBar_);
        window_->resize(480, 760);
        window_->show();
        // Active, so that the panel's shortcut reaches it.
        window_->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(window_.get()));
        QVERIFY(!progress_->isVisible());
        QVERIFY(button("fitButton")->isEnabled());
    }

    void cleanup()
    {
        window_.reset();
        controller_.reset();
        selection_.reset();
        document_.reset();
    }

    void fitAppliesOneStepThatBendsTheSpinTowardsTheSketch()
    {
        // Free the middle key through the panel, so the fit may turn it.
        QUndoStack& stack = document_->undoStack();
        QTableWidget* keys = panel_->findChild<QTableWidget*>(QStringLiteral("keyTable"));
        keys->item(2, 1)->setCheckState(Qt::Unchecked);
        QVERIFY(!track().keys[2].constrained);
        QCOMPARE(stack.undoText(), QStringLiteral("Toggle Keyframe Constraint"));

        // δ as the paper's absolute 0.1 rad²/s was for this spin (S̄ = (π/2)² rad²/s²), so that the fit
        // adds the variable frames it needs to bend near the window's start.
        document_->push(new model::SetFitParameterCommand(*document_, object_, model::FitParameter::Delta, 0.04));
        const model::MotionTrack before = track();
        const int stepsBefore = stack.count();
        QTest::mouseClick(button("fitButton"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(stack.count() == stepsBefore + 1, kFitTimeoutMilliseconds);
        QCOMPARE(stack.undoText(), kApplyFitText);
        QVERIFY(!track().sketch.fittedCurve.empty());
        QVERIFY(!controller_->isFitting());
        QTRY_VERIFY(!progress_->isVisible());
        QVERIFY(statusBar_->currentMessage().startsWith(QStringLiteral("Fit ")));
        for (std::size_t key = 0; key < before.keys.size(); ++key)
            if (before.keys[key].constrained)
                QVERIFY(sameQuaternion(track().keys[key].pose.orientation, before.keys[key].pose.orientation));

        // Inside the window ω leans towards the sketched direction; before the fit it was z throughout.
        // The constrained keys at 1 s and 3 s still ask for half a turn about z, so it cannot follow
        // the sketch all the way: it leans to +x everywhere and is nearer the sketch on the whole.
        const model::TrackMotion fitted(track());
        double offBefore = 0.0;
        double offAfter = 0.0;
        for (double time = 1.05; time < 3.0; time += 0.1) {
            const Eigen::Vector3d sketched = sketchedDirection(time, 1.0, 3.0, kTilt);
            const Eigen::Vector3d omega = fitted.angularVelocity(time);
            QVERIFY2(omega.x() > 0.05 * omega.norm(), qPrintable(QStringLiteral("at %1 s").arg(time)));
            offBefore += angleBetween(Eigen::Vector3d::UnitZ(), sketched);
            offAfter += angleBetween(omega, sketched);
        }
        QVERIFY2(offAfter < 0.8 * offBefore,
                 qPrintable(QStringLiteral("off the sketch by %1 rad in all, %2 before").arg(offAfter).arg(offBefore)));

        stack.undo();
        QVERIFY(sameTrack(track(), before));
        QVERIFY(track().sketch.fittedCurve.empty());
        stack.redo();
        QVERIFY(!track().sketch.fittedCurve.empty());
    }

    void cancelLeavesTheDocumentAndHidesTheProgress()
    {
        makeSlowToFit();
        QUndoStack& stack = document_->undoStack();
        const model::MotionTrack before = track();
        const int stepsBefore = stack.count();
        const int indexBefore = stack.index();
        QTest::mouseClick(button("fitButton"), Qt::LeftButton);
        QVERIFY(progress_->isVisible());
        QVERIFY(button("cancelButton")->isEnabled());
        QVERIFY(!button("fitButton")->isEnabled());
        // Cancel as the first progress shows: the fit is unanswered then however fast the build runs
        // it, and a fit cancelled before its answer is answered by cancelled.
        int roundsShown = 0;
        QMetaObject::Connection firstProgress;
        firstProgress = connect(controller_.get(), &app::FitController::progressed, this, [&] {
            disconnect(firstProgress);
            roundsShown = progress_->progressBar()->maximum();
            QTest::mouseClick(progress_->findChild<QPushButton*>(QStringLiteral("cancelFit")), Qt::LeftButton);
        });
        QTRY_VERIFY_WITH_TIMEOUT(!progress_->isVisible(), kFitTimeoutMilliseconds);
        QVERIFY(roundsShown > 0);
        QCOMPARE(statusBar_->currentMessage(), QStringLiteral("Fit cancelled; nothing was applied."));
        QVERIFY(!controller_->isFitting());
        QVERIFY(button("fitButton")->isEnabled());
        QTest::qWait(300);
        QCOMPARE(stack.count(), stepsBefore);
        QCOMPARE(stack.index(), indexBefore);
        QVERIFY(sameTrack(track(), before));
    }

    void alphaTypedOrSteppedIsOneUndoStepEach()
    {
        QUndoStack& stack = document_->undoStack();
        auto* alpha = panel_->findChild<QDoubleSpinBox*>(QStringLiteral("alphaSpin"));
        QCOMPARE(alpha->decimals(), 4);
        QCOMPARE(alpha->maximum(), 1.0);
        const int stepsBefore = stack.count();
        alpha->setFocus();
        alpha->selectAll();
        QTest::keyClicks(alpha, QStringLiteral("0.004"));
        QCOMPARE(track().sketch.alpha, 0.002); // typing is not yet an edit
        QTest::keyClick(alpha, Qt::Key_Return);
        QCOMPARE(track().sketch.alpha, 0.004);
        QCOMPARE(stack.count(), stepsBefore + 1);
        QCOMPARE(stack.undoText(), QStringLiteral("Set Fit Parameter"));

        QTest::keyClick(alpha, Qt::Key_Up);
        QCOMPARE(track().sketch.alpha, 0.0045);
        QCOMPARE(stack.count(), stepsBefore + 2);
        stack.undo();
        QCOMPARE(track().sketch.alpha, 0.004);
        QCOMPARE(alpha->value(), 0.004);
        stack.undo();
        QCOMPARE(track().sketch.alpha, 0.002);
    }

    void wholeSketchClearsTheWindowAsOneStep()
    {
        QUndoStack& stack = document_->undoStack();
        auto* whole = panel_->findChild<QCheckBox*>(QStringLiteral("wholeSketchCheck"));
        QVERIFY(!whole->isChecked());
        const int stepsBefore = stack.count();
        QTest::mouseClick(whole, Qt::LeftButton, {}, QPoint(8, whole->height() / 2));
        QVERIFY(!track().sketch.window.has_value());
        QCOMPARE(stack.count(), stepsBefore + 1);
        QCOMPARE(stack.undoText(), QStringLiteral("Set Fit Window"));
        stack.undo();
        QCOMPARE(track().sketch.window, std::optional(std::pair(1.0, 3.0)));
        QVERIFY(!whole->isChecked());
    }

    void liveModePreviewsWhileDrawingAndAppliesOneStepAtTheEnd()
    {
        QUndoStack& stack = document_->undoStack();
        std::vector<std::optional<model::MotionTrack>> previews;
        connect(controller_.get(), &app::FitController::previewChanged, this,
                [&](model::ObjectId object, const std::optional<model::MotionTrack>& preview) {
                    QCOMPARE(object, object_);
                    previews.push_back(preview);
                });
        // Turning Live on fits the track as it is.
        const int stepsBefore = stack.count();
        QTest::mouseClick(panel_->findChild<QCheckBox*>(QStringLiteral("liveCheck")), Qt::LeftButton, {}, QPoint(8, 8));
        QVERIFY(controller_->isLive());
        QTRY_VERIFY_WITH_TIMEOUT(stack.count() == stepsBefore + 1, kFitTimeoutMilliseconds);
        QCOMPARE(stack.undoText(), kApplyFitText);
        QVERIFY(previews.empty());

        // A stroke redrawn as the pen moves: every move an edit inside one gesture.
        const int stepsBeforeStroke = stack.count();
        {
            model::Gesture gesture(*document_);
            for (double tilt : {0.9, 1.0, 1.1}) {
                gesture.push(new model::EditStrokeCommand(*document_, object_, 0, tiltingStroke(1.0, 3.0, tilt)));
                const std::size_t previewsBefore = previews.size();
                QTRY_VERIFY_WITH_TIMEOUT(previews.size() > previewsBefore, kFitTimeoutMilliseconds);
                QVERIFY(previews.back().has_value());
                QVERIFY(!previews.back()->sketch.fittedCurve.empty());
                QCOMPARE(previews.back()->sketch.directionStrokes.front().points.back(),
                         tiltingStroke(1.0, 3.0, tilt).points.back());
                // Nothing applied: the gesture is the only step past the start, and still open.
                QCOMPARE(stack.count(), stepsBeforeStroke + 1);
                QVERIFY(document_->isGestureOpen());
            }
        }
        QVERIFY(!document_->isGestureOpen());
        QTRY_VERIFY_WITH_TIMEOUT(stack.count() == stepsBeforeStroke + 2, kFitTimeoutMilliseconds);
        QCOMPARE(stack.undoText(), kApplyFitText);
        QCOMPARE(stack.text(stack.count() - 2), QStringLiteral("Edit Stroke"));
        QVERIFY(!previews.back().has_value());
        const model::MotionTrack applied = track();
        QCOMPARE(applied.sketch.directionStrokes.front().points.back(), tiltingStroke(1.0, 3.0, 1.1).points.back());
        // Applying the fit changed none of its inputs: no further fit.
        QTest::qWait(1000);
        QCOMPARE(stack.count(), stepsBeforeStroke + 2);

        // Undoing the fit and the stroke starts no fit that would throw the redo steps away.
        stack.undo();
        stack.undo();
        QTest::qWait(1000);
        QCOMPARE(stack.index(), stepsBeforeStroke);
        QCOMPARE(stack.count(), stepsBeforeStroke + 2);
    }

    void theViewportDrawsThePreviewTrackUntilItIsCleared()
    {
        app::Viewport viewport(*document_, *selection_);
        viewport.resize(640, 480);
        viewport.show();
        QVERIFY(QTest::qWaitForWindowExposed(&viewport));
        viewport.frameScene();
        const QPointF drawn = *viewport.objectScreenPosition(object_);
        // A preview moved aside, so that where the object is drawn shows which track is used.
        model::MotionTrack preview = track();
        for (model::Keyframe& key : preview.keys)
            key.pose.position.x() += 2.0;
        viewport.setPreviewTrack(object_, preview);
        QTRY_VERIFY((*viewport.objectScreenPosition(object_) - drawn).manhattanLength() > 10.0);
        QVERIFY(track().keys.front().pose.position.isZero());
        viewport.setPreviewTrack(object_, std::nullopt);
        QTRY_VERIFY((*viewport.objectScreenPosition(object_) - drawn).manhattanLength() < 0.5);
    }

    // Set physics target replaces the strokes and the magnitude curve, in one undo step, by the ω of the free
    // flight from the motion at the window's start (1 s): here a spin about z of a body whose principal axes are
    // not z, so it tumbles. Checked against the test's own RK4 (steps of 1e-4 s: its error is far below 1e-8).
    void physicsTargetIsTheFreeFlightsOmegaInOneStep()
    {
        MassProperties body;
        body.inertia = inertiaTensor({1.0, 2.0, 2.5, 0.2, 0.3, -0.1});
        document_->push(new model::SetMassOverrideCommand(*document_, object_, body));
        QUndoStack& stack = document_->undoStack();
        const model::SketchState before = track().sketch;
        const int stepsBefore = stack.count();
        QTest::mouseClick(button("physicsTargetButton"), Qt::LeftButton);
        QCOMPARE(stack.count(), stepsBefore + 1);
        QCOMPARE(stack.undoText(), QStringLiteral("Set Physics Target"));

        const model::SketchState& sketch = track().sketch;
        QCOMPARE(sketch.directionStrokes.size(), std::size_t{1});
        const model::DirectionStroke& stroke = sketch.directionStrokes.front();
        QCOMPARE(stroke.times.size(), stroke.points.size());
        QCOMPARE(sketch.magnitude.size(), stroke.points.size());
        // One sample a frame (24 fps) over the window's 2 s.
        QCOMPARE(stroke.points.size(), std::size_t{49});
        QCOMPARE(stroke.times.front(), 1.0);
        QCOMPARE(stroke.times.back(), 3.0);

        const model::TrackMotion motion(track());
        std::vector<double> elapsed;
        for (const double time : stroke.times)
            elapsed.push_back(time - 1.0);
        const std::vector<Eigen::Vector3d> expected =
            eulerRk4(body.inertia, motion.at(1.0).orientation, motion.angularVelocity(1.0), elapsed, 1e-4);
        double turned = 0.0; // how far ω's direction wanders: the target is not the steady spin
        for (std::size_t i = 0; i < expected.size(); ++i) {
            QVERIFY2(angleBetween(stroke.points[i], expected[i]) < 1e-8, qPrintable(QString::number(stroke.times[i])));
            QCOMPARE(sketch.magnitude[i].time, stroke.times[i]);
            QVERIFY(std::abs(sketch.magnitude[i].magnitude - expected[i].norm()) < 1e-8 * expected[i].norm());
            turned = std::max(turned, angleBetween(stroke.points[i], Eigen::Vector3d::UnitZ()));
        }
        QVERIFY(turned > 0.1);

        stack.undo();
        QCOMPARE(track().sketch.directionStrokes, before.directionStrokes);
        QCOMPARE(track().sketch.magnitude, before.magnitude);
        // The fit runs on the new target as on any sketch.
        stack.redo();
        QVERIFY(button("fitButton")->isEnabled());
    }

    void removeFitTakesTheCurveAwayInOneStep()
    {
        QUndoStack& stack = document_->undoStack();
        const int stepsBefore = stack.count();
        QVERIFY(!button("removeFitButton")->isEnabled());
        QTest::keyClick(window_.get(), Qt::Key_F, Qt::ControlModifier);
        QTRY_VERIFY_WITH_TIMEOUT(stack.count() == stepsBefore + 1, kFitTimeoutMilliseconds);
        const std::vector<HermiteControlPoint> curve = track().sketch.fittedCurve;
        QVERIFY(!curve.empty());
        QVERIFY(button("removeFitButton")->isEnabled());

        QTest::mouseClick(button("removeFitButton"), Qt::LeftButton);
        QCOMPARE(stack.count(), stepsBefore + 2);
        QCOMPARE(stack.undoText(), QStringLiteral("Remove angular velocity fit"));
        QVERIFY(track().sketch.fittedCurve.empty());
        QVERIFY(!button("removeFitButton")->isEnabled());
        stack.undo();
        QCOMPARE(track().sketch.fittedCurve.size(), curve.size());
        QVERIFY(sameQuaternion(track().sketch.fittedCurve.back().value, curve.back().value));
    }

    void aResultForAChangedTrackIsDropped()
    {
        QUndoStack& stack = document_->undoStack();
        QTest::mouseClick(button("fitButton"), Qt::LeftButton);
        pushEditAlone();
        const int stepsAfterEdit = stack.count();
        auto* status = panel_->findChild<QLabel*>(QStringLiteral("fitStatusLabel"));
        QTRY_VERIFY_WITH_TIMEOUT(!controller_->isFitting(), kFitTimeoutMilliseconds);
        QCOMPARE(status->text(), QStringLiteral("Fit not applied: the track changed while it ran."));
        QCOMPARE(stack.count(), stepsAfterEdit);
        QVERIFY(track().sketch.fittedCurve.empty());
    }

    // A free key the artist turns while the fit runs is part of what the fit read: the result is
    // dropped, as for any other change, and the key keeps the turn.
    void aResultForATrackWithATurnedFreeKeyIsDropped()
    {
        QUndoStack& stack = document_->undoStack();
        document_->push(new model::ToggleKeyframeConstraintCommand(*document_, object_, 2));
        QVERIFY(!track().keys[2].constrained);
        QTest::mouseClick(button("fitButton"), Qt::LeftButton);
        const Eigen::Quaterniond turned =
            track().keys[2].pose.orientation * Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
        document_->push(new model::SetKeyframeOrientationCommand(*document_, object_, 2, turned));
        const int stepsAfterTurn = stack.count();
        auto* status = panel_->findChild<QLabel*>(QStringLiteral("fitStatusLabel"));
        QTRY_VERIFY_WITH_TIMEOUT(!controller_->isFitting(), kFitTimeoutMilliseconds);
        QCOMPARE(status->text(), QStringLiteral("Fit not applied: the track changed while it ran."));
        QCOMPARE(stack.count(), stepsAfterTurn);
        QVERIFY(track().sketch.fittedCurve.empty());
        QVERIFY(track().keys[2].pose.orientation.isApprox(turned, 1e-15));
    }

    // The key table changes its rows in place: a key turned, as at every move of a drag, changes no
    // item; a key's constraint or time changes its own row's item; a key added adds a row.
    void theKeyTableChangesItsRowsInPlace()
    {
        auto* keys = panel_->findChild<QTableWidget*>(QStringLiteral("keyTable"));
        QCOMPARE(keys->rowCount(), 5);
        QTableWidgetItem* time = keys->item(1, 0);
        QTableWidgetItem* constrained = keys->item(1, 1);
        QCOMPARE(time->text(), QStringLiteral("1.000"));
        QCOMPARE(constrained->checkState(), Qt::Checked);

        const Eigen::Quaterniond turned = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
        document_->push(new model::SetKeyframeOrientationCommand(*document_, object_, 1, turned));
        QCOMPARE(keys->item(1, 0), time);
        QCOMPARE(keys->item(1, 1), constrained);

        document_->push(new model::ToggleKeyframeConstraintCommand(*document_, object_, 1));
        QCOMPARE(keys->item(1, 1), constrained);
        QCOMPARE(constrained->checkState(), Qt::Unchecked);
        document_->push(new model::SetKeyframeTimeCommand(*document_, object_, 1, 1.25));
        QCOMPARE(keys->item(1, 0), time);
        QCOMPARE(time->text(), QStringLiteral("1.250"));

        model::Keyframe added = track().keys.back();
        added.time = 5.0;
        document_->push(new model::ReplaceKeyframesCommand(*document_, {{object_, model::withKeys(track().keys, {added})}},
                                                           model::ReplaceKeyframesCommand::Edit::Insert));
        QCOMPARE(keys->rowCount(), 6);
        QCOMPARE(keys->item(5, 0)->text(), QStringLiteral("5.000"));
        QCOMPARE(keys->item(5, 1)->checkState(), Qt::Checked);
        QCOMPARE(keys->item(1, 0), time);
    }

    // Off screen the key table waits, and catches up once the panel is shown again; the fields and the
    // Fit button follow at once, so that Fit is right the moment the panel is raised.
    void theKeyTableWaitsToBeOnScreenTheFitButtonDoesNot()
    {
        auto* keys = panel_->findChild<QTableWidget*>(QStringLiteral("keyTable"));
        QCOMPARE(keys->rowCount(), 5);
        window_->hide();
        document_->push(new model::ReplaceKeyframesCommand(*document_, {{object_, model::withoutKeys(track().keys, {4})}},
                                                           model::ReplaceKeyframesCommand::Edit::Delete));
        document_->push(new model::SetFitWindowCommand(*document_, object_, std::pair(3.5, 4.0)));
        QCoreApplication::processEvents();
        QCOMPARE(keys->rowCount(), 5);
        QVERIFY(!button("fitButton")->isEnabled()); // the window lies beyond the last key now
        QVERIFY(panel_->findChild<QFrame*>(QStringLiteral("fitProblemFrame"))->isVisibleTo(panel_));

        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
        QTRY_COMPARE(keys->rowCount(), 4);
        document_->undoStack().undo();
        QVERIFY(button("fitButton")->isEnabled());
    }

    // A screw track is fitted as any other (its own subdivided, retimed polyscrew the motion the fit
    // starts from): Fit is on, one undo step applies the fit, the keys stay as they were, and the
    // scene's motion, which the viewport plays, follows the fitted curve inside the window, leaning
    // towards the sketch, and the polyscrew outside it.
    void aScrewTrackIsFittedAndPlays()
    {
        document_->push(new model::SetInterpolationCommand(*document_, object_, InterpolationMethod::Screw));
        auto* problem = panel_->findChild<QFrame*>(QStringLiteral("fitProblemFrame"));
        QVERIFY(!problem->isVisible());
        QVERIFY(button("fitButton")->isEnabled());

        QUndoStack& stack = document_->undoStack();
        const model::MotionTrack keyed = track();
        const int stepsBefore = stack.count();
        QTest::mouseClick(button("fitButton"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(stack.count() == stepsBefore + 1, kFitTimeoutMilliseconds);
        QCOMPARE(stack.undoText(), kApplyFitText);
        QVERIFY(statusBar_->currentMessage().contains(QStringLiteral("Against what was drawn")));
        QVERIFY(!track().sketch.fittedCurve.empty());
        QCOMPARE(track().interpolation, InterpolationMethod::Screw);
        QCOMPARE(track().keys.size(), keyed.keys.size());
        for (std::size_t key = 0; key < keyed.keys.size(); ++key)
            QVERIFY(sameQuaternion(track().keys[key].pose.orientation, keyed.keys[key].pose.orientation));

        const model::SceneMotion played(document_->scene(),
                                        [this](const model::SceneObject& object) { return document_->motion(object.id); });
        const model::TrackMotion polyscrew(keyed);
        const HermiteQuaternionSpline curve(track().sketch.fittedCurve);
        for (double time = 0.0; time <= 4.0; time += 0.05) {
            const Eigen::Quaterniond orientation = played.worldPose(object_, time).orientation;
            const Eigen::Quaterniond expected = time >= 1.0 && time <= 3.0 ? curve.sample(time).value
                                                                           : polyscrew.at(time).orientation;
            QVERIFY2(orientation.angularDistance(expected) < 1e-12, qPrintable(QStringLiteral("at %1 s").arg(time)));
        }
        const double before = model::drawnError(keyed, polyscrew);
        const double after = model::drawnError(track(), model::TrackMotion(track()));
        QVERIFY2(after < 0.9 * before, qPrintable(QStringLiteral("%1 → %2 rad²/s").arg(before).arg(after)));
    }

    // Not a check: how long a realistic fit takes from the click to the applied step (8 s, 17 keys,
    // a stroke and a magnitude over 4 s), printed for the record.
    void timeFromClickToApply()
    {
        QUndoStack& stack = document_->undoStack();
        auto* import = new model::ImportObjectsCommand(*document_, {spinningObject(8.0, 0.5)});
        stack.push(import);
        const model::ObjectId realistic = import->ids().front();
        document_->push(new model::AddStrokeCommand(*document_, realistic, tiltingStroke(2.0, 6.0, kTilt)));
        document_->push(new model::SetMagnitudeCurveCommand(
            *document_, realistic, {{2.0, kSpinRate}, {4.0, 2 * kSpinRate}, {6.0, kSpinRate}}));
        selection_->selectObject(realistic);
        const int stepsBefore = stack.count();
        QElapsedTimer clock;
        clock.start();
        QTest::mouseClick(button("fitButton"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(stack.count() == stepsBefore + 1, kFitTimeoutMilliseconds);
        qInfo("Fit from click to applied step: %lld ms (%s)", static_cast<long long>(clock.elapsed()),
              qPrintable(statusBar_->currentMessage()));
    }

    // Not a check: the UI thread's CPU time per move of a drag that turns a key of a sketched
    // 2,000-key track with the Fit panel shown (docs/fit.md), printed for the record. Each move is
    // one command of the gesture, as the viewport's rotate handle pushes it, and the events it posts
    // are processed before the next.
    void measuresTheUiThreadPerDragMoveOnALongTrack()
    {
        constexpr int kKeys = 2000;
        constexpr double kSpacing = 1.0 / 24.0;
        auto* import = new model::ImportObjectsCommand(*document_, {spinningObject((kKeys - 1) * kSpacing, kSpacing)});
        document_->undoStack().push(import);
        const model::ObjectId longTrack = import->ids().front();
        QCOMPARE(document_->object(longTrack)->track.keys.size(), std::size_t{kKeys});
        document_->push(new model::AddStrokeCommand(*document_, longTrack, tiltingStroke(1.0, 80.0, kTilt)));
        document_->push(new model::SetMagnitudeCurveCommand(*document_, longTrack, {{1.0, kSpinRate}, {80.0, 2 * kSpinRate}}));
        selection_->selectObject(longTrack);
        QCoreApplication::processEvents();

        constexpr int kWarmUpMoves = 5;
        constexpr int kMoves = 40;
        constexpr std::size_t kDraggedKey = kKeys / 2;
        const Eigen::Quaterniond start = document_->object(longTrack)->track.keys[kDraggedKey].pose.orientation;
        double uiStart = 0.0;
        model::Gesture gesture(*document_);
        for (int move = 1; move <= kWarmUpMoves + kMoves; ++move) {
            if (move == kWarmUpMoves + 1)
                uiStart = test::threadMilliseconds();
            const Eigen::Quaterniond turned = start * Eigen::Quaterniond(Eigen::AngleAxisd(0.01 * move, Eigen::Vector3d::UnitX()));
            gesture.push(new model::SetKeyframeOrientationCommand(*document_, longTrack, kDraggedKey, turned));
            QCoreApplication::processEvents();
        }
        const double perMove = (test::threadMilliseconds() - uiStart) / kMoves;
        gesture.finish();
        QVERIFY(!document_->object(longTrack)->track.keys[kDraggedKey].pose.orientation.isApprox(start));
        qInfo("Fit panel shown, %d keys, per drag move of a key: UI thread %.2f ms of CPU", kKeys, perMove);
    }

private:
    const model::MotionTrack& track() const { return document_->object(object_)->track; }

    QPushButton* button(const char* name) const
    {
        auto* found = panel_->findChild<QPushButton*>(QString::fromLatin1(name));
        if (found == nullptr)
            qFatal("no button %s", name);
        return found;
    }

    // δ tiny and a magnitude the keys cannot follow over the whole track: variable frames round after round.
    void makeSlowToFit()
    {
        document_->push(new model::SetFitParameterCommand(*document_, object_, model::FitParameter::Delta, 1e-9));
        document_->push(new model::SetFitWindowCommand(*document_, object_, std::pair(0.0, 4.0)));
        document_->push(new model::SetMagnitudeCurveCommand(*document_, object_, {{0.0, 4 * kSpinRate}, {4.0, kSpinRate}}));
        document_->push(new model::EditStrokeCommand(*document_, object_, 0, tiltingStroke(0.0, 4.0, kTilt)));
    }

    void pushEditAlone()
    {
        document_->push(new model::EditStrokeCommand(*document_, object_, 0, tiltingStroke(1.0, 3.0, 0.8)));
    }

    std::unique_ptr<model::Document> document_;
    model::ObjectId object_ = model::kNoObject;
    std::unique_ptr<app::Selection> selection_;
    std::unique_ptr<app::FitController> controller_;
    std::unique_ptr<QWidget> window_;
    app::FitPanel* panel_ = nullptr;
    QStatusBar* statusBar_ = nullptr;
    app::FitProgress* progress_ = nullptr;
};

QTEST_MAIN(TestFitPanel)
#include "tst_fit_panel.moc"
