#pragma once
// The errors that reading and writing files report. Their messages are meant for the user as they
// stand: each names the file, and where there is one the 1-based line, as `path:line: what`, or the
// field, as `path: objects[2].name: what`. The model owns them because the project file is read here
// and io, which reads the other formats, depends on the model.

#include <QCoreApplication>
#include <QString>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace gyre {

// The words of these errors in the user's language, as FileError::tr("..."): the desktop app installs
// its translations, gyre-cli none, so what pipelines read of gyre-cli stays English.
class FileError {
    Q_DECLARE_TR_FUNCTIONS(gyre::FileError)

public:
    // A number as the messages write it: the shortest text that reads back exactly (formatNumber).
    static QString number(double value);
};

// A file that cannot be read, or whose contents are not what the format allows.
class InputError : public std::runtime_error {
public:
    InputError(const QString& path, std::string_view message);
    InputError(const QString& path, std::int64_t line, std::string_view message);
};

// A file that cannot be written. The file named keeps its old contents, or stays absent.
class OutputError : public std::runtime_error {
public:
    OutputError(const QString& path, std::string_view message);
};

} // namespace gyre
