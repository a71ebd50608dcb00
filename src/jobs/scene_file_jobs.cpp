#include "jobs/scene_file_jobs.h"

#include <QFuture>
#include <QtConcurrent/QtConcurrentRun>

#include <exception>

namespace gyre::jobs {

namespace {

// What a job gives back: its result, or the message of the error that stopped it. Caught on the
// worker, so that the message is the file's own and not a copy of a base class's.
template <class Result>
struct Outcome {
    std::shared_ptr<const Result> result;
    QString error;
};

template <class Work>
auto runCatching(Work work) -> Outcome<decltype(work())>
{
    try {
        return {std::make_shared<const decltype(work())>(work()), QString()};
    } catch (const io::SceneWorkerCancelled&) {
        return {}; // the job has already been counted as cancelled
    } catch (const std::exception& error) {
        return {nullptr, QString::fromUtf8(error.what())};
    }
}

// Qt runs a continuation at once, inside then(), when the work has already ended, as a worker that
// cannot start does; posting the outcome keeps it from arriving before startImport or startExport
// has returned and the caller has shown that the job runs.
template <class Deliver>
void later(QObject* context, Deliver deliver)
{
    QMetaObject::invokeMethod(context, std::move(deliver), Qt::QueuedConnection);
}

} // namespace

SceneFileJobs::SceneFileJobs(QObject* parent)
    : QObject(parent)
{
}

bool SceneFileJobs::startImport(const QString& path, const io::ImportOptions& options)
{
    if (busy_)
        return false;
    busy_ = true;
    const std::uint64_t job = ++job_;
    cancelRunning_ = std::make_shared<std::atomic_bool>(false);
    QtConcurrent::run([path, options, limits = limits_, cancel = cancelRunning_] {
        return runCatching([&] { return io::importSceneInWorker(path, options, limits, cancel.get()); });
    }).then(this, [this, job, path](const Outcome<io::SceneImport>& outcome) {
        later(this, [this, job, path, outcome] {
            if (!finishJob(job, path))
                return;
            if (outcome.result)
                emit imported(path, outcome.result);
            else
                emit failed(path, outcome.error);
        });
    });
    return true;
}

bool SceneFileJobs::startExport(const model::Scene& scene, const QString& path, io::SceneFormat format, double fps)
{
    if (busy_)
        return false;
    busy_ = true;
    const std::uint64_t job = ++job_;
    // The scene is copied: the document may change while the export runs. Meshes are shared, not
    // copied, and never change once made.
    QtConcurrent::run([scene, path, format, fps, limits = limits_] {
        return runCatching([&] { return io::exportSceneInWorker(scene, path, format, fps, limits); });
    }).then(this, [this, job, path](const Outcome<io::ExportReport>& outcome) {
        later(this, [this, job, path, outcome] {
            if (!finishJob(job, path))
                return;
            if (outcome.result)
                emit exported(path, *outcome.result);
            else
                emit failed(path, outcome.error);
        });
    });
    return true;
}

void SceneFileJobs::cancelImport()
{
    if (!busy_)
        return;
    ++job_;
    if (cancelRunning_)
        cancelRunning_->store(true);
}

bool SceneFileJobs::finishJob(std::uint64_t job, const QString& path)
{
    busy_ = false;
    if (job == job_)
        return true;
    emit cancelled(path);
    return false;
}

} // namespace gyre::jobs
