#include "jobs/subdivision_job.h"

#include "model/value_checks.h"

#include <QElapsedTimer>

#include <stdexcept>
#include <utility>

namespace gyre::jobs {

SubdivisionJob::SubdivisionJob(QObject* parent)
    : QObject(parent)
{
}

SubdivisionJob::~SubdivisionJob() = default;

std::uint64_t SubdivisionJob::request(std::vector<Pose> controlPoses, const SubdivisionSettings& settings)
{
    const std::uint64_t generation = ++newestGeneration_;
    thread_.post([this, generation, poses = std::move(controlPoses), settings](const std::atomic<bool>&) {
        QElapsedTimer clock;
        clock.start();
        try {
            model::checkPoseBudget(poses.size(), InterpolationMethod::Screw, settings);
            // The copy is the one allocation per run: the result has to leave the worker's buffers.
            std::vector<Pose> result = subdivider_.subdivide(poses, settings);
            const qint64 nanoseconds = clock.nsecsElapsed();
            QMetaObject::invokeMethod(
                this, [this, generation, result = std::move(result), nanoseconds] { deliver(generation, result, nanoseconds); },
                Qt::QueuedConnection);
        } catch (...) {
            QMetaObject::invokeMethod(
                this, [this, generation, reason = QString::fromStdString(currentExceptionText())] {
                    deliverFailure(generation, reason);
                }, Qt::QueuedConnection);
        }
    });
    return generation;
}

void SubdivisionJob::cancel()
{
    // A generation no request has: every result on its way is now stale.
    ++newestGeneration_;
}

void SubdivisionJob::deliver(std::uint64_t generation, const std::vector<Pose>& poses, qint64 nanoseconds)
{
    if (generation == newestGeneration_)
        emit subdivided(generation, poses, nanoseconds);
}

void SubdivisionJob::deliverFailure(std::uint64_t generation, const QString& reason)
{
    if (generation == newestGeneration_)
        emit failed(generation, reason);
}

} // namespace gyre::jobs
