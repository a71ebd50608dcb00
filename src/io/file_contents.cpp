#include "io/file_contents.h"

#include "model/input_error.h"

#include <QSaveFile>

namespace gyre {

namespace {

OutputError writeError(const QSaveFile& file)
{
    return OutputError(file.fileName(), FileError::tr("cannot write: %1").arg(file.errorString()).toStdString());
}

} // namespace

void openForWriting(QSaveFile& file)
{
    if (!file.open(QIODevice::WriteOnly))
        throw writeError(file);
}

void writeBytes(QSaveFile& file, const char* data, qint64 size)
{
    if (file.write(data, size) != size)
        throw writeError(file);
}

void commitWrite(QSaveFile& file)
{
    if (!file.commit())
        throw writeError(file);
}

void saveFileContents(const QString& path, const QByteArray& contents)
{
    QSaveFile file(path);
    openForWriting(file);
    writeBytes(file, contents.constData(), contents.size());
    commitWrite(file);
}

} // namespace gyre
