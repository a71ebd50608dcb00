#include "jobs/subdivision_job.h"

#include "model/value_checks.h"

#include <QElapsedTimer>

#include <algorithm>
#include <utility>

namespace gyre::jobs {

namespace {

bool samePolyscrew(const SubdivisionJob::Polyscrew& a, const SubdivisionJob::Polyscrew& b)
{
    return a.settings == b.settings &&
           std::equal(a.controlPoses.begin(), a.controlPoses.end(), b.controlPoses.begin(), b.controlPoses.end(),
                      [](const Pose& p, const Pose& q) {
                          return p.orientation.coeffs() == q.orientation.coeffs() && p.position == q.position;
                      });
}

} // namespace

SubdivisionJob::SubdivisionJob(QObject* parent)
    : QObject(parent)
    , job_(JobPolicy::NewestWins,
           {.finished = [this](Subdivided result) { emit subdivided(job_.newestRequest(), result.poses, result.nanoseconds); },
            .failed = [this](const QString& reason) { emit failed(job_.newestRequest(), reason); }})
{
}

SubdivisionJob::~SubdivisionJob() = default;

std::uint64_t SubdivisionJob::request(std::vector<Polyscrew> polyscrews)
{
    return job_.post([this, polyscrews = std::move(polyscrews)](const JobRun<NoProgress>& run) {
        run.throwIfStopped(); // cancelled before it started
        QElapsedTimer clock;
        clock.start();
        std::vector<Kept> kept;
        kept.reserve(polyscrews.size());
        for (const Polyscrew& polyscrew : polyscrews) {
            const auto same = std::find_if(previousRun_.begin(), previousRun_.end(),
                                           [&](const Kept& previous) { return samePolyscrew(previous.polyscrew, polyscrew); });
            if (same != previousRun_.end()) {
                kept.push_back({polyscrew, same->poses});
                continue;
            }
            model::checkPoseBudget(polyscrew.controlPoses.size(), InterpolationMethod::Screw, polyscrew.settings);
            // The copy is the one allocation per polyscrew subdivided: the result has to leave the subdivider's buffers.
            kept.push_back({polyscrew, std::make_shared<const std::vector<Pose>>(
                                           subdivider_.subdivide(polyscrew.controlPoses, polyscrew.settings))});
        }
        previousRun_ = kept;
        Subdivided result;
        result.poses.reserve(kept.size());
        for (const Kept& each : kept)
            result.poses.push_back(each.poses);
        result.nanoseconds = clock.nsecsElapsed();
        return result;
    });
}

void SubdivisionJob::cancel()
{
    job_.cancel();
}

} // namespace gyre::jobs
