// gyre-cli subdivide: a sequence of poses smoothed by polyscrew subdivision.

#include "cli/command_line.h"
#include "cli/verbs.h"
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
    if (!count || *count > kMaxPoseRows)
        throw commandLine.error("--levels " + std::to_string(settings.levels) + " would turn " +
                                std::to_string(poses) + " poses into more than " + std::to_string(kMaxPoseRows));
}

// Output pose i·2^L + j sits at fraction j/2^L of input span i. The span that closes a cycle has no
// time of its own and lasts the mean of the others.
std::vector<double> subdividedTimes(const PoseTable& table, const SubdivisionSettings& settings)
{
    const double first = table.rows.front().time;
    const double last = table.rows.back().time;
    std::vector<double> spanEnds;
    for (const PoseRow& row : table.rows)
        spanEnds.push_back(row.time);
    if (settings.cyclic)
        spanEnds.push_back(last + (last - first) / static_cast<double>(table.rows.size() - 1));
    const double perSpan = std::ldexp(1.0, settings.levels);
    std::vector<double> times;
    for (std::size_t i = 0; i + 1 < spanEnds.size(); ++i)
        for (double j = 0; j < perSpan; ++j)
            times.push_back(spanEnds[i] + (spanEnds[i + 1] - spanEnds[i]) * (j / perSpan));
    if (!settings.cyclic)
        times.push_back(last);
    return times;
}

} // namespace

void runSubdivide(const QStringList& arguments)
{
    const VerbCommandLine commandLine(QStringLiteral("subdivide"), arguments, subdivideOptions());
    const SubdivisionSettings chosen = settings(commandLine);
    const PoseTable input = readPoseCsv(commandLine.inputPath(), commandLine.eulerConvention());
    if (input.rows.size() < 2)
        throw InputError(commandLine.inputPath(), input.rows.back().line, "subdivide needs at least two poses");
    checkOutputSize(input.rows.size(), chosen, commandLine);
    std::vector<Pose> controlPoses;
    for (const PoseRow& row : input.rows)
        controlPoses.push_back(row.pose);
    const std::vector<Pose> poses = subdividePolyscrew(controlPoses, chosen);
    const std::vector<double> times =
        input.hasTime ? subdividedTimes(input, chosen) : std::vector<double>(poses.size());
    PoseTable output{RotationColumns::Quaternion, input.hasTime, true, {}};
    output.rows.reserve(poses.size());
    for (std::size_t k = 0; k < poses.size(); ++k)
        output.rows.push_back({times[k], poses[k], 0});
    writePoseCsv(commandLine.outputPath(), output);
}

} // namespace gyre::cli
