#pragma once
// Reads a comma-separated text file a line at a time with bounded memory, for formats of plain
// numbers and names: no quoting. Skips blank lines and comment lines (first non-blank character
// '#'), accepts LF and CRLF line ends and a UTF-8 byte order mark, and rejects the signs of a file
// that is not text at all: control characters (NUL and friends) and lines too long to be a record.

#include "model/input_error.h"

#include <QFile>
#include <QString>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace gyre {

class CsvLineReader {
public:
    // The longest line accepted, in bytes without its line end. A pose row needs well under 1 KiB.
    static constexpr std::size_t kMaxLineBytes = 64 * 1024;

    // Opens the file; throws InputError if it cannot be read (missing, a directory, no permission).
    explicit CsvLineReader(const QString& path);

    // Reads on to the next record and splits it at commas into fields without surrounding spaces
    // and tabs. False at the end of the file. Throws InputError for a line that is too long or holds
    // control characters. The fields stay valid until the next call.
    bool nextRecord();
    const std::vector<std::string_view>& fields() const { return fields_; }

    // The 1-based number of the line last read, counting every line of the file.
    std::int64_t lineNumber() const { return lineNumber_; }
    const QString& path() const { return path_; }

    // An InputError located at the line last read, for the caller to throw.
    InputError errorHere(std::string_view message) const { return InputError(path_, lineNumber_, message); }

private:
    bool readLine();
    void checkCharacters() const;
    void split();

    QString path_;
    QFile file_;
    std::vector<char> buffer_;
    std::string_view line_;
    std::vector<std::string_view> fields_;
    std::int64_t lineNumber_ = 0;
};

} // namespace gyre
