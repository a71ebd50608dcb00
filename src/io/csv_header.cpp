#include "io/csv_header.h"

#include "core/number_text.h"

#include <algorithm>
#include <stdexcept>

namespace gyre::io {

std::string joinedNames(std::span<const std::string_view> names)
{
    std::string text;
    for (const std::string_view name : names) {
        if (!text.empty())
            text += ',';
        text += name;
    }
    return text;
}

CsvHeader::CsvHeader(CsvLineReader& reader, const std::function<bool(std::string_view)>& isKnown,
                     std::string_view knownNames)
    : reader_(reader)
{
    if (!reader_.nextRecord())
        throw InputError(reader_.path(), std::max<std::int64_t>(reader_.lineNumber(), 1),
                         "no header row: the file is empty or holds only comments");
    line_ = reader_.lineNumber();
    const auto& names = reader_.fields();
    fieldCount_ = names.size();
    for (std::size_t i = 0; i < names.size(); ++i) {
        const std::string_view name = names[i];
        if (name.empty())
            throw reader_.errorHere("header field " + std::to_string(i + 1) + " is empty");
        if (!isKnown(name))
            throw reader_.errorHere("unknown column '" + std::string(name) + "'; the columns are " +
                                    std::string(knownNames));
        if (!fields_.emplace(std::string(name), i).second)
            throw reader_.errorHere("column " + std::string(name) + " appears twice");
    }
}

std::optional<std::size_t> CsvHeader::field(std::string_view name) const
{
    const auto found = fields_.find(name);
    if (found == fields_.end())
        return std::nullopt;
    return found->second;
}

std::vector<std::size_t> CsvHeader::requiredFields(std::span<const std::string_view> names,
                                                   std::string_view setName) const
{
    std::vector<std::size_t> indices;
    for (const std::string_view name : names) {
        const std::optional<std::size_t> found = field(name);
        if (!found)
            throw InputError(reader_.path(), line_,
                             "missing column " + std::string(name) + " (" + std::string(setName) + " needs " +
                                 joinedNames(names) + ")");
        indices.push_back(*found);
    }
    return indices;
}

void CsvHeader::checkRowWidth() const
{
    const std::size_t fieldCount = reader_.fields().size();
    if (fieldCount != fieldCount_)
        throw reader_.errorHere(std::to_string(fieldCount) + " fields, but the header on line " +
                                std::to_string(line_) + " has " + std::to_string(fieldCount_));
}

double CsvHeader::number(std::size_t field, std::string_view column) const
{
    try {
        return parseFiniteNumber(reader_.fields()[field]);
    } catch (const std::invalid_argument& error) {
        throw reader_.errorHere("column " + std::string(column) + ": " + error.what());
    }
}

void IncreasingColumn::check(const CsvLineReader& reader, double value)
{
    if (previous_ && !(value > *previous_))
        throw reader.errorHere("column " + name_ + ": " + formatNumber(value) + " does not come after " +
                               formatNumber(*previous_) + " on line " + std::to_string(previousLine_) + "; " +
                               name_ + "s must strictly increase");
    previous_ = value;
    previousLine_ = reader.lineNumber();
}

} // namespace gyre::io
