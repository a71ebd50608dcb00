#pragma once
// Scene import and export in gyre-scene-worker (io/scene_worker.h), waited for on Qt's thread pool, so
// the UI thread never waits on Assimp and a file that crashes Assimp, or exhausts the worker's memory
// or time limit, ends in `failed` naming the file. The UI thread starts a job and receives its outcome
// as a signal, never before the start call has returned; one job runs at a time.
//
// Cancelling an import stops its worker and drops what it read: the document never sees it. An export
// is not cancellable: it writes through temporary files (QSaveFile), so stopping it half-way would
// change nothing anyway, and it is quick (docs/scene-files.md).

#include "io/scene_export.h"
#include "io/scene_import.h"
#include "io/scene_worker.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <atomic>
#include <cstdint>
#include <memory>

namespace gyre::jobs {

class SceneFileJobs : public QObject {
    Q_OBJECT

public:
    explicit SceneFileJobs(QObject* parent = nullptr);

    bool isBusy() const { return busy_; }

    // Reads the scene at `path`. Refused (false) while another job runs.
    bool startImport(const QString& path, const io::ImportOptions& options = {});
    // Writes a copy of `scene` to `path` in `format`, its motion baked at `fps`. Refused (false)
    // while another job runs.
    bool startExport(const model::Scene& scene, const QString& path, io::SceneFormat format, double fps);
    // Stops the running import and drops its result; it ends with `cancelled`.
    void cancelImport();

    // The worker's limits for the jobs started from now on.
    void setWorkerLimits(const io::SceneWorkerLimits& limits) { limits_ = limits; }

signals:
    void imported(const QString& path, std::shared_ptr<const gyre::io::SceneImport> scene);
    void exported(const QString& path, const gyre::io::ExportReport& report);
    // The message names the file and says what was wrong with it.
    void failed(const QString& path, const QString& message);
    void cancelled(const QString& path);

private:
    // Ends the running job and reports, unless it was cancelled.
    bool finishJob(std::uint64_t job, const QString& path);

    bool busy_ = false;
    std::uint64_t job_ = 0; // the running job's number; cancelling moves past it
    // Set by cancelImport for the running import's worker to be stopped.
    std::shared_ptr<std::atomic_bool> cancelRunning_;
    io::SceneWorkerLimits limits_;
};

} // namespace gyre::jobs
