#pragma once
// The header row of a comma-separated table of numbers, and the checks every such table shares:
// known, non-empty, unrepeated column names; required columns present; rows as wide as the header;
// numbers finite; a column whose values must strictly increase.

#include "io/csv_line_reader.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace gyre::io {

// "a,b,c"
std::string joinedNames(std::span<const std::string_view> names);

class CsvHeader {
public:
    // Reads the header row. Throws InputError for an empty file, an empty, unknown or repeated name;
    // `knownNames` describes the accepted names for that message.
    CsvHeader(CsvLineReader& reader, const std::function<bool(std::string_view)>& isKnown,
              std::string_view knownNames);

    bool has(std::string_view name) const { return fields_.contains(name); }
    std::optional<std::size_t> field(std::string_view name) const;
    // The fields of `names`, in that order; throws InputError naming the first missing one and
    // saying that `setName` needs all of `names`.
    std::vector<std::size_t> requiredFields(std::span<const std::string_view> names, std::string_view setName) const;
    std::int64_t line() const { return line_; }

    // Checks that the record just read is as wide as the header.
    void checkRowWidth() const;
    // The finite number in `field` of the record just read; InputError naming `column` otherwise.
    double number(std::size_t field, std::string_view column) const;

private:
    CsvLineReader& reader_;
    std::map<std::string, std::size_t, std::less<>> fields_;
    std::size_t fieldCount_ = 0;
    std::int64_t line_ = 0;
};

// Checks that a column's values strictly increase from row to row, naming both lines if not.
class IncreasingColumn {
public:
    explicit IncreasingColumn(std::string_view name)
        : name_(name)
    {
    }

    void check(const CsvLineReader& reader, double value);

private:
    std::string name_;
    std::optional<double> previous_;
    std::int64_t previousLine_ = 0;
};

} // namespace gyre::io
