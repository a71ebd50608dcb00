#include "io/csv_line_reader.h"

#include "core/number_text.h"

#include <QFileInfo>

#include <cstdio>

namespace gyre::io {

namespace {

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

bool isControlCharacter(unsigned char c) { return (c < 0x20 && c != '\t') || c == 0x7F; }

bool isSkipped(std::string_view line)
{
    const std::string_view content = trimmed(line);
    return content.empty() || content.front() == '#';
}

} // namespace

CsvLineReader::CsvLineReader(const QString& path) : path_(path), file_(path)
{
    // QFile refuses a directory too, but its message does not say so.
    if (QFileInfo(path).isDir())
        throw InputError(path_, "is a directory, not a file");
    if (!file_.open(QIODevice::ReadOnly))
        throw InputError(path_, "cannot open: " + file_.errorString().toStdString());
    // Room for the longest accepted line, its CR LF, one byte more to notice a longer line, and the
    // terminating NUL that QIODevice::readLine adds.
    buffer_.resize(kMaxLineBytes + 4);
}

std::optional<std::size_t> CsvLineReader::countRows(const QString& path, std::size_t budget, std::string_view rows)
{
    if (!QFileInfo(path).isFile())
        return std::nullopt;
    CsvLineReader reader(path);
    std::size_t records = 0;
    std::int64_t firstPastBudget = 0;
    try {
        while (reader.skipToRecord())
            if (++records == budget + 2) // the header, then the rows
                firstPastBudget = reader.lineNumber();
    } catch (const InputError&) {
        // Reported by the parse, in its place.
    }
    const std::size_t rowCount = records == 0 ? 0 : records - 1;
    if (rowCount > budget)
        throw InputError(path, firstPastBudget,
                         "the file holds " + std::to_string(rowCount) + " " + std::string(rows) + ", more than the " +
                             std::to_string(budget) + " a file may hold (docs/pose-csv.md)");
    return rowCount;
}

bool CsvLineReader::nextRecord()
{
    if (!skipToRecord())
        return false;
    split();
    return true;
}

bool CsvLineReader::skipToRecord()
{
    do {
        if (!readLine())
            return false;
    } while (isSkipped(line_));
    return true;
}

bool CsvLineReader::readLine()
{
    // Not atEnd(): for a pipe or a device it says nothing about what a read would return. A read
    // returns at least the line end of every line, and -1 at the end of the data or on an error.
    const qint64 length = file_.readLine(buffer_.data(), static_cast<qint64>(buffer_.size()));
    if (length <= 0) {
        if (file_.error() != QFileDevice::NoError)
            throw InputError(path_, lineNumber_ + 1, "cannot read: " + file_.errorString().toStdString());
        return false;
    }
    ++lineNumber_;
    line_ = std::string_view(buffer_.data(), static_cast<std::size_t>(length));
    if (line_.ends_with('\n'))
        line_.remove_suffix(1);
    if (line_.ends_with('\r'))
        line_.remove_suffix(1);
    // A line cut off by the buffer is longer than the limit, so this also catches lines that go on.
    if (line_.size() > kMaxLineBytes)
        throw errorHere("line longer than " + std::to_string(kMaxLineBytes) + " bytes; is this a pose CSV file?");
    if (lineNumber_ == 1 && line_.starts_with(kByteOrderMark))
        line_.remove_prefix(kByteOrderMark.size());
    checkCharacters();
    return true;
}

void CsvLineReader::checkCharacters() const
{
    for (std::size_t i = 0; i < line_.size(); ++i) {
        const auto c = static_cast<unsigned char>(line_[i]);
        if (isControlCharacter(c)) {
            char code[8];
            std::snprintf(code, sizeof code, "0x%02X", c);
            throw errorHere("control character " + std::string(code) + " at byte " + std::to_string(i + 1) +
                            "; is this a text file?");
        }
    }
}

void CsvLineReader::split()
{
    fields_.clear();
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line_.find(',', start);
        fields_.push_back(trimmed(line_.substr(start, comma - start)));
        if (comma == std::string_view::npos)
            return;
        start = comma + 1;
    }
}

} // namespace gyre::io
