#pragma once
// Tables of plain numbers under named columns, for the files that are not poses: angular-velocity
// samples, sketch curves, patterns. The same text rules as the pose format (docs/pose-csv.md): a
// header row naming the columns in any order, '#' comment lines, blank lines skipped.

#include "model/input_error.h"

#include <QString>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace gyre::io {

struct NumberCsvColumns {
    std::span<const std::string_view> required;
    std::span<const std::string_view> optional;
    std::optional<std::string_view> increasing;  // a column whose values must strictly increase
};

class NumberTable {
public:
    NumberTable(QString path, std::vector<std::string_view> columns)
        : path_(std::move(path))
        , columns_(std::move(columns))
    {
    }

    std::size_t rowCount() const { return lines_.size(); }
    bool hasColumn(std::string_view name) const;
    // The value in a column the file has; throws std::out_of_range for another.
    double value(std::size_t row, std::string_view column) const;
    // An InputError at a row's line, for the caller to throw.
    InputError errorAt(std::size_t row, std::string_view message) const;

    void reserve(std::size_t rows);
    void addRow(std::int64_t line, std::span<const double> values);

private:
    QString path_;
    std::vector<std::string_view> columns_;  // those the file has, in the order of `values_`
    std::vector<double> values_;             // row after row
    std::vector<std::int64_t> lines_;
};

// Reads a number file with the `required` columns and any of the `optional` ones, no others. Throws
// InputError, naming the file, the line and the column, for anything else, including a file with
// no rows or more than CsvLineReader::kRowBudget rows.
NumberTable readNumberCsv(const QString& path, const NumberCsvColumns& columns);

} // namespace gyre::io
