#pragma once
// Autosave of unsaved work, and recovery after a crash.
//
// While the document has unsaved changes, an Autosave writes a recovery copy of it every interval
// into a directory of its own (the app passes QStandardPaths' AppLocalDataLocation). The UI thread
// only takes a snapshot of the scene, which shares every track's keys with the document (SharedVector),
// so it costs microseconds however long the capture; the project text is made and written by a job
// (job.h). Writes and removals run in the order asked, a newer one replacing one still waiting
// (newest wins): each write or removal sets all of the session's files, so only the last request
// decides what is on disk, and a queue would only write copies overwritten at once.
//
// Each session holds a QLockFile there for as long as it runs, so a later start can tell the copy of a
// session that crashed (its lock is stale or gone) from the copy of one still running. The copy goes
// away when the document is saved and when the session ends cleanly. A recovered copy is taken over
// by the session that recovers it, so it is kept until the recovered work is saved or discarded,
// through any number of further crashes.
//
// A session's files: <id>.gyre (the copy, a project file), <id>.json (which document it copies),
// <id>.lock.

#include "jobs/job.h"
#include "model/document.h"

#include <QDateTime>
#include <QLockFile>
#include <QObject>
#include <QString>
#include <QTimer>

#include <chrono>
#include <memory>
#include <vector>

namespace gyre::jobs {

// A copy left by a session that ended without cleaning up.
struct RecoveryFile {
    QString recoveryPath;
    QString documentPath; // the file the document was loaded from or saved to; empty if untitled
    QDateTime savedAt;
};

class Autosave : public QObject {
    Q_OBJECT

public:
    // Starts the session, creating `directory` if it is missing. Throws OutputError if the session's
    // lock cannot be taken there.
    Autosave(model::Document& document, const QString& directory, std::chrono::milliseconds interval,
             QObject* parent = nullptr);
    // The session ends cleanly: waits for a write under way, then removes its copy and its lock.
    ~Autosave() override;

    const QString& recoveryPath() const { return recoveryPath_; }

    // The copies in `directory` whose sessions are no longer running, newest first. Removes what
    // ended sessions left besides their copies (stale locks, notes of which document they copied).
    static std::vector<RecoveryFile> recoverableFiles(const QString& directory);
    // Opens the copy as the document's unsaved state (Document::recover) and takes it over as this
    // session's copy. Throws InputError and leaves the copy where it was if it cannot be read.
    void recover(const RecoveryFile& file);
    // Removes a copy the user chose not to recover.
    static void discard(const RecoveryFile& file);

signals:
    void autosaved(const QString& recoveryPath);
    // The copy could not be written; the next interval tries again.
    void autosaveFailed(const QString& message);

private:
    // What a request did to the session's files.
    enum class CopyChange { Written, Removed };

    void copyIfChanged();
    void removeCopy();

    model::Document& document_;
    QString recoveryPath_;
    QString infoPath_;
    std::unique_ptr<QLockFile> lock_;
    QTimer timer_;
    bool changedSinceCopy_ = false; // since the last copy was asked for, or since the session began
    std::unique_ptr<Job<CopyChange>> writer_; // reset first in the destructor: done before the files go
};

} // namespace gyre::jobs
