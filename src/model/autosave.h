#pragma once
// Autosave of unsaved work, and recovery after a crash.
//
// While the document has unsaved changes, an Autosave writes a recovery copy of it every interval
// into a directory of its own (the app passes QStandardPaths' AppLocalDataLocation). Each session
// holds a QLockFile there for as long as it runs, so a later start can tell the copy of a session
// that crashed (its lock is stale or gone) from the copy of one still running. The copy goes away
// when the document is saved and when the session ends cleanly.
//
// A session's files: <id>.gyre (the copy, a project file), <id>.json (which document it copies),
// <id>.lock.

#include "model/document.h"

#include <QDateTime>
#include <QLockFile>
#include <QObject>
#include <QString>
#include <QTimer>

#include <chrono>
#include <memory>
#include <vector>

namespace gyre::model {

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
    Autosave(Document& document, const QString& directory, std::chrono::milliseconds interval,
             QObject* parent = nullptr);
    // The session ends cleanly: its copy and its lock are removed.
    ~Autosave() override;

    const QString& recoveryPath() const { return recoveryPath_; }

    // The copies in `directory` whose sessions are no longer running, newest first.
    static std::vector<RecoveryFile> recoverableFiles(const QString& directory);
    // Opens the copy as the document's unsaved state (Document::recover), then removes it: from
    // now on the document's own session keeps it safe. Throws InputError and keeps the copy if it
    // cannot be read.
    static void recover(Document& document, const RecoveryFile& file);
    // Removes a copy the user chose not to recover.
    static void discard(const RecoveryFile& file);

signals:
    void autosaved(const QString& recoveryPath);
    void autosaveFailed(const QString& message);

private:
    void writeCopyIfChanged();
    void removeCopy();

    Document& document_;
    QString recoveryPath_;
    QString infoPath_;
    std::unique_ptr<QLockFile> lock_;
    QTimer timer_;
    bool changedSinceCopy_ = false; // since the last copy, or since the session began
};

} // namespace gyre::model
