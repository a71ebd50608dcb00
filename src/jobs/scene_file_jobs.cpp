#include "jobs/scene_file_jobs.h"

#include <QFuture>
#include <QtConcurrent/QtConcurrentRun>

#include <exception>

namespace gyre::jobs {

SceneFileJobs::SceneFileJobs(QObject* parent)
    : QObject(parent)
{
}

bool SceneFileJobs::startImport(const QString& path, const ImportOptions& options)
{
    if (busy_)
        return false;
    busy_ = true;
    const std::uint64_t job = ++job_;
    QtConcurrent::run([path, options] { return std::make_shared<const SceneImport>(importScene(path, options)); })
        .then(this,
              [this, job, path](std::shared_ptr<const SceneImport> scene) {
                  if (finishJob(job, path))
                      emit imported(path, std::move(scene));
              })
        .onFailed(this, [this, job, path](const std::exception& error) {
            if (finishJob(job, path))
                emit failed(path, QString::fromUtf8(error.what()));
        });
    return true;
}

bool SceneFileJobs::startExport(const model::Scene& scene, const QString& path, SceneFormat format, double fps)
{
    if (busy_)
        return false;
    busy_ = true;
    const std::uint64_t job = ++job_;
    // The scene is copied: the document may change while the export runs. Meshes are shared, not
    // copied, and never change once made.
    QtConcurrent::run([scene, path, format, fps] { return exportScene(scene, path, format, fps); })
        .then(this,
              [this, job, path](const ExportReport& report) {
                  if (finishJob(job, path))
                      emit exported(path, report);
              })
        .onFailed(this, [this, job, path](const std::exception& error) {
            if (finishJob(job, path))
                emit failed(path, QString::fromUtf8(error.what()));
        });
    return true;
}

void SceneFileJobs::cancelImport()
{
    if (busy_)
        ++job_;
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
