#include "io/pose_csv.h"

#include "core/number_text.h"
#include "io/csv_line_reader.h"

#include <QSaveFile>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace gyre {

namespace {

constexpr std::string_view kTimeName = "time";
constexpr std::array<std::string_view, 3> kPositionNames{"x", "y", "z"};

std::string joined(std::span<const std::string_view> names)
{
    std::string text;
    for (const std::string_view name : names) {
        if (!text.empty())
            text += ',';
        text += name;
    }
    return text;
}

// "qw,qx,qy,qz | m00,…,m22 | …": the rotation column sets, for messages.
std::string rotationColumnSets()
{
    std::string text;
    for (const auto& [columns, setName] : kRotationColumnsNames) {
        if (!text.empty())
            text += " | ";
        text += joined(rotationColumnNames(columns));
    }
    return text;
}

std::string knownColumnNames()
{
    return std::string(kTimeName) + " | " + rotationColumnSets() + " | " + joined(kPositionNames);
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
    std::size_t fieldCount = 0;
    std::int64_t headerLine = 0;
};

class PoseCsvParser {
public:
    PoseCsvParser(const QString& path, const EulerConvention& convention, TimeColumn timeColumn)
        : reader_(path), convention_(convention), timeColumn_(timeColumn)
    {
    }

    PoseTable read();

private:
    using FieldIndex = std::map<std::string_view, std::size_t>;

    Layout readHeader();
    FieldIndex indexHeaderFields() const;
    RotationColumns findRotationColumns(const FieldIndex& fields) const;
    std::vector<std::size_t> requiredFields(const FieldIndex& fields, std::span<const std::string_view> names,
                                            std::string_view setName) const;
    PoseRow readRow(const Layout& layout);
    double number(std::size_t field, std::string_view column) const;
    void checkTimeIncreases(double time);

    CsvLineReader reader_;
    EulerConvention convention_;
    TimeColumn timeColumn_;
    std::optional<double> previousTime_;
    std::int64_t previousTimeLine_ = 0;
};

PoseTable PoseCsvParser::read()
{
    const Layout layout = readHeader();
    PoseTable table{layout.rotationColumns, layout.timeField.has_value(), !layout.positionFields.empty(), {}};
    while (reader_.nextRecord()) {
        if (table.rows.size() == kMaxPoseRows)
            throw reader_.errorHere("more than " + std::to_string(kMaxPoseRows) + " poses");
        table.rows.push_back(readRow(layout));
    }
    if (table.rows.empty())
        throw reader_.errorHere("no poses after the header on line " + std::to_string(layout.headerLine));
    return table;
}

Layout PoseCsvParser::readHeader()
{
    if (!reader_.nextRecord())
        throw InputError(reader_.path(), std::max<std::int64_t>(reader_.lineNumber(), 1),
                         "no header row: the file is empty or holds only comments");
    const FieldIndex fields = indexHeaderFields();
    Layout layout;
    layout.headerLine = reader_.lineNumber();
    layout.fieldCount = reader_.fields().size();
    layout.rotationColumns = findRotationColumns(fields);
    const auto setName = rotationColumnsName(layout.rotationColumns);
    layout.rotationFields = requiredFields(fields, rotationColumnNames(layout.rotationColumns), setName);
    if (const auto time = fields.find(kTimeName); time != fields.end())
        layout.timeField = time->second;
    else if (timeColumn_ == TimeColumn::Required)
        throw reader_.errorHere("missing column time, which is required here");
    if (std::ranges::any_of(kPositionNames, [&fields](std::string_view name) { return fields.contains(name); }))
        layout.positionFields = requiredFields(fields, kPositionNames, "position");
    return layout;
}

PoseCsvParser::FieldIndex PoseCsvParser::indexHeaderFields() const
{
    FieldIndex fields;
    const auto& names = reader_.fields();
    for (std::size_t i = 0; i < names.size(); ++i) {
        const std::string_view name = names[i];
        if (name.empty())
            throw reader_.errorHere("header field " + std::to_string(i + 1) + " is empty");
        if (!isKnownColumn(name))
            throw reader_.errorHere("unknown column '" + std::string(name) + "'; the columns are " +
                                    knownColumnNames());
        if (!fields.emplace(name, i).second)
            throw reader_.errorHere("column " + std::string(name) + " appears twice");
    }
    return fields;
}

RotationColumns PoseCsvParser::findRotationColumns(const FieldIndex& fields) const
{
    std::optional<RotationColumns> found;
    std::string_view foundName;
    for (const auto& [columns, setName] : kRotationColumnsNames) {
        for (const std::string_view name : rotationColumnNames(columns)) {
            if (!fields.contains(name))
                continue;
            if (found && *found != columns)
                throw reader_.errorHere("columns " + std::string(foundName) + " and " + std::string(name) +
                                        " give the rotation twice; use one column set");
            found = columns;
            foundName = name;
        }
    }
    if (!found)
        throw reader_.errorHere("no rotation columns; give one set of " + rotationColumnSets());
    return *found;
}

std::vector<std::size_t> PoseCsvParser::requiredFields(const FieldIndex& fields,
                                                        std::span<const std::string_view> names,
                                                        std::string_view setName) const
{
    std::vector<std::size_t> indices;
    for (const std::string_view name : names) {
        const auto field = fields.find(name);
        if (field == fields.end())
            throw reader_.errorHere("missing column " + std::string(name) + " (" + std::string(setName) +
                                    " needs " + joined(names) + ")");
        indices.push_back(field->second);
    }
    return indices;
}

PoseRow PoseCsvParser::readRow(const Layout& layout)
{
    const std::size_t fieldCount = reader_.fields().size();
    if (fieldCount != layout.fieldCount)
        throw reader_.errorHere(std::to_string(fieldCount) + " fields, but the header on line " +
                                std::to_string(layout.headerLine) + " has " + std::to_string(layout.fieldCount));
    PoseRow row;
    row.line = reader_.lineNumber();
    if (layout.timeField) {
        row.time = number(*layout.timeField, kTimeName);
        checkTimeIncreases(row.time);
    }
    const auto names = rotationColumnNames(layout.rotationColumns);
    std::array<double, 9> values{};
    for (std::size_t i = 0; i < names.size(); ++i)
        values[i] = number(layout.rotationFields[i], names[i]);
    try {
        row.pose.orientation =
            rotationFromColumnValues(layout.rotationColumns, std::span(values.data(), names.size()), convention_);
    } catch (const std::invalid_argument& error) {
        throw reader_.errorHere("columns " + joined(names) + ": " + error.what());
    }
    for (std::size_t i = 0; i < layout.positionFields.size(); ++i)
        row.pose.position[static_cast<Eigen::Index>(i)] = number(layout.positionFields[i], kPositionNames[i]);
    return row;
}

double PoseCsvParser::number(std::size_t field, std::string_view column) const
{
    try {
        return parseFiniteNumber(reader_.fields()[field]);
    } catch (const std::invalid_argument& error) {
        throw reader_.errorHere("column " + std::string(column) + ": " + error.what());
    }
}

void PoseCsvParser::checkTimeIncreases(double time)
{
    if (previousTime_ && !(time > *previousTime_))
        throw reader_.errorHere("column time: " + formatNumber(time) + " does not come after " +
                                formatNumber(*previousTime_) + " on line " + std::to_string(previousTimeLine_) +
                                "; times must strictly increase");
    previousTime_ = time;
    previousTimeLine_ = reader_.lineNumber();
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
    return joined(names) + '\n';
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

void writeText(QSaveFile& file, const std::string& text)
{
    if (file.write(text.data(), static_cast<qint64>(text.size())) != static_cast<qint64>(text.size()))
        throw OutputError(file.fileName(), "cannot write: " + file.errorString().toStdString());
}

std::vector<Eigen::Quaterniond> orientations(const PoseTable& table)
{
    std::vector<Eigen::Quaterniond> result;
    result.reserve(table.rows.size());
    for (const PoseRow& row : table.rows)
        result.push_back(row.pose.orientation);
    return result;
}

} // namespace

PoseTable readPoseCsv(const QString& path, const EulerConvention& convention, TimeColumn timeColumn)
{
    return PoseCsvParser(path, convention, timeColumn).read();
}

void writePoseCsv(const QString& path, const PoseTable& table, const EulerConvention& convention)
{
    const Eigen::MatrixXd rotations = rotationColumnValues(table.rotationColumns, orientations(table), convention);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        throw OutputError(path, "cannot write: " + file.errorString().toStdString());
    writeText(file, headerLine(table));
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
        const Eigen::RowVectorXd rotation = rotations.row(static_cast<Eigen::Index>(i));
        // The format cannot hold nan or inf; refuse rather than write a file that cannot be read.
        if (!isFinite(table.rows[i], rotation))
            throw OutputError(path, "row " + std::to_string(i + 1) + " holds a value that is not finite");
        writeText(file, rowLine(table, table.rows[i], rotation));
    }
    if (!file.commit())
        throw OutputError(path, "cannot write: " + file.errorString().toStdString());
}

} // namespace gyre
