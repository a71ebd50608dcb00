#pragma once
// Whole files written at once, through QSaveFile: the file appears, or is replaced, only once every
// byte is written, so a failed write leaves what was there.

#include <QByteArray>
#include <QSaveFile>
#include <QString>

namespace gyre {

// Throws OutputError naming the file if it cannot be written.
void saveFileContents(const QString& path, const QByteArray& contents);

// The steps of a QSaveFile write, each throwing OutputError naming the file when it fails.
void openForWriting(QSaveFile& file);
void writeBytes(QSaveFile& file, const char* data, qint64 size);
void commitWrite(QSaveFile& file);

} // namespace gyre
