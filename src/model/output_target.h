#pragma once
// Writing a file the user named, so that nothing is lost and nothing is replaced that must stay:
//
// - a regular file, a path that does not exist yet, or a symbolic link to a regular file: through
//   QSaveFile, so the file appears, or is replaced, only once every byte is written, and a failed
//   write leaves what was there. A symbolic link stays a link: the file it points to is replaced.
// - an existing file that is not a regular file (a FIFO, a character device such as /dev/null or a
//   terminal, a socket, or a link to one): opened and written directly, never replaced by a regular
//   file; opening it does not truncate it. A failed write may leave part of the bytes delivered.
// - "-": standard output, written directly as well.
// The model owns it because the project file is written here and io, which writes the other
// formats, depends on the model.

#include <QByteArray>
#include <QFileDevice>
#include <QString>

#include <memory>
#include <vector>

namespace gyre {

class OutputTarget {
public:
    // The path that names standard output.
    static constexpr QLatin1StringView kStandardOutput{"-"};

    explicit OutputTarget(QString path);
    ~OutputTarget();
    OutputTarget(const OutputTarget&) = delete;
    OutputTarget& operator=(const OutputTarget&) = delete;

    // Whether the target is written in place (standard output or a file that is not a regular file)
    // rather than through a temporary file.
    bool isDirect() const;
    const QString& path() const { return path_; }

    // Each throws OutputError naming the file when it fails: a directory, no permission, a full disk.
    void open();
    void write(const char* data, qint64 size);
    void write(const QByteArray& data) { write(data.constData(), data.size()); }
    // Makes the bytes written the file's contents: renames the temporary file over the target, or
    // flushes a direct target.
    void commit();

private:
    [[noreturn]] void fail() const;

    QString path_;
    std::unique_ptr<QFileDevice> device_;
};

// Writes `contents` as the whole of the file at `path` through an OutputTarget. Throws OutputError
// naming the file if it cannot be written.
void saveFileContents(const QString& path, const QByteArray& contents);

struct FileContents {
    QString path;
    QByteArray contents;
};

// Writes files that belong together (a .gltf and its .bin, an .obj and its .mtl): every one is written
// whole before any replaces what is on disk, so that a failure leaves all of them as they were (but for
// a failed rename in the commits themselves); the last is committed last. Throws OutputError naming the
// file that failed.
void saveFilesTogether(const std::vector<FileContents>& files);

} // namespace gyre
