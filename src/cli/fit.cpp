// gyre-cli fit: the rotation through keys bent to match a target angular velocity (src/fit).

#include "cli/command_line.h"
#include "cli/verbs.h"
#include "core/position_curve.h"
#include "fit/angular_velocity_fit.h"
#include "io/number_csv.h"
#include "core/number_text.h"
#include "io/pose_csv.h"
#include "model/output_target.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <array>
#include <cmath>
#include <set>
#include <string_view>

namespace gyre::cli {

namespace {

using fit::AngularVelocityTarget;
using fit::FitKey;
using fit::FitResult;
using fit::FitSettings;
using fit::TimedScalar;
using fit::TimedVector;

const QString kOmega = QStringLiteral("omega");
const QString kDirection = QStringLiteral("direction");
const QString kMagnitude = QStringLiteral("magnitude");
const QString kPattern = QStringLiteral("pattern");
const QString kRepeat = QStringLiteral("repeat");
const QString kFps = QStringLiteral("fps");
const QString kAlpha = QStringLiteral("alpha");
const QString kBeta = QStringLiteral("beta");
const QString kDelta = QStringLiteral("delta");
const QString kFragment = QStringLiteral("fragment");
const QString kFree = QStringLiteral("free");
const QString kWindow = QStringLiteral("window");
const QString kReport = QStringLiteral("report");

// How far from unit length a direction may be before it is refused as off the sphere.
constexpr double kUnitTolerance = 0.01;

constexpr std::array<std::string_view, 1> kTime{"time"};
constexpr std::array<std::string_view, 4> kOmegaColumns{"time", "wx", "wy", "wz"};
constexpr std::array<std::string_view, 3> kDirectionColumns{"x", "y", "z"};
constexpr std::array<std::string_view, 2> kMagnitudeColumns{"time", "magnitude"};
constexpr std::array<std::string_view, 2> kPatternColumns{"x", "y"};

QList<QCommandLineOption> fitOptions()
{
    QList<QCommandLineOption> options;
    for (const QString& name : {kOmega, kDirection, kMagnitude, kPattern, kRepeat, kFps, kAlpha, kBeta, kDelta,
                                kFragment, kFree, kWindow, kReport})
        options.append(QCommandLineOption(name, {}, QStringLiteral("value")));
    return options + eulerOptions();
}

Eigen::Vector3d vectorAt(const io::NumberTable& table, std::size_t row, std::span<const std::string_view> columns)
{
    return {table.value(row, columns[0]), table.value(row, columns[1]), table.value(row, columns[2])};
}

AngularVelocityTarget omegaTarget(const QString& path)
{
    const io::NumberTable table = io::readNumberCsv(path, {kOmegaColumns, {}, "time"});
    if (table.rowCount() < 2)
        throw table.errorAt(0, "an angular-velocity target needs at least two samples");
    std::vector<TimedVector> samples;
    for (std::size_t row = 0; row < table.rowCount(); ++row)
        samples.push_back({table.value(row, "time"), vectorAt(table, row, std::span(kOmegaColumns).subspan(1))});
    return AngularVelocityTarget::fromSamples(std::move(samples));
}

std::vector<TimedScalar> magnitudeCurve(const QString& path)
{
    const io::NumberTable table = io::readNumberCsv(path, {kMagnitudeColumns, {}, "time"});
    if (table.rowCount() < 2)
        throw table.errorAt(0, "a magnitude curve needs at least two samples");
    std::vector<TimedScalar> curve;
    for (std::size_t row = 0; row < table.rowCount(); ++row) {
        const double magnitude = table.value(row, "magnitude");
        if (!(magnitude > 0.0))
            throw table.errorAt(row, "column magnitude: " + formatNumber(magnitude) +
                                         " is not positive; |ω| is in rad/s and must be > 0");
        curve.push_back({table.value(row, "time"), magnitude});
    }
    return curve;
}

// The direction curve, timed by its own column or spread over `window` by arc length.
std::vector<TimedVector> directionCurve(const QString& path, const fit::TimeWindow& window)
{
    const io::NumberTable table = io::readNumberCsv(path, {kDirectionColumns, kTime, "time"});
    std::vector<Eigen::Vector3d> points;
    for (std::size_t row = 0; row < table.rowCount(); ++row) {
        const Eigen::Vector3d point = vectorAt(table, row, kDirectionColumns);
        if (std::abs(point.norm() - 1.0) > kUnitTolerance)
            throw table.errorAt(row, "x,y,z has length " + formatNumber(point.norm()) +
                                         ": a direction must lie on the unit sphere");
        points.push_back(point.normalized());
    }
    if (!table.hasColumn("time"))
        return fit::spreadByArcLength(points, window.start, window.end);
    if (table.rowCount() < 2)
        throw table.errorAt(0, "a timed direction curve needs at least two points");
    std::vector<TimedVector> timed;
    for (std::size_t row = 0; row < table.rowCount(); ++row)
        timed.push_back({table.value(row, "time"), points[row]});
    return timed;
}

std::vector<Eigen::Vector2d> patternCurve(const QString& path)
{
    const io::NumberTable table = io::readNumberCsv(path, {kPatternColumns, {}, std::nullopt});
    std::vector<Eigen::Vector2d> pattern;
    for (std::size_t row = 0; row < table.rowCount(); ++row)
        pattern.emplace_back(table.value(row, "x"), table.value(row, "y"));
    return pattern;
}

std::optional<fit::TimeWindow> windowOption(const VerbCommandLine& commandLine)
{
    if (!commandLine.isSet(kWindow))
        return std::nullopt;
    const QStringList ends = commandLine.requiredValue(kWindow).split(QLatin1Char(','));
    try {
        if (ends.size() == 2) {
            const fit::TimeWindow window{parseFiniteNumber(ends[0].toStdString()), parseFiniteNumber(ends[1].toStdString())};
            if (window.start < window.end)
                return window;
        }
    } catch (const std::invalid_argument& problem) {
        throw commandLine.error(std::string("--window: ") + problem.what());
    }
    throw commandLine.error("--window: give two times ta,tb with ta < tb");
}

// The sketch's target: magnitude times direction, the pattern applied, over the window (by default the
// magnitude curve's span).
AngularVelocityTarget sketchTarget(const VerbCommandLine& commandLine, const std::optional<fit::TimeWindow>& window)
{
    if (!commandLine.isSet(kMagnitude))
        throw commandLine.error("--direction needs --magnitude");
    if (commandLine.isSet(kPattern) != commandLine.isSet(kRepeat))
        throw commandLine.error("--pattern and --repeat go together");
    const QString magnitudePath = commandLine.requiredValue(kMagnitude);
    std::vector<TimedScalar> magnitudes = magnitudeCurve(magnitudePath);
    const fit::TimeWindow span = window.value_or(fit::TimeWindow{magnitudes.front().time, magnitudes.back().time});
    const QString directionPath = commandLine.requiredValue(kDirection);
    std::vector<TimedVector> directions = directionCurve(directionPath, span);
    if (commandLine.isSet(kPattern)) {
        const int repeat = commandLine.nonNegativeInteger(kRepeat);
        if (repeat < 1)
            throw commandLine.error("--repeat: a pattern repeats at least once");
        const QString patternPath = commandLine.requiredValue(kPattern);
        const std::vector<Eigen::Vector2d> pattern = patternCurve(patternPath);
        try {
            fit::checkPatternPointCount(pattern.size(), repeat);
        } catch (const std::invalid_argument& problem) {
            throw commandLine.error("--repeat: " + std::string(problem.what()));
        }
        try {
            directions = fit::applyPattern(directions, pattern, repeat);
        } catch (const std::invalid_argument& problem) {
            throw InputError(patternPath, problem.what());
        }
    }
    try {
        return AngularVelocityTarget::fromSketch(std::move(directions), std::move(magnitudes));
    } catch (const std::invalid_argument& problem) {
        throw InputError(directionPath, std::string(problem.what()) + " (with " + magnitudePath.toStdString() + ")");
    }
}

AngularVelocityTarget target(const VerbCommandLine& commandLine, const std::optional<fit::TimeWindow>& window)
{
    const bool omega = commandLine.isSet(kOmega);
    const bool sketch = commandLine.isSet(kDirection);
    if (omega == sketch)
        throw commandLine.error("give the target as either --omega or --direction with --magnitude");
    if (omega && (commandLine.isSet(kMagnitude) || commandLine.isSet(kPattern) || commandLine.isSet(kRepeat)))
        throw commandLine.error("--magnitude, --pattern and --repeat go with --direction, not --omega");
    return omega ? omegaTarget(commandLine.requiredValue(kOmega)) : sketchTarget(commandLine, window);
}

FitSettings settings(const VerbCommandLine& commandLine, const std::optional<fit::TimeWindow>& window)
{
    FitSettings settings;
    if (commandLine.isSet(kAlpha)) {
        settings.alpha = commandLine.number(kAlpha);
        if (settings.alpha < 0.0)
            throw commandLine.error("--alpha: must be ≥ 0");
    }
    if (commandLine.isSet(kBeta))
        settings.beta = commandLine.positiveNumber(kBeta);
    if (commandLine.isSet(kDelta))
        settings.delta = commandLine.positiveNumber(kDelta);
    if (commandLine.isSet(kFragment))
        settings.fragmentSeconds = commandLine.positiveNumber(kFragment);
    settings.window = window;
    return settings;
}

std::set<std::size_t> freedKeys(const VerbCommandLine& commandLine, std::size_t keyCount)
{
    std::set<std::size_t> freed;
    if (!commandLine.isSet(kFree))
        return freed;
    for (const QString& item : commandLine.requiredValue(kFree).split(QLatin1Char(','))) {
        bool ok = false;
        const int index = item.trimmed().toInt(&ok);
        if (!ok || index < 0 || static_cast<std::size_t>(index) >= keyCount)
            throw commandLine.error("--free: '" + item.toStdString() + "' is not a key index from 0 to " +
                                    std::to_string(keyCount - 1));
        freed.insert(static_cast<std::size_t>(index));
    }
    return freed;
}

QJsonObject energyJson(const fit::EnergyTerms& terms, const FitSettings& settings)
{
    return {{QStringLiteral("tangential"), terms.tangential},
            {QStringLiteral("angular"), terms.angular},
            {QStringLiteral("total"), settings.alpha * terms.tangential + settings.beta * terms.angular}};
}

QByteArray reportJson(const FitResult& result, const FitSettings& settings)
{
    const QJsonObject report{
        {QStringLiteral("outcome"), QString::fromUtf8(nameOf(fit::kFitOutcomeNames, result.outcome))},
        {QStringLiteral("converged"), result.outcome == fit::FitOutcome::Converged},
        {QStringLiteral("rounds"), result.rounds},
        {QStringLiteral("iterations"), result.iterations},
        {QStringLiteral("variableFrames"), result.variableFrames},
        {QStringLiteral("largestFragmentError"), result.largestFragmentError},
        {QStringLiteral("delta"), settings.delta},
        {QStringLiteral("largestNormDeviation"), result.largestNormDeviation},
        {QStringLiteral("window"), QJsonArray{result.window.start, result.window.end}},
        {QStringLiteral("solveSeconds"), result.solveSeconds},
        {QStringLiteral("energyBefore"), energyJson(result.before, settings)},
        {QStringLiteral("energyAfter"), energyJson(result.after, settings)},
    };
    return QJsonDocument(report).toJson();
}

io::PoseTable fittedFrames(const io::PoseTable& keys, const std::vector<FitKey>& fitKeys, const FitResult& result,
                       const std::vector<double>& times)
{
    std::vector<PositionKey> positions;
    for (const io::PoseRow& row : keys.rows)
        positions.push_back({row.time, row.pose.position});
    const PositionCurve positionCurve(std::move(positions), PositionCurve::Shape::Cubic);
    const fit::FittedMotion motion(fitKeys, result);
    io::PoseTable frames{io::RotationColumns::Quaternion, true, keys.hasPosition, {}};
    frames.rows.reserve(times.size());
    for (const double time : times)
        frames.rows.push_back({time, {motion.sample(time).value, positionCurve.at(time)}, 0});
    return frames;
}

// Every file fit reads and writes: no output may be one of the others.
void refuseSharedFiles(const VerbCommandLine& commandLine)
{
    std::vector<NamedFile> inputs{{"the input file", commandLine.inputPath()}};
    for (const QString& option : {kOmega, kDirection, kMagnitude, kPattern})
        if (commandLine.isSet(option))
            inputs.push_back({"--" + option.toStdString(), commandLine.requiredValue(option)});
    std::vector<NamedFile> outputs{{"-o", commandLine.outputPath()}};
    if (commandLine.isSet(kReport))
        outputs.push_back({"--report", commandLine.requiredValue(kReport)});
    commandLine.refuseSharedFiles(inputs, outputs);
}

} // namespace

void runFit(const QStringList& arguments)
{
    const VerbCommandLine commandLine(QStringLiteral("fit"), arguments, fitOptions());
    refuseSharedFiles(commandLine);
    const double fps = commandLine.frameRate(kFps);
    const std::optional<fit::TimeWindow> window = windowOption(commandLine);
    const FitSettings fitSettings = settings(commandLine, window);
    const io::PoseTable keys = io::readPoseCsv(commandLine.inputPath(), commandLine.eulerConvention(), io::TimeColumn::Required);
    if (keys.rows.size() < 2)
        throw InputError(commandLine.inputPath(), keys.rows.back().line, "fit needs at least two keys");
    const std::set<std::size_t> freed = freedKeys(commandLine, keys.rows.size());
    const AngularVelocityTarget angularVelocity = target(commandLine, window);
    try {
        fit::checkFragmentCount(window.value_or(fit::TimeWindow{angularVelocity.startTime(), angularVelocity.endTime()}),
                                fitSettings.fragmentSeconds);
    } catch (const std::invalid_argument& problem) {
        throw commandLine.error("--fragment: " + std::string(problem.what()));
    }

    std::vector<FitKey> fitKeys;
    std::vector<double> keyTimes;
    for (std::size_t i = 0; i < keys.rows.size(); ++i) {
        fitKeys.push_back({keys.rows[i].time, keys.rows[i].pose.orientation, !freed.contains(i)});
        keyTimes.push_back(keys.rows[i].time);
    }
    const model::BakeRange range{keyTimes.front(), keyTimes.back(), fps};
    const std::vector<double> times = model::bakeTimes(keyTimes, checkedOutputRange(range, keyTimes.size(), commandLine));
    FitResult result;
    try {
        result = fit::fitAngularVelocity(fitKeys, angularVelocity, fitSettings);
    } catch (const std::invalid_argument& problem) {
        throw InputError(commandLine.inputPath(), std::string("cannot fit: ") + problem.what());
    }

    const io::PoseTable frames = fittedFrames(keys, fitKeys, result, times);
    if (!commandLine.isSet(kReport)) {
        io::writePoseCsv(commandLine.outputPath(), frames);
        return;
    }
    // Both files are written in full before either replaces what was there.
    OutputTarget framesFile(commandLine.outputPath());
    OutputTarget reportFile(commandLine.requiredValue(kReport));
    framesFile.open();
    reportFile.open();
    io::writePoseCsv(framesFile, frames);
    reportFile.write(reportJson(result, fitSettings));
    framesFile.commit();
    reportFile.commit();
}

} // namespace gyre::cli
