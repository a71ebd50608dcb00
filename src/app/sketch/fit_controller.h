#pragma once
// The angular-velocity fit of the selected object, as the fit panel and the status bar's progress
// share it: one explicit fit at a time (Fit, Cancel), and the live mode, which refits whenever the
// selected object's fit inputs change.
//
// A result is applied as one undo step (ApplyFitResultCommand) only if it still applies to the
// document (model::fitResultApplies: the fit would read the same, and no key was edited since); an
// explicit fit whose track changed while it ran, a free key turned included, is dropped, and says so. While a gesture is open (Document::isGestureOpen: a stroke being drawn pushes its commands
// at every mouse move), nothing is applied: a live result is shown as a preview of the motion
// (previewChanged, for the viewport), and the newest result is applied when the gesture ends
// (Document::gestureEnded) and it matches the document.
// Live fits follow only changes made with nothing to redo, so undo and redo never lose history to a
// fit. A fit reads the track without its fit (model::withoutFit: the keys a fit moved as they were
// before it), so applying a fit, which changes the fitted curve and the free keys and keeps what they
// were in sketch.keysBeforeFit, leaves what the next fit would read as it was (model::sameFitInput)
// and starts no other fit. The UI thread never waits: every fit runs on a FitJob.

#include "app/selected_track.h"
#include "app/selection.h"
#include "jobs/fit_job.h"
#include "model/document.h"

#include <QObject>
#include <QString>

#include <optional>

namespace gyre::app {

class FitController : public QObject {
    Q_OBJECT

public:
    FitController(model::Document& document, Selection& selection, QObject* parent = nullptr);

    // Fits the selected object's track as it is now, in place of a fit running.
    void fitSelected();
    // Stops the running explicit fit; nothing is applied.
    void cancel();
    bool isFitting() const { return fitJob_.isRunning(); }

    bool isLive() const { return live_; }
    void setLive(bool live);

signals:
    void fitStarted(gyre::model::ObjectId object);
    void progressed(const gyre::jobs::FitJobProgress& progress);
    // The explicit fit is over: applied, dropped, cancelled or failed, as `message` says in a sentence.
    void fitEnded(const QString& message);
    void liveChanged(bool live);
    // The motion to draw for `object` while a gesture is open: its track with the newest live fit
    // applied. nullopt: draw the document's track again.
    void previewChanged(gyre::model::ObjectId object, const std::optional<gyre::model::MotionTrack>& track);

private:
    // A result waiting for the gesture to end.
    struct HeldResult {
        model::ObjectId object = model::kNoObject;
        model::MotionTrack input;
        model::FitResult result;
        QString appliedMessage;  // what fitEnded says once an explicit fit is applied
    };

    void onFitFinished(model::ObjectId object, const model::MotionTrack& input, const model::FitResult& result,
                       const jobs::FitSummary& summary);
    void onLiveFinished(model::ObjectId object, const model::MotionTrack& input, const model::FitResult& result);
    // The explicit fit's result, when no gesture is open: applied, or dropped for a changed track.
    void settleFit(const HeldResult& held);
    // After a gesture ended or the undo history moved: applies what was held, unless a gesture is open.
    void settleHeld();
    void onSelectionChanged();
    // Posts a live fit of the selected track unless its inputs are those of the newest live fit.
    void requestLiveFit();
    // Applies `result` as one undo step if it still applies to the object (model::fitResultApplies);
    // whether it did.
    bool applyIfCurrent(model::ObjectId object, const model::MotionTrack& input, const model::FitResult& result);
    void showPreview(const HeldResult& held);
    void clearPreview();

    model::Document& document_;
    Selection& selection_;
    SelectedTrack selectedTrack_;
    bool live_ = false;
    std::optional<model::MotionTrack> newestLiveInput_;
    std::optional<HeldResult> heldFit_;
    std::optional<HeldResult> heldLiveResult_;
    model::ObjectId previewObject_ = model::kNoObject;
    jobs::FitJob fitJob_;
    jobs::FitJob liveJob_;
};

} // namespace gyre::app
