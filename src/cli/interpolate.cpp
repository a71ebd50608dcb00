// gyre-cli interpolate: a motion through timed keys, sampled at a frame rate and at every key.

#include "cli/command_line.h"
#include "cli/verbs.h"
#include "core/number_text.h"
#include "core/orientation_curves.h"
#include "core/torque_free.h"
#include "fit/ballistic_flight.h"
#include "io/pose_csv.h"
#include "model/object_mass.h"
#include "model/track_evaluation.h"
#include "model/value_checks.h"

#include <optional>
#include <stdexcept>
#include <string>

namespace gyre::cli {

namespace {

constexpr std::string_view kBallistic = "ballistic";

QList<QCommandLineOption> interpolateOptions()
{
    return QList<QCommandLineOption>{QCommandLineOption(QStringLiteral("method"), {}, QStringLiteral("method")),
                                     QCommandLineOption(QStringLiteral("fps"), {}, QStringLiteral("rate")),
                                     QCommandLineOption(QStringLiteral("inertia"), {}, QStringLiteral("tensor")),
                                     QCommandLineOption(QStringLiteral("solution"), {}, QStringLiteral("index")),
                                     QCommandLineOption(QStringLiteral("gravity"), {}, QStringLiteral("g")),
                                     QCommandLineOption(QStringLiteral("up"), {}, QStringLiteral("vector"))} +
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

// --inertia Ixx,Iyy,Izz[,Ixy,Ixz,Iyz]: the body-frame tensor, symmetric positive definite.
Eigen::Matrix3d inertiaOption(const VerbCommandLine& commandLine)
{
    const std::vector<double> n = commandLine.numberList(QStringLiteral("inertia"));
    if (n.size() != 3 && n.size() != 6)
        throw commandLine.error("--inertia: give 3 numbers (Ixx,Iyy,Izz) or 6 (Ixx,Iyy,Izz,Ixy,Ixz,Iyz), not " +
                                std::to_string(n.size()));
    InertiaComponents components{};
    std::copy(n.begin(), n.end(), components.begin()); // the products of inertia 0 when three are given
    const Eigen::Matrix3d inertia = inertiaTensor(components);
    try {
        model::checkMassProperties({1.0, Eigen::Vector3d::Zero(), inertia});
    } catch (const std::invalid_argument& problem) {
        throw commandLine.error(std::string("--inertia: ") + problem.what());
    }
    return inertia;
}

// --gravity G (default 9.81 m/s², ≥ 0) and --up X,Y,Z (default 0,0,1: Gyre's world is Z-up).
fit::FlightBody flightBody(const VerbCommandLine& commandLine)
{
    fit::FlightBody body;
    body.inertia = inertiaOption(commandLine);
    if (commandLine.isSet(QStringLiteral("gravity"))) {
        body.gravity = commandLine.number(QStringLiteral("gravity"));
        if (body.gravity < 0.0)
            throw commandLine.error("--gravity: " + formatNumber(body.gravity) + " is negative");
    }
    if (commandLine.isSet(QStringLiteral("up"))) {
        const std::vector<double> up = commandLine.numberList(QStringLiteral("up"));
        if (up.size() != 3 || Eigen::Vector3d(up[0], up[1], up[2]).norm() == 0.0)
            throw commandLine.error("--up: give a non-zero vector as three numbers X,Y,Z");
        body.up = Eigen::Vector3d(up[0], up[1], up[2]).normalized();
    }
    return body;
}

// The ballistic motion's samples: every span a free flight (fit/ballistic_flight.h), solution K of each span
// by energy when --solution is given, else the one nearest the hermite motion through the keys.
std::vector<model::TimedPose> ballisticSamples(const io::PoseTable& keys, const model::BakeRange& range,
                                               const VerbCommandLine& commandLine)
{
    try {
        model::checkPoseBudget(keys.rows.size(), InterpolationMethod::Ballistic, {});
    } catch (const std::invalid_argument& problem) {
        throw InputError(commandLine.inputPath(), problem.what());
    }
    const fit::FlightBody body = flightBody(commandLine);
    std::vector<fit::FlightKey> flightKeys;
    std::vector<double> times;
    for (const io::PoseRow& row : keys.rows) {
        flightKeys.push_back({row.time, row.pose});
        times.push_back(row.time);
    }
    std::optional<std::size_t> solution;
    if (commandLine.isSet(QStringLiteral("solution")))
        solution = static_cast<std::size_t>(commandLine.nonNegativeInteger(QStringLiteral("solution")));
    std::optional<fit::BallisticFlight> flight;
    try {
        flight.emplace(flightKeys, body, std::vector<std::optional<std::size_t>>(flightKeys.size() - 1, solution));
    } catch (const std::invalid_argument& problem) {
        throw InputError(commandLine.inputPath(), problem.what());
    }
    for (std::size_t span = 0; span < flight->spans().size(); ++span)
        if (solution && *solution >= flight->spans()[span].solutions.size())
            throw commandLine.error("--solution " + std::to_string(*solution) + ": the flight from key " +
                                    std::to_string(span + 1) + " has " +
                                    std::to_string(flight->spans()[span].solutions.size()) +
                                    " solutions, numbered from 0");
    std::vector<model::TimedPose> samples;
    for (const double time : model::bakeTimes(times, range))
        samples.push_back({time, model::unitSample(flight->at(time), time)});
    return samples;
}

} // namespace

void runInterpolate(const QStringList& arguments)
{
    const VerbCommandLine commandLine(QStringLiteral("interpolate"), arguments, interpolateOptions());
    const std::string methodName = commandLine.requiredValue(QStringLiteral("method")).toStdString();
    const bool ballistic = methodName == kBallistic;
    const std::optional<InterpolationMethod> curve = valueNamed(kInterpolationMethodNames, methodName);
    if (!ballistic && !curve) {
        std::vector<std::string_view> names;
        for (const auto& entry : kInterpolationMethodNames)
            names.push_back(entry.second);
        throw commandLine.error("--method: unknown value '" + methodName + "'; expected " + alternatives(names));
    }
    if (ballistic && !commandLine.isSet(QStringLiteral("inertia")))
        throw commandLine.error("--method ballistic needs --inertia");
    for (const char* option : {"inertia", "solution", "gravity", "up"})
        if (!ballistic && commandLine.isSet(QLatin1String(option)))
            throw commandLine.error("--" + std::string(option) + " is for --method ballistic alone");
    const InterpolationMethod method = curve.value_or(InterpolationMethod::Hermite);
    const double fps = commandLine.frameRate(QStringLiteral("fps"));
    const EulerConvention convention = commandLine.eulerConvention();
    const io::PoseTable keys = io::readPoseCsv(commandLine.inputPath(), convention, io::TimeColumn::Required);
    if (keys.rows.size() < 2)
        throw InputError(commandLine.inputPath(), keys.rows.back().line, "interpolate needs at least two keys");
    const model::MotionTrack track = trackOf(keys, method);
    const model::BakeRange range = checkedOutputRange({track.keys.front().time, track.keys.back().time, fps},
                                                      track.keys.size(), commandLine);
    io::PoseTable frames{io::RotationColumns::Quaternion, true, true, {}};
    for (const model::TimedPose& sample :
         ballistic ? ballisticSamples(keys, range, commandLine) : model::bakeTrack(track, range, convention))
        frames.rows.push_back({sample.time, sample.pose, 0});
    io::writePoseCsv(commandLine.outputPath(), frames);
}

} // namespace gyre::cli
