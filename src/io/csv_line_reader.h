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
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gyre::io {

class CsvLineReader {
public:
    // The longest line accepted, in bytes without its line end. A pose row needs well under 1 KiB.
    static constexpr std::size_t kMaxLineBytes = 64 * 1024;

    // The most rows (records after the header) a file may hold: 2²², so that a file is read in a few
    // hundred MB at most. A larger file is refused before it is parsed (docs/pose-csv.md).
    static constexpr std::size_t kRowBudget = std::size_t{1} << 22;

    // How many rows a regular file holds, counted line by line before it is parsed so that the rows
    // can be stored without growing; throws InputError at the line of the first row past `budget`,
    // saying how many `rows` the file holds. A line that nextRecord would refuse ends the count, so
    // that the parse reports errors in the order of the file. nullopt for a file that cannot be read
    // twice (a FIFO, a device): its reader stops at the budget instead.
    static std::optional<std::size_t> countRows(const QString& path, std::size_t budget, std::string_view rows);

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
    bool skipToRecord();
    void checkCharacters() const;
    void split();

    QString path_;
    QFile file_;
    std::vector<char> buffer_;
    std::string_view line_;
    std::vector<std::string_view> fields_;
    std::int64_t lineNumber_ = 0;
};

} // namespace gyre::io
