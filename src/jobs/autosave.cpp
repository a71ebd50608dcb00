#include "jobs/autosave.h"

#include "model/input_error.h"
#include "model/project_file.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QUuid>

#include <algorithm>

namespace gyre::jobs {

using model::Document;

namespace {

const QString kCopySuffix = QStringLiteral(".gyre");
const QString kInfoSuffix = QStringLiteral(".json");
const QString kLockSuffix = QStringLiteral(".lock");
const QString kDocumentPathKey = QStringLiteral("documentPath");

// `path` with its suffix (.gyre) replaced.
QString sibling(const QString& copyPath, const QString& suffix)
{
    return copyPath.chopped(kCopySuffix.size()) + suffix;
}

void writeInfo(const QString& path, const QString& documentPath)
{
    QSaveFile file(path);
    const QByteArray json = QJsonDocument(QJsonObject{{kDocumentPathKey, documentPath}}).toJson();
    if (!file.open(QIODevice::WriteOnly) || file.write(json) != json.size() || !file.commit())
        throw OutputError(path, FileError::tr("cannot write: %1").arg(file.errorString()).toStdString());
}

// The document path an info file names; empty if it is missing or unreadable, which costs the user
// only the name of the file they were editing.
QString documentPathIn(const QString& infoPath)
{
    QFile file(infoPath);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(file.readAll()).object().value(kDocumentPathKey).toString();
}

// Whether the session that wrote `copyPath` has ended: its lock is stale (its process is gone) or
// missing. Taking the lock removes a stale one; releasing it removes the lock file.
bool sessionHasEnded(const QString& copyPath)
{
    QLockFile lock(sibling(copyPath, kLockSuffix));
    lock.setStaleLockTime(0);
    if (!lock.tryLock(0))
        return false;
    lock.unlock();
    return true;
}

// Removes the files in `directory` ending in `suffix` whose session has ended and left no copy: the lock
// of a session that crashed before its first copy, or that ended cleanly without removing its lock,
// and the note of a session whose copy was recovered or discarded.
void removeLeftovers(const QDir& directory, const QString& suffix)
{
    for (const QFileInfo& file : directory.entryInfoList({QStringLiteral("*") + suffix}, QDir::Files)) {
        const QString copy = file.absolutePath() + QLatin1Char('/') + file.completeBaseName() + kCopySuffix;
        if (QFileInfo::exists(copy) || !sessionHasEnded(copy))
            continue;
        QFile::remove(file.absoluteFilePath());
    }
}

} // namespace

Autosave::Autosave(Document& document, const QString& directory, std::chrono::milliseconds interval, QObject* parent)
    : QObject(parent)
    , document_(document)
{
    if (!QDir().mkpath(directory))
        throw OutputError(directory, FileError::tr("cannot create the autosave directory").toStdString());
    const QString session = QDir(directory).filePath(QUuid::createUuid().toString(QUuid::WithoutBraces));
    recoveryPath_ = session + kCopySuffix;
    infoPath_ = session + kInfoSuffix;
    lock_ = std::make_unique<QLockFile>(session + kLockSuffix);
    // A session lasts as long as the app runs: its lock is stale only when its process is gone.
    lock_->setStaleLockTime(0);
    if (!lock_->tryLock(0))
        throw OutputError(lock_->fileName(), FileError::tr("cannot take the autosave lock").toStdString());

    // A document that arrives with unsaved changes is copied at the first tick.
    changedSinceCopy_ = document_.isModified();
    // Every edit, undo and redo, and a new scene, says so.
    connect(&document_, &Document::changed, this, [this] { changedSinceCopy_ = true; });
    connect(&document_, &Document::modifiedChanged, this, [this](bool modified) {
        if (!modified)
            removeCopy();
    });
    writer_ = std::make_unique<Job<CopyChange>>(JobPolicy::NewestWins,
                                                Job<CopyChange>::Handlers{
                                                    .finished = [this](CopyChange change) {
                                                        if (change == CopyChange::Written)
                                                            emit autosaved(recoveryPath_);
                                                    },
                                                    .failed = [this](const QString& error) {
                                                        changedSinceCopy_ = true; // try again at the next tick
                                                        emit autosaveFailed(error);
                                                    }});
    connect(&timer_, &QTimer::timeout, this, &Autosave::copyIfChanged);
    timer_.start(interval);
}

Autosave::~Autosave()
{
    writer_.reset();
    QFile::remove(recoveryPath_);
    QFile::remove(infoPath_);
}

void Autosave::copyIfChanged()
{
    if (!changedSinceCopy_ || !document_.isModified())
        return;
    changedSinceCopy_ = false;
    // The snapshot shares the tracks' keys with the document (model::SharedVector): what the UI
    // thread pays here does not grow with the length of the motion.
    writer_->post([this, scene = document_.scene(), documentPath = document_.filePath()](const JobRun<NoProgress>&) {
        writeInfo(infoPath_, documentPath);
        model::writeProject(recoveryPath_, scene);
        return CopyChange::Written;
    });
}

void Autosave::removeCopy()
{
    changedSinceCopy_ = false;
    // After any write still under way, in place of one still waiting.
    writer_->post([recoveryPath = recoveryPath_, infoPath = infoPath_](const JobRun<NoProgress>&) {
        QFile::remove(recoveryPath);
        QFile::remove(infoPath);
        return CopyChange::Removed;
    });
}

std::vector<RecoveryFile> Autosave::recoverableFiles(const QString& directory)
{
    removeLeftovers(QDir(directory), kLockSuffix);
    removeLeftovers(QDir(directory), kInfoSuffix);
    std::vector<RecoveryFile> files;
    const QFileInfoList copies = QDir(directory).entryInfoList({QStringLiteral("*") + kCopySuffix}, QDir::Files);
    for (const QFileInfo& copy : copies) {
        const QString path = copy.absoluteFilePath();
        if (sessionHasEnded(path))
            files.push_back({path, documentPathIn(sibling(path, kInfoSuffix)), copy.lastModified()});
    }
    std::sort(files.begin(), files.end(),
              [](const RecoveryFile& a, const RecoveryFile& b) { return a.savedAt > b.savedAt; });
    return files;
}

void Autosave::recover(const RecoveryFile& file)
{
    document_.recover(file.recoveryPath, file.documentPath);
    // The copy on disk is the document now: it becomes this session's copy at once, so that it is
    // never missing while the recovered work is unsaved. The next tick writes it again all the same,
    // in case a write of the document as it was before is still under way.
    QFile::remove(recoveryPath_);
    QFile::remove(infoPath_);
    QFile::rename(file.recoveryPath, recoveryPath_);
    QFile::rename(sibling(file.recoveryPath, kInfoSuffix), infoPath_);
    changedSinceCopy_ = true;
}

void Autosave::discard(const RecoveryFile& file)
{
    QFile::remove(file.recoveryPath);
    QFile::remove(sibling(file.recoveryPath, kInfoSuffix));
}

} // namespace gyre::jobs
