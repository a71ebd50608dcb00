#include "jobs/fit_job.h"

#include "fit/angular_velocity_fit.h"

#include <QElapsedTimer>

#include <stdexcept>
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
{
}

FitJob::~FitJob() = default;

void FitJob::request(model::ObjectId object, model::MotionTrack track)
{
    const std::uint64_t generation = ++newestGeneration_;
    auto cancelRequested = std::make_shared<std::atomic<bool>>(false);
    running_ = Running{generation, object, cancelRequested};
    thread_.post([this, generation, cancelRequested, input = std::move(track)](const std::atomic<bool>& superseded) {
        QElapsedTimer clock;
        clock.start();
        const auto sendToUi = [this](auto call) { QMetaObject::invokeMethod(this, std::move(call), Qt::QueuedConnection); };
        try {
            const model::SketchFitProblem problem = model::sketchFitProblem(input);
            const int maxRounds = problem.settings.maxRounds;
            int reportedRound = 0;
            QElapsedTimer sinceReport;
            fit::FitHooks hooks;
            hooks.isCancelled = [&superseded, &cancelRequested] { return superseded || *cancelRequested; };
            hooks.onProgress = [&](const fit::FitProgress& progress) {
                if (progress.round == reportedRound && sinceReport.isValid()
                    && sinceReport.elapsed() < kProgressIntervalMilliseconds)
                    return;
                reportedRound = progress.round;
                sinceReport.start();
                const FitJobProgress report{progress.round, maxRounds, progress.iteration, progress.largestRelativeError};
                sendToUi([this, generation, report] { deliverProgress(generation, report); });
            };
            const fit::FitResult result = model::fitSketch(problem, hooks);
            if (result.outcome == fit::FitOutcome::Cancelled) {
                sendToUi([this, generation] { answer(generation, [this](model::ObjectId id) { emit cancelled(id); }); });
                return;
            }
            model::FitResult applied = model::appliedFitResult(input, result);
            const model::DrawnErrors drawnErrors = model::drawnErrors(input, applied);
            const FitSummary summary = summaryOf(result, drawnErrors, static_cast<double>(clock.nsecsElapsed()) * 1e-9);
            sendToUi([this, generation, input, applied = std::move(applied), summary] {
                answer(generation, [&](model::ObjectId id) { emit finished(id, input, applied, summary); });
            });
        } catch (...) {
            // SketchFitError says what the artist should do; the fit's own refusals name what is wrong; any
            // other failure (out of memory, a solver error) is reported as it is.
            sendToUi([this, generation, message = QString::fromStdString(currentExceptionText())] {
                answer(generation, [&](model::ObjectId id) { emit failed(id, message); });
            });
        }
    });
}

void FitJob::cancel()
{
    if (running_)
        *running_->cancelRequested = true;
}

void FitJob::answer(std::uint64_t generation, const std::function<void(model::ObjectId)>& emitAnswer)
{
    if (!running_ || running_->generation != generation)
        return;
    const Running answered = *running_;
    running_.reset();
    if (*answered.cancelRequested)
        emit cancelled(answered.object);
    else
        emitAnswer(answered.object);
}

void FitJob::deliverProgress(std::uint64_t generation, const FitJobProgress& progress)
{
    if (running_ && running_->generation == generation && !*running_->cancelRequested)
        emit progressed(running_->object, progress);
}

} // namespace gyre::jobs
