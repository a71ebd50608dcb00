#include "jobs/subdivision_job.h"

#include "model/value_checks.h"

#include <QElapsedTimer>

#include <utility>

namespace gyre::jobs {

SubdivisionJob::SubdivisionJob(QObject* parent)
    : QObject(parent)
    , job_(JobPolicy::NewestWins,
           {.finished = [this](Subdivided result) { emit subdivided(job_.newestRequest(), result.poses, result.nanoseconds); },
            .failed = [this](const QString& reason) { emit failed(job_.newestRequest(), reason); }})
{
}

SubdivisionJob::~SubdivisionJob() = default;

std::uint64_t SubdivisionJob::request(std::vector<Pose> controlPoses, const SubdivisionSettings& settings)
{
    return job_.post([this, poses = std::move(controlPoses), settings](const JobRun<NoProgress>& run) {
        run.throwIfStopped(); // cancelled before it started
        QElapsedTimer clock;
        clock.start();
        model::checkPoseBudget(poses.size(), InterpolationMethod::Screw, settings);
        // The copy is the one allocation per run: the result has to leave the subdivider's buffers.
        std::vector<Pose> result = subdivider_.subdivide(poses, settings);
        return Subdivided{std::move(result), clock.nsecsElapsed()};
    });
}

void SubdivisionJob::cancel()
{
    job_.cancel();
}

} // namespace gyre::jobs
