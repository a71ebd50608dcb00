#include "jobs/scene_file_jobs.h"

#include "model/object_mass.h"

namespace gyre::jobs {

SceneFileJobs::SceneFileJobs(QObject* parent)
    : QObject(parent)
    , import_(JobPolicy::Queue,
              {.finished = [this](std::shared_ptr<const io::SceneImport> scene) { emit imported(finishJob(), scene); },
               .failed = [this](const QString& message) { emit failed(finishJob(), message); },
               .cancelled = [this] { emit cancelled(finishJob()); }})
    , export_(JobPolicy::Queue,
              {.finished = [this](const io::ExportReport& report) { emit exported(finishJob(), report); },
               .failed = [this](const QString& message) { emit failed(finishJob(), message); }})
{
}

bool SceneFileJobs::startImport(const QString& path, const io::ImportOptions& options)
{
    if (busy_)
        return false;
    busy_ = true;
    path_ = path;
    // A cancelled import's worker is killed, and the job answers cancelled whatever it then throws
    // (SceneWorkerCancelled).
    import_.post([path, options, limits = limits_](const JobRun<NoProgress>& run) {
        auto imported = std::make_shared<const io::SceneImport>(io::importSceneInWorker(path, options, limits, &run.stopFlag()));
        // Each mesh's mass properties here, once (model/object_mass.h keeps them while the mesh lives), not on the
        // interface's thread when the inspector or a ballistic track first asks for a large mesh's.
        for (const model::SceneObject& object : imported->scene.objects)
            model::objectMassProperties(object);
        return imported;
    });
    return true;
}

bool SceneFileJobs::startExport(const model::Scene& scene, const QString& path, io::SceneFormat format, double fps)
{
    if (busy_)
        return false;
    busy_ = true;
    path_ = path;
    // The scene is copied: the document may change while the export runs. Meshes are shared, not
    // copied, and never change once made.
    export_.post([scene, path, format, fps, limits = limits_](const JobRun<NoProgress>&) {
        return io::exportSceneInWorker(scene, path, format, fps, limits);
    });
    return true;
}

void SceneFileJobs::cancelImport()
{
    import_.cancel();
}

QString SceneFileJobs::finishJob()
{
    busy_ = false;
    return path_;
}

} // namespace gyre::jobs
