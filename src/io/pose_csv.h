#pragma once
// The pose CSV format (docs/pose-csv.md): a header row naming the columns, then one pose per row.
//
//   time,qw,qx,qy,qz,x,y,z
//   0,1,0,0,0,0,0,0
//   0.5,0.7071067811865476,0,0.7071067811865476,0,1,0,0
//
// The rotation is given by exactly one column set (rotation_columns.h); `time` and the position
// columns x,y,z are optional. Columns may come in any order. Lines whose first non-blank character
// is '#' are comments; blank lines are skipped. Numbers are written so that they read back exactly.

#include "core/euler_angles.h"
#include "core/pose.h"
#include "io/rotation_columns.h"
#include "model/input_error.h"

#include <QString>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace gyre {
class OutputTarget;
}

namespace gyre::io {

struct PoseRow {
    double time = 0.0;     // seconds; 0 when the table has no time column
    Pose pose;             // position zero when the table has no position columns
    std::int64_t line = 0; // the 1-based line of the file it was read from; 0 for a row made in memory
    // The angles as read from Euler columns, radians (720° stays 720°); none for the other column sets.
    std::optional<Eigen::Vector3d> eulerAngles = std::nullopt;
};

struct PoseTable {
    RotationColumns rotationColumns = RotationColumns::Quaternion;
    bool hasTime = false;
    bool hasPosition = false;
    std::vector<PoseRow> rows;
};

// The most poses a verb may make: 2²⁴, about 1.5 GB of poses in memory and a few GB of text. A file
// read may hold CsvLineReader::kRowBudget (2²²) poses at most.
inline constexpr std::size_t kMaxPoseRows = std::size_t{1} << 24;

enum class TimeColumn { Optional, Required };

// Reads a pose file. Euler angle columns are read in `convention`. Where there is a time column,
// times must strictly increase. Throws InputError, naming the file, the line and the column, for
// anything the format does not allow, including an empty or header-only file and one with more than
// CsvLineReader::kRowBudget poses. The file is read a line at a time, and a regular file is counted
// first, so memory holds the poses and no more.
PoseTable readPoseCsv(const QString& path, const EulerConvention& convention,
                      TimeColumn timeColumn = TimeColumn::Optional);

// Writes the table with the header time (if hasTime), the rotationColumns set, x,y,z (if
// hasPosition); Euler angles in `convention`. Goes through an OutputTarget: a regular file appears
// only once complete, so on any error (OutputError; a value that is not finite is one) a file
// already at `path` keeps its contents and none is created; a FIFO or a device is written in place,
// and "-" is standard output.
void writePoseCsv(const QString& path, const PoseTable& table, const EulerConvention& convention = {});
// The same into a target the caller opened and commits, for a verb that writes several files and
// commits them together.
void writePoseCsv(OutputTarget& file, const PoseTable& table, const EulerConvention& convention = {});

} // namespace gyre::io
