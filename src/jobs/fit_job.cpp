#include "jobs/fit_job.h"

#include "fit/angular_velocity_fit.h"

#include <QElapsedTimer>

#include <string_view>
#include <utility>

namespace gyre::jobs {

namespace {

FitSummary summaryOf(const fit::FitResult& result, const model::DrawnErrors& drawnErrors, double seconds)
{
    const std::string_view outcome = nameOf(fit::kFitOutcomeNames, result.outcome);
    return {QString::fromUtf8(outcome.data(), static_cast<qsizetype>(outcome.size())),
            result.outcome == fit::FitOutcome::Converged,
            result.rounds,
            result.iterations,
            result.largestRelativeError,
            drawnErrors,
            seconds};
}

} // namespace

FitJob::FitJob(QObject* parent)
    : QObject(parent)
    , job_(JobPolicy::NewestWins,
           {.finished = [this](const Answer& answer) { emit finished(object_, answer.input, answer.applied, answer.summary); },
            // SketchFitError says what the artist should do; the fit's own refusals name what is wrong;
            // any other failure (out of memory, a solver error) is reported as it is.
            .failed = [this](const QString& message) { emit failed(object_, message); },
            .cancelled = [this] { emit cancelled(object_); },
            .progressed = [this](const FitJobProgress& progress) { emit progressed(object_, progress); }})
{
}

FitJob::~FitJob() = default;

void FitJob::request(model::ObjectId object, model::MotionTrack track, const MassProperties& body)
{
    object_ = object;
    job_.post([input = std::move(track), body](const JobRun<FitJobProgress>& run) {
        QElapsedTimer clock;
        clock.start();
        const model::SketchFitProblem problem = model::sketchFitProblem(input, body);
        const int maxRounds = problem.settings.maxRounds;
        int reportedRound = 0;
        QElapsedTimer sinceReport;
        fit::FitHooks hooks;
        hooks.isCancelled = [&run] { return run.stopRequested(); };
        hooks.onProgress = [&](const fit::FitProgress& progress) {
            if (progress.round == reportedRound && sinceReport.isValid()
                && sinceReport.elapsed() < kProgressIntervalMilliseconds)
                return;
            reportedRound = progress.round;
            sinceReport.start();
            run.progress({progress.round, maxRounds, progress.iteration, progress.largestRelativeError});
        };
        const fit::FitResult result = model::fitSketch(problem, hooks);
        // A fit stopped early answers nothing: its request is cancelled or superseded.
        run.throwIfStopped();
        model::FitResult applied = model::appliedFitResult(input, result);
        const model::DrawnErrors drawnErrors = model::drawnErrors(input, *problem.motionWithoutFit, applied, body);
        const FitSummary summary = summaryOf(result, drawnErrors, static_cast<double>(clock.nsecsElapsed()) * 1e-9);
        return Answer{input, std::move(applied), summary};
    });
}

void FitJob::cancel()
{
    job_.cancel();
}

} // namespace gyre::jobs
