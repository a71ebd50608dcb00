#include "model/output_target.h"

#include "model/input_error.h"

#include <QFileInfo>
#include <QSaveFile>

#include <cstdio>

namespace gyre {

namespace {

// QFileInfo follows symbolic links, so a link is judged by what it points to.
bool isExistingNonRegularFile(const QFileInfo& info) { return info.exists() && !info.isFile() && !info.isDir(); }

} // namespace

OutputTarget::OutputTarget(QString path) : path_(std::move(path)) {}

OutputTarget::~OutputTarget() = default;

bool OutputTarget::isDirect() const
{
    return path_ == kStandardOutput || isExistingNonRegularFile(QFileInfo(path_));
}

void OutputTarget::open()
{
    if (path_ == kStandardOutput) {
        auto standardOutput = std::make_unique<QFile>();
        // Qt writes through the C stream, so text the program printed before keeps its place.
        if (!standardOutput->open(stdout, QIODevice::WriteOnly, QFileDevice::DontCloseHandle))
            throw OutputError(path_, FileError::tr("cannot write to standard output: %1")
                                         .arg(standardOutput->errorString())
                                         .toStdString());
        device_ = std::move(standardOutput);
        return;
    }
    const QFileInfo info(path_);
    if (info.isDir())
        throw OutputError(path_, FileError::tr("is a directory, not a file").toStdString());
    if (isExistingNonRegularFile(info))
        // QFile asks for truncation with WriteOnly, which POSIX leaves without effect on a FIFO or a
        // device; the file is never removed or renamed over.
        device_ = std::make_unique<QFile>(path_);
    else
        device_ = std::make_unique<QSaveFile>(path_);
    if (!device_->open(QIODevice::WriteOnly))
        fail();
}

void OutputTarget::write(const char* data, qint64 size)
{
    if (device_->write(data, size) != size)
        fail();
}

void OutputTarget::commit()
{
    if (auto* saveFile = qobject_cast<QSaveFile*>(device_.get())) {
        if (!saveFile->commit())
            fail();
        return;
    }
    if (!device_->flush())
        fail();
    device_->close();
}

void OutputTarget::fail() const
{
    throw OutputError(path_, FileError::tr("cannot write: %1").arg(device_->errorString()).toStdString());
}

void saveFileContents(const QString& path, const QByteArray& contents)
{
    OutputTarget target(path);
    target.open();
    target.write(contents);
    target.commit();
}

void saveFilesTogether(const std::vector<FileContents>& files)
{
    std::vector<std::unique_ptr<OutputTarget>> targets;
    for (const FileContents& file : files) {
        targets.push_back(std::make_unique<OutputTarget>(file.path));
        targets.back()->open();
        targets.back()->write(file.contents);
    }
    for (const std::unique_ptr<OutputTarget>& target : targets)
        target->commit();
}

} // namespace gyre
