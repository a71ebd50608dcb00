// gyre-cli convert: the same poses with their rotation in another column set.

#include "cli/command_line.h"
#include "cli/verbs.h"
#include "io/pose_csv.h"

#include <cstdio>
#include <numbers>

namespace gyre::cli {

namespace {

// Within this of gimbal lock the Euler angles e1 and e3 are ill-conditioned, and the user is told.
constexpr double kGimbalWarningDegrees = 1.0;
// Enough warnings to see where the trouble is without burying the terminal.
constexpr int kMaxGimbalWarnings = 10;

QList<QCommandLineOption> convertOptions()
{
    return QList<QCommandLineOption>{QCommandLineOption(QStringLiteral("to"), {}, QStringLiteral("set"))} +
           eulerOptions();
}

// An angle for people to read, not to read back: "0.03°".
std::string roundedDegrees(double degrees)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.2f°", degrees);
    return text;
}

// Gimbal lock is shown, not hidden: each row near it is named on standard error.
void warnNearGimbalLock(const QString& inputPath, const io::PoseTable& table, const EulerConvention& convention)
{
    int nearRows = 0;
    for (const io::PoseRow& row : table.rows) {
        const double degrees =
            eulerAnglesFromQuaternion(row.pose.orientation, convention).gimbalLockDistance * 180.0 / std::numbers::pi;
        if (!(degrees < kGimbalWarningDegrees))
            continue;
        if (++nearRows <= kMaxGimbalWarnings)
            warn(inputPath.toStdString() + ":" + std::to_string(row.line) + ": rotation " + roundedDegrees(degrees) +
                 " from gimbal lock in " + convention.name() +
                 "; only the sum or difference of e1 and e3 is well defined there");
    }
    if (nearRows > kMaxGimbalWarnings)
        warn(std::to_string(nearRows - kMaxGimbalWarnings) + " more rows of " + inputPath.toStdString() +
             " are within " + roundedDegrees(kGimbalWarningDegrees) + " of gimbal lock");
}

} // namespace

void runConvert(const QStringList& arguments)
{
    // The same poses in another column set: the file may be converted in place.
    const VerbCommandLine commandLine(QStringLiteral("convert"), arguments, convertOptions(),
                                      OutputFile::MayReplaceInput);
    const io::RotationColumns target = commandLine.choice(QStringLiteral("to"), io::kRotationColumnsNames);
    const EulerConvention convention = commandLine.eulerConvention();
    io::PoseTable table = io::readPoseCsv(commandLine.inputPath(), convention);
    table.rotationColumns = target;
    if (target == io::RotationColumns::Euler)
        warnNearGimbalLock(commandLine.inputPath(), table, convention);
    io::writePoseCsv(commandLine.outputPath(), table, convention);
}

} // namespace gyre::cli
