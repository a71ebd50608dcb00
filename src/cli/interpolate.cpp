// gyre-cli interpolate: a motion through timed keys, sampled at a frame rate and at every key.

#include "cli/command_line.h"
#include "cli/verbs.h"
#include "core/number_text.h"
#include "core/orientation_curves.h"
#include "core/polyscrew.h"
#include "core/position_curve.h"
#include "core/timed_keys.h"
#include "io/pose_csv.h"

#include <algorithm>
#include <cmath>

namespace gyre::cli {

namespace {

// A frame that falls this close to a key is the key's sample: the key time is written, not a
// near-duplicate a rounding error away.
constexpr double kKeyMergeSeconds = 1e-9;

QList<QCommandLineOption> interpolateOptions()
{
    return QList<QCommandLineOption>{QCommandLineOption(QStringLiteral("method"), {}, QStringLiteral("method")),
                                     QCommandLineOption(QStringLiteral("fps"), {}, QStringLiteral("rate"))} +
           eulerOptions();
}

// t0 + k/fps up to the last key, merged with the key times; a frame within kKeyMergeSeconds of a
// key gives way to it.
std::vector<double> sampleTimes(const std::vector<double>& keyTimes, double fps, const VerbCommandLine& commandLine)
{
    const double first = keyTimes.front();
    const double last = keyTimes.back();
    // One frame more than the product promises, in case rounding put it just below a whole number;
    // frames past the last key are dropped below.
    const double frames = std::floor((last - first) * fps) + 2.0;
    if (!(frames + static_cast<double>(keyTimes.size()) <= static_cast<double>(kMaxPoseRows)))
        throw commandLine.error("--fps " + formatNumber(fps) + " over " + formatNumber(last - first) +
                                " s of keys gives more than " + std::to_string(kMaxPoseRows) + " samples");
    std::vector<double> times;
    std::size_t key = 0;
    for (std::size_t k = 0; k < static_cast<std::size_t>(frames); ++k) {
        const double time = first + static_cast<double>(k) / fps;
        while (key < keyTimes.size() && keyTimes[key] < time - kKeyMergeSeconds)
            times.push_back(keyTimes[key++]);
        const bool atKey = key < keyTimes.size() && std::abs(keyTimes[key] - time) <= kKeyMergeSeconds;
        if (!atKey && time <= last)
            times.push_back(time);
    }
    times.insert(times.end(), keyTimes.begin() + static_cast<std::ptrdiff_t>(key), keyTimes.end());
    return times;
}

// Where a time falls among the keys: in the span from key `span` to key `span + 1`, at fraction u.
struct SpanPosition {
    std::size_t span = 0;
    double u = 0.0;
};

SpanPosition spanPosition(const PoseTable& keys, double time)
{
    const std::size_t span = segmentAt(keys.rows, time);
    const double start = keys.rows[span].time;
    return {span, (time - start) / (keys.rows[span + 1].time - start)};
}

std::vector<Pose> curvePoses(InterpolationMethod method, const PoseTable& keys,
                             const std::vector<double>& times, const EulerConvention& convention)
{
    std::vector<OrientationKey> orientationKeys;
    std::vector<PositionKey> positionKeys;
    for (const PoseRow& row : keys.rows) {
        orientationKeys.push_back({row.time, row.pose.orientation});
        positionKeys.push_back({row.time, row.pose.position});
    }
    const auto curve = makeOrientationCurve(method, std::move(orientationKeys), convention);
    const bool cubic = method == InterpolationMethod::Squad || method == InterpolationMethod::Hermite;
    const PositionCurve positions(std::move(positionKeys), cubic ? PositionCurve::Shape::Cubic : PositionCurve::Shape::Linear);
    std::vector<Pose> poses;
    poses.reserve(times.size());
    for (const double time : times)
        poses.push_back({curve->sample(time).value, positions.at(time)});
    return poses;
}

// The polyscrew through the keys, its parameter mapped piecewise linearly from the key times so
// that key i sits at parameter i.
std::vector<Pose> screwPoses(const PoseTable& keys, const std::vector<double>& times)
{
    std::vector<Pose> keyPoses;
    for (const PoseRow& row : keys.rows)
        keyPoses.push_back(row.pose);
    const Polyscrew motion(std::move(keyPoses), false);
    std::vector<Pose> poses;
    poses.reserve(times.size());
    for (const double time : times) {
        const auto [span, u] = spanPosition(keys, time);
        poses.push_back(motion.at(static_cast<double>(span) + u));
    }
    return poses;
}

std::vector<double> timesOf(const PoseTable& table)
{
    std::vector<double> times;
    for (const PoseRow& row : table.rows)
        times.push_back(row.time);
    return times;
}

} // namespace

void runInterpolate(const QStringList& arguments)
{
    const VerbCommandLine commandLine(QStringLiteral("interpolate"), arguments, interpolateOptions());
    const InterpolationMethod method = commandLine.choice(QStringLiteral("method"), kInterpolationMethodNames);
    const double fps = commandLine.positiveNumber(QStringLiteral("fps"));
    const EulerConvention convention = commandLine.eulerConvention();
    const PoseTable keys = readPoseCsv(commandLine.inputPath(), convention, TimeColumn::Required);
    if (keys.rows.size() < 2)
        throw InputError(commandLine.inputPath(), keys.rows.back().line, "interpolate needs at least two keys");
    const std::vector<double> keyTimes = timesOf(keys);
    const std::vector<double> times = sampleTimes(keyTimes, fps, commandLine);
    const std::vector<Pose> poses = method == InterpolationMethod::Screw
                                        ? screwPoses(keys, times)
                                        : curvePoses(method, keys, times, convention);
    PoseTable frames{RotationColumns::Quaternion, true, true, {}};
    frames.rows.reserve(times.size());
    for (std::size_t k = 0; k < times.size(); ++k)
        frames.rows.push_back({times[k], poses[k], 0});
    writePoseCsv(commandLine.outputPath(), frames);
}

} // namespace gyre::cli
