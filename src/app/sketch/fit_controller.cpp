#include "app/sketch/fit_controller.h"

#include "app/undo_gesture.h"
#include "jobs/fit_input.h"
#include "model/commands/apply_fit_result_command.h"

#include <stdexcept>
#include <utility>

namespace gyre::app {

namespace {

QString endOfFitMessage(const jobs::FitSummary& summary)
{
    const QString how = summary.converged ? FitController::tr("Fit converged")
                                          : FitController::tr("Fit stopped (%1)").arg(summary.outcome);
    return FitController::tr("%1: %2 rounds, %3 iterations, largest fragment error %4 rad²/s, %5 s.")
        .arg(how)
        .arg(summary.rounds)
        .arg(summary.iterations)
        .arg(summary.largestFragmentError, 0, 'g', 3)
        .arg(summary.seconds, 0, 'g', 2);
}

} // namespace

FitController::FitController(model::Document& document, Selection& selection, QObject* parent)
    : QObject(parent)
    , document_(document)
    , selection_(selection)
{
    connect(&fitJob_, &jobs::FitJob::progressed, this,
            [this](model::ObjectId, const jobs::FitJobProgress& progress) { emit progressed(progress); });
    connect(&fitJob_, &jobs::FitJob::finished, this, &FitController::onFitFinished);
    connect(&fitJob_, &jobs::FitJob::failed, this, [this](model::ObjectId, const QString& message) {
        emit fitEnded(tr("Fit failed: %1").arg(message));
    });
    connect(&fitJob_, &jobs::FitJob::cancelled, this, [this] { emit fitEnded(tr("Fit cancelled.")); });

    connect(&liveJob_, &jobs::FitJob::finished, this,
            [this](model::ObjectId object, const model::MotionTrack& input, const model::FitResult& result,
                   const jobs::FitSummary&) { onLiveFinished(object, input, result); });
    // The fit panel says why a track cannot be fitted; the preview of a fit that no longer is goes.
    connect(&liveJob_, &jobs::FitJob::failed, this, [this] {
        heldLiveResult_.reset();
        clearPreview();
    });

    connect(&document_, &model::Document::keyframesChanged, this, &FitController::onInputsMayHaveChanged);
    connect(&document_, &model::Document::sketchChanged, this, &FitController::onInputsMayHaveChanged);
    connect(&document_, &model::Document::trackSettingsChanged, this, &FitController::onInputsMayHaveChanged);
    connect(&document_, &model::Document::sceneReset, this, &FitController::onSelectionChanged);
    connect(&document_.undoStack(), &QUndoStack::indexChanged, this, &FitController::onUndoIndexChanged);
    connect(&selection_, &Selection::changed, this, [this, shown = selection.object()]() mutable {
        // Another key of the same object is selected: the fit is the same.
        if (selection_.object() != shown) {
            shown = selection_.object();
            onSelectionChanged();
        }
    });
}

void FitController::fitSelected()
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr)
        return;
    heldFit_.reset();
    fitJob_.request(object->id, object->track);
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
    HeldResult held{object, input, result, endOfFitMessage(summary)};
    if (isMacroOpen(document_.undoStack()))
        heldFit_ = std::move(held);
    else
        settleFit(held);
}

void FitController::settleFit(const HeldResult& held)
{
    if (applyIfCurrent(held.object, held.input, held.result))
        emit fitEnded(held.appliedMessage);
    else
        emit fitEnded(tr("Fit dropped: the track changed while it ran."));
}

void FitController::onLiveFinished(model::ObjectId object, const model::MotionTrack& input,
                                   const model::FitResult& result)
{
    if (object != selection_.object())
        return;
    // Reset before applying: the push's indexChanged must find nothing older to apply.
    heldLiveResult_.reset();
    if (!isMacroOpen(document_.undoStack()) && applyIfCurrent(object, input, result)) {
        clearPreview();
        return;
    }
    // Drawing goes on, or the track changed since, and a newer fit is on its way: show this one.
    HeldResult held{object, input, result, {}};
    showPreview(held);
    heldLiveResult_ = std::move(held);
}

void FitController::onInputsMayHaveChanged(model::ObjectId object)
{
    if (live_ && object == selection_.object())
        requestLiveFit();
}

void FitController::onUndoIndexChanged()
{
    if (isMacroOpen(document_.undoStack()))
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
    if (newestLiveInput_ && jobs::sameFitInput(*newestLiveInput_, object->track))
        return;
    newestLiveInput_ = object->track;
    liveJob_.request(object->id, object->track);
}

bool FitController::applyIfCurrent(model::ObjectId object, const model::MotionTrack& input,
                                   const model::FitResult& result)
{
    const model::SceneObject* current = document_.object(object);
    if (current == nullptr || !jobs::sameFitInput(input, current->track))
        return false;
    try {
        pushAlone(document_.undoStack(), new model::ApplyFitResultCommand(document_, object, result));
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
