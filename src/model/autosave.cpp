#include "model/autosave.h"

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

namespace gyre::model {

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
    const auto noteChange = [this] { changedSinceCopy_ = true; };
    connect(&document_.undoStack(), &QUndoStack::indexChanged, this, noteChange);
    connect(&document_, &Document::sceneReset, this, noteChange);
    connect(&document_, &Document::modifiedChanged, this, [this](bool modified) {
        if (!modified)
            removeCopy();
    });
    connect(&timer_, &QTimer::timeout, this, &Autosave::writeCopyIfChanged);
    timer_.start(interval);
}

Autosave::~Autosave() { removeCopy(); }

void Autosave::writeCopyIfChanged()
{
    if (!changedSinceCopy_ || !document_.isModified())
        return;
    try {
        writeInfo(infoPath_, document_.filePath());
        writeProject(recoveryPath_, document_.scene());
        changedSinceCopy_ = false;
        emit autosaved(recoveryPath_);
    } catch (const OutputError& error) {
        emit autosaveFailed(QString::fromStdString(error.what()));
    }
}

void Autosave::removeCopy()
{
    QFile::remove(recoveryPath_);
    QFile::remove(infoPath_);
    changedSinceCopy_ = false;
}

std::vector<RecoveryFile> Autosave::recoverableFiles(const QString& directory)
{
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

void Autosave::recover(Document& document, const RecoveryFile& file)
{
    document.recover(file.recoveryPath, file.documentPath);
    discard(file);
}

void Autosave::discard(const RecoveryFile& file)
{
    QFile::remove(file.recoveryPath);
    QFile::remove(sibling(file.recoveryPath, kInfoSuffix));
}

} // namespace gyre::model
