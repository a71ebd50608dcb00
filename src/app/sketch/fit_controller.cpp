#include "app/sketch/fit_controller.h"

#include "fit/angular_velocity_fit.h"
#include "model/fit_input.h"
#include "model/commands/apply_fit_result_command.h"

#include <optional>
#include <stdexcept>
#include <utility>

namespace gyre::app {

namespace {

// What an explicit fit did, in words, once its result is applied to `input`: how it ended, against
// δ, and how far the motion is from what was drawn before and after.
QString appliedFitMessage(const jobs::FitSummary& summary, const model::MotionTrack& input)
{
    const QString delta = QString::number(input.sketch.delta, 'g', 3);
    const QString largest = QString::number(summary.largestRelativeError, 'g', 3);
    const QString drawn = FitController::tr("Against what was drawn: %1 rad²/s before, %2 after.")
                              .arg(QString::number(summary.drawnErrors.before, 'g', 3),
                                   QString::number(summary.drawnErrors.after, 'g', 3));
    const std::optional<fit::FitOutcome> outcome = valueNamed(fit::kFitOutcomeNames, summary.outcome.toStdString());
    switch (outcome.value_or(fit::FitOutcome::RoundLimit)) {
    case fit::FitOutcome::Converged:
        return FitController::tr("Fit applied: the motion now follows the sketch within δ = %1 "
                                 "(largest relative error %2, %3 rounds, %4 s).")
                   .arg(delta, largest)
                   .arg(summary.rounds)
                   .arg(summary.seconds, 0, 'g', 2)
               + QLatin1Char(' ') + drawn;
    case fit::FitOutcome::VariableFrameLimit:
        return FitController::tr("Fit stopped at its limit of added control points, still off the sketch by a "
                                 "relative error of up to %1 (δ = %2); its last result was applied.")
                   .arg(largest, delta)
               + QLatin1Char(' ') + drawn;
    case fit::FitOutcome::NoPlaceForFrame:
        return FitController::tr("Fit could not meet δ = %1: where it is furthest off (relative error %2) it has no "
                                 "room for another control point, often because constrained keys there disagree "
                                 "with the sketch; its result was applied.")
                   .arg(delta, largest)
               + QLatin1Char(' ') + drawn;
    case fit::FitOutcome::RoundLimit:
    case fit::FitOutcome::Cancelled: // answered by FitJob::cancelled, never as a result
        break;
    }
    return FitController::tr("Fit stopped after %1 rounds, still off the sketch by a relative error of up to %2 "
                             "(δ = %3); its last result was applied.")
               .arg(summary.rounds)
               .arg(largest, delta)
           + QLatin1Char(' ') + drawn;
}

} // namespace

FitController::FitController(model::Document& document, Selection& selection, QObject* parent)
    : QObject(parent)
    , document_(document)
    , selection_(selection)
    , selectedTrack_(document, selection)
{
    connect(&fitJob_, &jobs::FitJob::progressed, this,
            [this](model::ObjectId, const jobs::FitJobProgress& progress) { emit progressed(progress); });
    connect(&fitJob_, &jobs::FitJob::finished, this, &FitController::onFitFinished);
    connect(&fitJob_, &jobs::FitJob::failed, this, [this](model::ObjectId, const QString& message) {
        emit fitEnded(tr("Fit failed, nothing was applied: %1").arg(message));
    });
    connect(&fitJob_, &jobs::FitJob::cancelled, this, [this] { emit fitEnded(tr("Fit cancelled; nothing was applied.")); });

    connect(&liveJob_, &jobs::FitJob::finished, this,
            [this](model::ObjectId object, const model::MotionTrack& input, const model::FitResult& result,
                   const jobs::FitSummary&) { onLiveFinished(object, input, result); });
    // The fit panel says why a track cannot be fitted (model::checkSketchFittable), and an explicit
    // fit whatever else its build refuses; the preview of a fit that no longer is goes.
    connect(&liveJob_, &jobs::FitJob::failed, this, [this] {
        heldLiveResult_.reset();
        clearPreview();
    });

    // Another key of the same object is selected: the fit is the same (SelectedTrack).
    connect(&selectedTrack_, &SelectedTrack::changed, this, [this](model::Changes changes) {
        using model::Change;
        if (changes & (SelectedTrack::kAnotherObject | Change::Scene))
            onSelectionChanged();
        else if (live_ && (changes & (Change::Keyframes | Change::Sketch | Change::TrackSettings)))
            requestLiveFit(); // the fit's inputs may have changed
    });
    connect(&document_, &model::Document::gestureEnded, this, &FitController::settleHeld);
    connect(&document_.undoStack(), &QUndoStack::indexChanged, this, &FitController::settleHeld);
}

void FitController::fitSelected()
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr)
        return;
    heldFit_.reset();
    fitJob_.request(object->id, object->track, model::flightBodyOf(*object));
    emit fitStarted(object->id);
}

void FitController::cancel()
{
    fitJob_.cancel();
}

void FitController::setLive(bool live)
{
    if (live == live_)
        return;
    live_ = live;
    newestLiveInput_.reset();
    heldLiveResult_.reset();
    if (live_) {
        requestLiveFit();
    } else {
        liveJob_.cancel();
        clearPreview();
    }
    emit liveChanged(live_);
}

void FitController::onFitFinished(model::ObjectId object, const model::MotionTrack& input,
                                  const model::FitResult& result, const jobs::FitSummary& summary)
{
    HeldResult held{object, input, result, appliedFitMessage(summary, input)};
    if (document_.isGestureOpen())
        heldFit_ = std::move(held);
    else
        settleFit(held);
}

void FitController::settleFit(const HeldResult& held)
{
    if (applyIfCurrent(held.object, held.input, held.result))
        emit fitEnded(held.appliedMessage);
    else
        emit fitEnded(tr("Fit not applied: the track changed while it ran."));
}

void FitController::onLiveFinished(model::ObjectId object, const model::MotionTrack& input,
                                   const model::FitResult& result)
{
    if (object != selection_.object())
        return;
    // Reset before applying: the push's indexChanged must find nothing older to apply.
    heldLiveResult_.reset();
    if (!document_.isGestureOpen() && applyIfCurrent(object, input, result)) {
        clearPreview();
        return;
    }
    // Drawing goes on, or the track changed since, and a newer fit is on its way: show this one.
    HeldResult held{object, input, result, {}};
    showPreview(held);
    heldLiveResult_ = std::move(held);
}

void FitController::settleHeld()
{
    if (document_.isGestureOpen())
        return;
    // A gesture ended (or a step was pushed, undone or redone): what was held waits no longer.
    if (std::optional<HeldResult> held = std::exchange(heldFit_, std::nullopt))
        settleFit(*held);
    // Taken out before applying, so that the push's own indexChanged finds nothing held.
    if (std::optional<HeldResult> held = std::exchange(heldLiveResult_, std::nullopt)) {
        if (applyIfCurrent(held->object, held->input, held->result))
            clearPreview();
        else
            heldLiveResult_ = std::move(held);
    }
}

void FitController::onSelectionChanged()
{
    heldLiveResult_.reset();
    newestLiveInput_.reset();
    clearPreview();
    if (live_)
        requestLiveFit();
}

void FitController::requestLiveFit()
{
    const model::SceneObject* object = selection_.selectedObject();
    // After an undo there is a step to redo, which a fit pushed now would throw away.
    if (object == nullptr || document_.undoStack().canRedo())
        return;
    if (newestLiveInput_ && model::sameFitInput(*newestLiveInput_, object->track))
        return;
    newestLiveInput_ = object->track;
    liveJob_.request(object->id, object->track, model::flightBodyOf(*object));
}

bool FitController::applyIfCurrent(model::ObjectId object, const model::MotionTrack& input,
                                   const model::FitResult& result)
{
    const model::SceneObject* current = document_.object(object);
    if (current == nullptr || !model::fitResultApplies(input, current->track, result))
        return false;
    try {
        document_.push(new model::ApplyFitResultCommand(document_, object, result));
    } catch (const std::invalid_argument&) {
        // A result the document refuses (value_checks.h) is one not to apply.
        return false;
    }
    return true;
}

void FitController::showPreview(const HeldResult& held)
{
    previewObject_ = held.object;
    emit previewChanged(held.object, model::withFitApplied(held.input, held.result));
}

void FitController::clearPreview()
{
    if (previewObject_ == model::kNoObject)
        return;
    emit previewChanged(std::exchange(previewObject_, model::kNoObject), std::nullopt);
}

} // namespace gyre::app
