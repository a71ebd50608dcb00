#include "io/number_csv.h"

#include "io/csv_header.h"
#include "io/csv_line_reader.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace gyre::io {

bool NumberTable::hasColumn(std::string_view name) const { return std::ranges::count(columns_, name) > 0; }

double NumberTable::value(std::size_t row, std::string_view column) const
{
    const auto found = std::ranges::find(columns_, column);
    if (found == columns_.end())
        throw std::out_of_range("no column " + std::string(column));
    return values_.at(row * columns_.size() + static_cast<std::size_t>(found - columns_.begin()));
}

InputError NumberTable::errorAt(std::size_t row, std::string_view message) const
{
    return InputError(path_, lines_.at(row), message);
}

void NumberTable::reserve(std::size_t rows)
{
    values_.reserve(rows * columns_.size());
    lines_.reserve(rows);
}

void NumberTable::addRow(std::int64_t line, std::span<const double> values)
{
    values_.insert(values_.end(), values.begin(), values.end());
    lines_.push_back(line);
}

NumberTable readNumberCsv(const QString& path, const NumberCsvColumns& columns)
{
    std::vector<std::string_view> known(columns.required.begin(), columns.required.end());
    known.insert(known.end(), columns.optional.begin(), columns.optional.end());
    std::string knownText = joinedNames(columns.required);
    if (!columns.optional.empty())
        knownText += ", optionally " + joinedNames(columns.optional);

    CsvLineReader reader(path);
    const CsvHeader header(reader, [&known](std::string_view name) { return std::ranges::count(known, name) > 0; },
                           knownText);
    std::vector<std::string_view> present;
    std::vector<std::size_t> fields = header.requiredFields(columns.required, "this file");
    present.assign(columns.required.begin(), columns.required.end());
    for (const std::string_view name : columns.optional) {
        if (const std::optional<std::size_t> field = header.field(name)) {
            present.push_back(name);
            fields.push_back(*field);
        }
    }

    NumberTable table(path, present);
    std::optional<IncreasingColumn> increasing;
    if (columns.increasing)
        increasing.emplace(*columns.increasing);
    std::vector<double> values(present.size());
    if (const auto rowCount = CsvLineReader::countRows(path, CsvLineReader::kRowBudget, "rows"))
        table.reserve(*rowCount);
    while (reader.nextRecord()) {
        if (table.rowCount() == CsvLineReader::kRowBudget)
            throw reader.errorHere("more than the " + std::to_string(CsvLineReader::kRowBudget) +
                                   " rows a file may hold (docs/pose-csv.md)");
        header.checkRowWidth();
        for (std::size_t i = 0; i < present.size(); ++i) {
            values[i] = header.number(fields[i], present[i]);
            if (increasing && present[i] == *columns.increasing)
                increasing->check(reader, values[i]);
        }
        table.addRow(reader.lineNumber(), values);
    }
    if (table.rowCount() == 0)
        throw reader.errorHere("no rows after the header on line " + std::to_string(header.line()));
    return table;
}

} // namespace gyre::io
