// gyre-cli interpolate: a motion through timed keys, sampled at a frame rate and at every key.

#include "cli/command_line.h"
#include "cli/verbs.h"
#include "core/number_text.h"
#include "core/orientation_curves.h"
#include "core/number_text.h"
#include "io/pose_csv.h"
#include "model/track_evaluation.h"

#include <string>

namespace gyre::cli {

namespace {

QList<QCommandLineOption> interpolateOptions()
{
    return QList<QCommandLineOption>{QCommandLineOption(QStringLiteral("method"), {}, QStringLiteral("method")),
                                     QCommandLineOption(QStringLiteral("fps"), {}, QStringLiteral("rate"))} +
           eulerOptions();
}

// The keys as a track; screw is the plain polyscrew through them (no subdivision, open).
model::MotionTrack trackOf(const io::PoseTable& keys, InterpolationMethod method)
{
    model::MotionTrack track;
    track.interpolation = method;
    track.subdivision.levels = 0;
    track.subdivision.cyclic = false;
    track.keys.reserve(keys.rows.size());
    for (const io::PoseRow& row : keys.rows)
        track.keys.push_back({row.time, row.pose, true});
    return track;
}

} // namespace

void runInterpolate(const QStringList& arguments)
{
    const VerbCommandLine commandLine(QStringLiteral("interpolate"), arguments, interpolateOptions());
    const InterpolationMethod method = commandLine.choice(QStringLiteral("method"), kInterpolationMethodNames);
    const double fps = commandLine.frameRate(QStringLiteral("fps"));
    const EulerConvention convention = commandLine.eulerConvention();
    const io::PoseTable keys = io::readPoseCsv(commandLine.inputPath(), convention, io::TimeColumn::Required);
    if (keys.rows.size() < 2)
        throw InputError(commandLine.inputPath(), keys.rows.back().line, "interpolate needs at least two keys");
    const model::MotionTrack track = trackOf(keys, method);
    const model::BakeRange range = checkedOutputRange({track.keys.front().time, track.keys.back().time, fps},
                                                      track.keys.size(), commandLine);
    io::PoseTable frames{io::RotationColumns::Quaternion, true, true, {}};
    for (const model::TimedPose& sample : model::bakeTrack(track, range, convention))
        frames.rows.push_back({sample.time, sample.pose, 0});
    io::writePoseCsv(commandLine.outputPath(), frames);
}

} // namespace gyre::cli
