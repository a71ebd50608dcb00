// gyre-cli subdivide: a sequence of poses smoothed by polyscrew subdivision.

#include "cli/command_line.h"
#include "cli/verbs.h"
#include "core/key_time_map.h"
#include "core/subdivision.h"
#include "io/pose_csv.h"

#include <array>
#include <cmath>

namespace gyre::cli {

namespace {

QList<QCommandLineOption> subdivideOptions()
{
    return QList<QCommandLineOption>{QCommandLineOption(QStringLiteral("scheme"), {}, QStringLiteral("scheme")),
                                     QCommandLineOption(QStringLiteral("levels"), {}, QStringLiteral("levels")),
                                     QCommandLineOption(QStringLiteral("open")),
                                     QCommandLineOption(QStringLiteral("decoupled"))} +
           eulerOptions();
}

SubdivisionSettings settings(const VerbCommandLine& commandLine)
{
    return {commandLine.choice(QStringLiteral("scheme"), kSubdivisionSchemeNames),
            commandLine.nonNegativeInteger(QStringLiteral("levels")),
            !commandLine.isSet(QStringLiteral("open")), commandLine.isSet(QStringLiteral("decoupled"))};
}

void checkOutputSize(std::size_t poses, const SubdivisionSettings& settings, const VerbCommandLine& commandLine)
{
    const auto count = subdividedPoseCount(poses, settings.levels, settings.cyclic);
    if (!count || *count > io::kMaxPoseRows)
        throw commandLine.error("--levels " + std::to_string(settings.levels) + " would turn " +
                                std::to_string(poses) + " poses into more than " + std::to_string(io::kMaxPoseRows));
}

// Output pose i·2^L + j is at parameter i + j/2^L of the polyscrew, played at the time the track's
// time map gives it (KeyTimeMap): the times at which the app plays these poses.
std::vector<double> subdividedTimes(const io::PoseTable& table, const SubdivisionSettings& settings)
{
    std::vector<double> keyTimes;
    for (const io::PoseRow& row : table.rows)
        keyTimes.push_back(row.time);
    const KeyTimeMap timeMap(keyTimes, settings.cyclic);
    const double perSpan = std::ldexp(1.0, settings.levels);
    const double spans = static_cast<double>(settings.cyclic ? keyTimes.size() : keyTimes.size() - 1);
    std::vector<double> times;
    for (double k = 0; k < spans * perSpan; ++k)
        times.push_back(timeMap.timeAt(k / perSpan));
    if (!settings.cyclic)
        times.push_back(keyTimes.back());
    return times;
}

} // namespace

void runSubdivide(const QStringList& arguments)
{
    const VerbCommandLine commandLine(QStringLiteral("subdivide"), arguments, subdivideOptions());
    const SubdivisionSettings chosen = settings(commandLine);
    const io::PoseTable input = io::readPoseCsv(commandLine.inputPath(), commandLine.eulerConvention());
    if (input.rows.size() < 2)
        throw InputError(commandLine.inputPath(), input.rows.back().line, "subdivide needs at least two poses");
    checkOutputSize(input.rows.size(), chosen, commandLine);
    std::vector<Pose> controlPoses;
    for (const io::PoseRow& row : input.rows)
        controlPoses.push_back(row.pose);
    const std::vector<Pose> poses = subdividePolyscrew(controlPoses, chosen);
    const std::vector<double> times =
        input.hasTime ? subdividedTimes(input, chosen) : std::vector<double>(poses.size());
    io::PoseTable output{io::RotationColumns::Quaternion, input.hasTime, true, {}};
    output.rows.reserve(poses.size());
    for (std::size_t k = 0; k < poses.size(); ++k)
        output.rows.push_back({times[k], poses[k], 0});
    io::writePoseCsv(commandLine.outputPath(), output);
}

} // namespace gyre::cli
