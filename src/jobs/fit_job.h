#pragma once
// The angular-velocity fit of one object's track off the UI thread (the sketch-editing paper's "Fit",
// docs/fit.md). A request takes a copy of the track; the worker builds the fit from its sketch
// (model::sketchFitProblem) and runs it, and the result comes back to the UI thread as what
// ApplyFitResultCommand applies. The newest request wins (a newest-wins Job): a request made while a
// fit runs makes the running fit stop at its next solver iteration, and only the newest request is
// answered. A fit reports its progress while it runs, at most every
// kProgressIntervalMilliseconds and at every new round, so a fast fit does not flood the event loop.
//
// Every request is answered by exactly one of finished, failed or cancelled, unless a newer request
// replaced it. All signals are emitted on the UI thread.

#include "jobs/job.h"
#include "model/commands/apply_fit_result_command.h"
#include "model/scene.h"
#include "model/sketch_fit_problem.h"

#include <QObject>
#include <QString>

#include <optional>

namespace gyre::jobs {

// Where a running fit is.
struct FitJobProgress {
    int round = 0;      // 1-based
    int maxRounds = 0;  // the fit stops after this many rounds
    int iteration = 0;  // solver iterations so far, over all rounds
    std::optional<double> largestRelativeError;  // F_n/S̄ to compare with δ, after the last finished round
};

// How a fit ended.
struct FitSummary {
    QString outcome;  // fit::kFitOutcomeNames
    bool converged = false;
    int rounds = 0;
    int iterations = 0;
    double largestRelativeError = 0.0;  // F_n/S̄, what converged holds within δ
    model::DrawnErrors drawnErrors;     // against what was drawn, rad²/s, before and after the fit
    double seconds = 0.0;               // on the worker, from the request's start to its result
};

class FitJob : public QObject {
    Q_OBJECT

public:
    static constexpr int kProgressIntervalMilliseconds = 50;

    explicit FitJob(QObject* parent = nullptr);
    ~FitJob() override;

    // Fits `track`, the track of `object` as it is now, in place of any fit requested before; `body` is what a
    // ballistic track flies (model::flightBodyOf).
    void request(model::ObjectId object, model::MotionTrack track, const MassProperties& body);
    // Stops the newest request's fit: it is answered by cancelled. Does nothing when no fit is running.
    void cancel();
    // Whether the newest request is still unanswered.
    bool isRunning() const { return !job_.isIdle(); }

signals:
    void progressed(gyre::model::ObjectId object, const gyre::jobs::FitJobProgress& progress);
    // `input` is the track the fit read; `result` is what ApplyFitResultCommand applies to it.
    void finished(gyre::model::ObjectId object, const gyre::model::MotionTrack& input,
                  const gyre::model::FitResult& result, const gyre::jobs::FitSummary& summary);
    // The track cannot be fitted (SketchFitError) or the fit refused it; `message` says why, as it stands.
    void failed(gyre::model::ObjectId object, const QString& message);
    void cancelled(gyre::model::ObjectId object);

private:
    struct Answer {
        model::MotionTrack input;
        model::FitResult applied;
        FitSummary summary;
    };

    model::ObjectId object_ = model::kNoObject; // of the newest request, the one answered
    Job<Answer, FitJobProgress> job_;            // last: waits for the fit before the members above go
};

} // namespace gyre::jobs
