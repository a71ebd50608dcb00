#pragma once
// Scene import and export on Qt's thread pool, so the UI thread never waits on Assimp. The UI thread
// starts a job and receives its outcome as a signal; one job runs at a time.
//
// Assimp cannot be interrupted, so cancelling an import lets it run to its end and drops what it
// read: the document never sees it. An export is not cancellable: it writes through temporary files
// (QSaveFile), so stopping it half-way would change nothing anyway, and it is quick (docs/scene-files.md).

#include "io/scene_export.h"
#include "io/scene_import.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <memory>

namespace gyre::jobs {

class SceneFileJobs : public QObject {
    Q_OBJECT

public:
    explicit SceneFileJobs(QObject* parent = nullptr);

    bool isBusy() const { return busy_; }

    // Reads the scene at `path`. Refused (false) while another job runs.
    bool startImport(const QString& path, const ImportOptions& options = {});
    // Writes a copy of `scene` to `path` in `format`, its motion baked at `fps`. Refused (false)
    // while another job runs.
    bool startExport(const model::Scene& scene, const QString& path, SceneFormat format, double fps);
    // Drops the running import's result; it ends with `cancelled`.
    void cancelImport();

signals:
    void imported(const QString& path, std::shared_ptr<const gyre::SceneImport> scene);
    void exported(const QString& path, const gyre::ExportReport& report);
    // The message names the file and says what was wrong with it.
    void failed(const QString& path, const QString& message);
    void cancelled(const QString& path);

private:
    // Ends the running job and reports, unless it was cancelled.
    bool finishJob(std::uint64_t job, const QString& path);

    bool busy_ = false;
    std::uint64_t job_ = 0; // the running job's number; cancelling moves past it
};

} // namespace gyre::jobs
