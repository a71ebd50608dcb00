#include "io/pose_csv.h"

#include "core/number_text.h"
#include "io/csv_header.h"
#include "io/csv_line_reader.h"
#include "model/output_target.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace gyre::io {

namespace {

constexpr std::string_view kTimeName = "time";
// Rows are converted to their columns and written a block at a time, so that writing needs memory
// for one block beside the table.
constexpr std::size_t kRowsPerBlock = 4096;
constexpr std::array<std::string_view, 3> kPositionNames{"x", "y", "z"};

// "qw,qx,qy,qz | m00,…,m22 | …": the rotation column sets, for messages.
std::string rotationColumnSets()
{
    std::string text;
    for (const auto& [columns, setName] : kRotationColumnsNames) {
        if (!text.empty())
            text += " | ";
        text += joinedNames(rotationColumnNames(columns));
    }
    return text;
}

std::string knownColumnNames()
{
    return std::string(kTimeName) + " | " + rotationColumnSets() + " | " + joinedNames(kPositionNames);
}

bool isKnownColumn(std::string_view name)
{
    const auto among = [name](std::span<const std::string_view> names) { return std::ranges::count(names, name) > 0; };
    return name == kTimeName || among(kPositionNames) ||
           std::ranges::any_of(kRotationColumnsNames, [&among](const auto& entry) {
               return among(rotationColumnNames(entry.first));
           });
}

// Where each column of the header is among the fields of a row.
struct Layout {
    RotationColumns rotationColumns = RotationColumns::Quaternion;
    std::optional<std::size_t> timeField;
    std::vector<std::size_t> rotationFields; // in rotationColumnNames order
    std::vector<std::size_t> positionFields; // x, y, z; empty without position columns
};

class PoseCsvParser {
public:
    PoseCsvParser(const QString& path, const EulerConvention& convention, TimeColumn timeColumn)
        : reader_(path)
        , header_(reader_, isKnownColumn, knownColumnNames())
        , convention_(convention)
        , timeColumn_(timeColumn)
    {
    }

    PoseTable read();

private:
    Layout layout() const;
    RotationColumns findRotationColumns() const;
    PoseRow readRow(const Layout& layout);

    CsvLineReader reader_;
    CsvHeader header_;
    EulerConvention convention_;
    TimeColumn timeColumn_;
    IncreasingColumn times_{kTimeName};
};

PoseTable PoseCsvParser::read()
{
    const Layout columns = layout();
    PoseTable table{columns.rotationColumns, columns.timeField.has_value(), !columns.positionFields.empty(), {}};
    if (const auto rowCount = CsvLineReader::countRows(reader_.path(), CsvLineReader::kRowBudget, "poses"))
        table.rows.reserve(*rowCount);
    while (reader_.nextRecord()) {
        if (table.rows.size() == CsvLineReader::kRowBudget)
            throw reader_.errorHere("more than the " + std::to_string(CsvLineReader::kRowBudget) +
                                    " poses a file may hold (docs/pose-csv.md)");
        table.rows.push_back(readRow(columns));
    }
    if (table.rows.empty())
        throw reader_.errorHere("no poses after the header on line " + std::to_string(header_.line()));
    return table;
}

Layout PoseCsvParser::layout() const
{
    Layout layout;
    layout.rotationColumns = findRotationColumns();
    const auto setName = rotationColumnsName(layout.rotationColumns);
    layout.rotationFields = header_.requiredFields(rotationColumnNames(layout.rotationColumns), setName);
    layout.timeField = header_.field(kTimeName);
    if (!layout.timeField && timeColumn_ == TimeColumn::Required)
        throw InputError(reader_.path(), header_.line(), "missing column time, which is required here");
    if (std::ranges::any_of(kPositionNames, [this](std::string_view name) { return header_.has(name); }))
        layout.positionFields = header_.requiredFields(kPositionNames, "position");
    return layout;
}

RotationColumns PoseCsvParser::findRotationColumns() const
{
    std::optional<RotationColumns> found;
    std::string_view foundName;
    for (const auto& [columns, setName] : kRotationColumnsNames) {
        for (const std::string_view name : rotationColumnNames(columns)) {
            if (!header_.has(name))
                continue;
            if (found && *found != columns)
                throw InputError(reader_.path(), header_.line(),
                                 "columns " + std::string(foundName) + " and " + std::string(name) +
                                     " give the rotation twice; use one column set");
            found = columns;
            foundName = name;
        }
    }
    if (!found)
        throw InputError(reader_.path(), header_.line(), "no rotation columns; give one set of " + rotationColumnSets());
    return *found;
}

PoseRow PoseCsvParser::readRow(const Layout& layout)
{
    header_.checkRowWidth();
    PoseRow row;
    row.line = reader_.lineNumber();
    if (layout.timeField) {
        row.time = header_.number(*layout.timeField, kTimeName);
        times_.check(reader_, row.time);
    }
    const auto names = rotationColumnNames(layout.rotationColumns);
    std::array<double, 9> values{};
    for (std::size_t i = 0; i < names.size(); ++i)
        values[i] = header_.number(layout.rotationFields[i], names[i]);
    try {
        row.pose.orientation =
            rotationFromColumnValues(layout.rotationColumns, std::span(values.data(), names.size()), convention_);
    } catch (const std::invalid_argument& error) {
        throw reader_.errorHere("columns " + joinedNames(names) + ": " + error.what());
    }
    if (layout.rotationColumns == RotationColumns::Euler)
        row.eulerAngles = Eigen::Vector3d(values[0], values[1], values[2]) * (std::numbers::pi / 180.0);
    for (std::size_t i = 0; i < layout.positionFields.size(); ++i)
        row.pose.position[static_cast<Eigen::Index>(i)] = header_.number(layout.positionFields[i], kPositionNames[i]);
    return row;
}

std::string headerLine(const PoseTable& table)
{
    std::vector<std::string_view> names;
    if (table.hasTime)
        names.push_back(kTimeName);
    const auto rotationNames = rotationColumnNames(table.rotationColumns);
    names.insert(names.end(), rotationNames.begin(), rotationNames.end());
    if (table.hasPosition)
        names.insert(names.end(), kPositionNames.begin(), kPositionNames.end());
    return joinedNames(names) + '\n';
}

bool isFinite(const PoseRow& row, const Eigen::RowVectorXd& rotation)
{
    return std::isfinite(row.time) && rotation.allFinite() && row.pose.position.allFinite();
}

std::string rowLine(const PoseTable& table, const PoseRow& row, const Eigen::RowVectorXd& rotation)
{
    std::string line;
    const auto append = [&line](double value) {
        if (!line.empty())
            line += ',';
        line += formatNumber(value);
    };
    if (table.hasTime)
        append(row.time);
    for (const double value : rotation)
        append(value);
    if (table.hasPosition)
        for (const double value : row.pose.position)
            append(value);
    return line + '\n';
}

void writeText(OutputTarget& file, const std::string& text)
{
    file.write(text.data(), static_cast<qint64>(text.size()));
}

std::vector<Eigen::Quaterniond> orientations(std::span<const PoseRow> rows)
{
    std::vector<Eigen::Quaterniond> result;
    result.reserve(rows.size());
    for (const PoseRow& row : rows)
        result.push_back(row.pose.orientation);
    return result;
}

} // namespace

PoseTable readPoseCsv(const QString& path, const EulerConvention& convention, TimeColumn timeColumn)
{
    return PoseCsvParser(path, convention, timeColumn).read();
}

void writePoseCsv(OutputTarget& file, const PoseTable& table, const EulerConvention& convention)
{
    writeText(file, headerLine(table));
    std::optional<Eigen::Vector3d> eulerCarry;
    for (std::size_t start = 0; start < table.rows.size(); start += kRowsPerBlock) {
        const auto block = std::span(table.rows).subspan(start, std::min(kRowsPerBlock, table.rows.size() - start));
        const Eigen::MatrixXd rotations =
            rotationColumnValues(table.rotationColumns, orientations(block), convention, &eulerCarry);
        for (std::size_t i = 0; i < block.size(); ++i) {
            const Eigen::RowVectorXd rotation = rotations.row(static_cast<Eigen::Index>(i));
            // The format cannot hold nan or inf; refuse rather than write a file that cannot be read.
            if (!isFinite(block[i], rotation))
                throw OutputError(file.path(),
                                  "row " + std::to_string(start + i + 1) + " holds a value that is not finite");
            writeText(file, rowLine(table, block[i], rotation));
        }
    }
}

void writePoseCsv(const QString& path, const PoseTable& table, const EulerConvention& convention)
{
    OutputTarget file(path);
    file.open();
    writePoseCsv(file, table, convention);
    file.commit();
}

} // namespace gyre::io
