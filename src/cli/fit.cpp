// gyre-cli fit: the rotation through keys bent to match a target angular velocity (src/fit). A sketch,
// from a project or from files, becomes the fit's problem by the model's rules
// (model/sketch_fit_problem.h), the same the app's Fit button uses, and the result is applied and
// evaluated as the app applies and plays it (ApplyFitResultCommand's withFitApplied, TrackMotion).

#include "cli/command_line.h"
#include "cli/tracked_object.h"
#include "cli/verbs.h"
#include "core/number_text.h"
#include "fit/angular_velocity_fit.h"
#include "io/number_csv.h"
#include "io/pose_csv.h"
#include "model/output_target.h"
#include "model/project_file.h"
#include "model/sketch_fit_problem.h"
#include "model/track_evaluation.h"

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
using fit::FitResult;
using fit::FitSettings;
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
const QString kObject = QStringLiteral("object");

// The options that describe the target and the keys; a project holds all of these itself.
const std::array kKeysFileOptions{kOmega, kDirection, kMagnitude, kPattern, kRepeat, kAlpha,
                                  kBeta,  kDelta,     kFragment,  kFree,    kWindow};

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
    for (const QString& name : kKeysFileOptions)
        options.append(QCommandLineOption(name, {}, QStringLiteral("value")));
    for (const QString& name : {kFps, kReport, kObject})
        options.append(QCommandLineOption(name, {}, QStringLiteral("value")));
    return options + eulerOptions();
}

bool isProject(const QString& path)
{
    return path.endsWith(QStringLiteral(".gyre"), Qt::CaseInsensitive);
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

std::vector<model::MagnitudePoint> magnitudeCurve(const QString& path)
{
    const io::NumberTable table = io::readNumberCsv(path, {kMagnitudeColumns, {}, "time"});
    if (table.rowCount() < 2)
        throw table.errorAt(0, "a magnitude curve needs at least two samples");
    std::vector<model::MagnitudePoint> curve;
    for (std::size_t row = 0; row < table.rowCount(); ++row) {
        const double magnitude = table.value(row, "magnitude");
        if (!(magnitude > 0.0))
            throw table.errorAt(row, "column magnitude: " + formatNumber(magnitude) +
                                         " is not positive; |ω| is in rad/s and must be > 0");
        curve.push_back({table.value(row, "time"), magnitude});
    }
    return curve;
}

// The direction curve as one stroke, timed by its own column or untimed (then the model spreads it
// over the edit window by arc length).
model::DirectionStroke directionStroke(const QString& path)
{
    const io::NumberTable table = io::readNumberCsv(path, {kDirectionColumns, kTime, "time"});
    model::DirectionStroke stroke;
    for (std::size_t row = 0; row < table.rowCount(); ++row) {
        const Eigen::Vector3d point = vectorAt(table, row, kDirectionColumns);
        if (std::abs(point.norm() - 1.0) > kUnitTolerance)
            throw table.errorAt(row, "x,y,z has length " + formatNumber(point.norm()) +
                                         ": a direction must lie on the unit sphere");
        stroke.points.push_back(point.normalized());
    }
    if (!table.hasColumn("time"))
        return stroke;
    if (table.rowCount() < 2)
        throw table.errorAt(0, "a timed direction curve needs at least two points");
    for (std::size_t row = 0; row < table.rowCount(); ++row)
        stroke.times.push_back(table.value(row, "time"));
    return stroke;
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

// The keys file as a Hermite track, its keys constrained unless --free names them.
model::MotionTrack keyedTrack(const VerbCommandLine& commandLine, const io::PoseTable& keys)
{
    const std::set<std::size_t> freed = freedKeys(commandLine, keys.rows.size());
    model::MotionTrack track;
    track.interpolation = InterpolationMethod::Hermite;
    for (std::size_t i = 0; i < keys.rows.size(); ++i)
        track.keys.push_back({keys.rows[i].time, keys.rows[i].pose, !freed.contains(i)});
    return track;
}

// α, β and δ from --alpha, --beta and --delta, the fit's defaults (which are the sketch's) otherwise.
FitSettings weightOptions(const VerbCommandLine& commandLine)
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
    return settings;
}

// The sketch the files describe, with the weights and δ of the options (the sketch's defaults
// otherwise), as the app would hold it.
model::SketchState sketchOf(const VerbCommandLine& commandLine)
{
    if (commandLine.isSet(kPattern) != commandLine.isSet(kRepeat))
        throw commandLine.error("--pattern and --repeat go together");
    if (commandLine.isSet(kPattern) && !commandLine.isSet(kDirection))
        throw commandLine.error("--pattern follows the direction curve: give --direction too");
    model::SketchState sketch;
    if (commandLine.isSet(kDirection))
        sketch.directionStrokes.push_back(directionStroke(commandLine.requiredValue(kDirection)));
    if (commandLine.isSet(kMagnitude))
        sketch.magnitude = magnitudeCurve(commandLine.requiredValue(kMagnitude));
    if (commandLine.isSet(kPattern)) {
        sketch.patternRepeat = commandLine.nonNegativeInteger(kRepeat);
        if (sketch.patternRepeat < 1)
            throw commandLine.error("--repeat: a pattern repeats at least once");
        sketch.pattern = patternCurve(commandLine.requiredValue(kPattern));
        try {
            fit::checkPatternPointCount(sketch.pattern.size(), sketch.patternRepeat);
        } catch (const std::invalid_argument& problem) {
            throw commandLine.error("--repeat: " + std::string(problem.what()));
        }
    }
    if (const std::optional<fit::TimeWindow> window = windowOption(commandLine))
        sketch.window = std::pair(window->start, window->end);
    const FitSettings weights = weightOptions(commandLine);
    sketch.alpha = weights.alpha;
    sketch.beta = weights.beta;
    sketch.delta = weights.delta;
    return sketch;
}

// The fit's problem from the track's sketch, as the app makes it; a sketch it refuses is an input error
// whose message starts with `refusal`.
model::SketchFitProblem sketchProblem(const VerbCommandLine& commandLine, const model::MotionTrack& track,
                                      const std::string& refusal)
{
    try {
        // Keys from a pose file: a hermite track, which flies no body.
        return model::sketchFitProblem(track, MassProperties{});
    } catch (const std::invalid_argument& problem) {
        throw InputError(commandLine.inputPath(), refusal + problem.what());
    }
}

// What the fit solves: the keys and the --omega samples as they are, or the sketch made into the
// fit's problem by the model's rules.
model::SketchFitProblem fitProblem(const VerbCommandLine& commandLine, model::MotionTrack& track)
{
    const bool omega = commandLine.isSet(kOmega);
    const bool sketch = commandLine.isSet(kDirection) || commandLine.isSet(kMagnitude);
    if (omega == sketch)
        throw commandLine.error("give the target as either --omega or a sketch, --direction and/or --magnitude");
    if (omega && (commandLine.isSet(kPattern) || commandLine.isSet(kRepeat)))
        throw commandLine.error("--pattern and --repeat go with --direction, not --omega");
    if (sketch) {
        track.sketch = sketchOf(commandLine);
        return sketchProblem(commandLine, track, "cannot fit: ");
    }
    const AngularVelocityTarget target = omegaTarget(commandLine.requiredValue(kOmega));
    FitSettings settings = weightOptions(commandLine);
    settings.window = windowOption(commandLine).value_or(fit::TimeWindow{target.startTime(), target.endTime()});
    std::vector<fit::FitKey> keys;
    for (const model::Keyframe& key : track.keys)
        keys.push_back({key.time, key.pose.orientation, key.constrained});
    return {std::move(keys), target, settings, {}, {}};
}

QJsonObject energyJson(const fit::EnergyTerms& terms, const FitSettings& settings)
{
    return {{QStringLiteral("tangential"), terms.tangential},
            {QStringLiteral("angular"), terms.angular},
            {QStringLiteral("total"), settings.alpha * terms.tangential + settings.beta * terms.angular}};
}

QByteArray reportJson(const FitResult& result, const FitSettings& settings,
                      const std::optional<model::DrawnErrors>& drawnErrors)
{
    QJsonObject report{
        {QStringLiteral("outcome"), QString::fromUtf8(nameOf(fit::kFitOutcomeNames, result.outcome))},
        {QStringLiteral("converged"), result.outcome == fit::FitOutcome::Converged},
        {QStringLiteral("rounds"), result.rounds},
        {QStringLiteral("iterations"), result.iterations},
        {QStringLiteral("variableFrames"), result.variableFrames},
        {QStringLiteral("largestRelativeError"), result.largestRelativeError},
        {QStringLiteral("largestFragmentError"), result.largestFragmentError},
        {QStringLiteral("targetMeanSquare"), result.targetMeanSquare},
        {QStringLiteral("delta"), settings.delta},
        {QStringLiteral("largestNormDeviation"), result.largestNormDeviation},
        {QStringLiteral("window"), QJsonArray{result.window.start, result.window.end}},
        {QStringLiteral("solveSeconds"), result.solveSeconds},
        {QStringLiteral("energyBefore"), energyJson(result.before, settings)},
        {QStringLiteral("energyAfter"), energyJson(result.after, settings)},
    };
    if (drawnErrors) {
        report.insert(QStringLiteral("drawnErrorBefore"), drawnErrors->before);
        report.insert(QStringLiteral("drawnErrorAfter"), drawnErrors->after);
    }
    return QJsonDocument(report).toJson();
}

// The track with the fit applied as the app applies it, baked over `range`.
io::PoseTable fittedFrames(const VerbCommandLine& commandLine, const model::MotionTrack& fitted, const model::BakeRange& range,
                       bool hasPosition)
{
    std::vector<model::TimedPose> samples;
    try {
        samples = model::bakeTrack(fitted, range);
    } catch (const std::invalid_argument& problem) {
        throw InputError(commandLine.inputPath(), std::string("the fitted motion cannot be written: ") + problem.what());
    }
    io::PoseTable frames{io::RotationColumns::Quaternion, true, hasPosition, {}};
    frames.rows.reserve(samples.size());
    for (const model::TimedPose& sample : samples)
        frames.rows.push_back({sample.time, sample.pose, 0});
    return frames;
}

// Fits `problem`, made from `track`, and writes the fitted motion over `range` and the report if asked
// for (with the errors against what was drawn when the track is sketched); both files are written in
// full before either replaces what was there.
void fitAndWrite(const VerbCommandLine& commandLine, const model::MotionTrack& track,
                 const model::SketchFitProblem& problem, const model::BakeRange& range, bool hasPosition)
{
    FitResult result;
    try {
        result = model::fitSketch(problem);
    } catch (const std::invalid_argument& refusal) {
        throw InputError(commandLine.inputPath(), std::string("cannot fit: ") + refusal.what());
    }
    const model::FitResult applied = model::appliedFitResult(track, result);
    const io::PoseTable frames = fittedFrames(commandLine, model::withFitApplied(track, applied), range, hasPosition);
    if (!commandLine.isSet(kReport)) {
        io::writePoseCsv(commandLine.outputPath(), frames);
        return;
    }
    const bool sketched = !track.sketch.directionStrokes.empty() || !track.sketch.magnitude.empty();
    const QByteArray report = reportJson(result, problem.settings,
                                         sketched ? std::optional(model::drawnErrors(track, *problem.motionWithoutFit, applied, MassProperties{}))
                                                  : std::nullopt);
    OutputTarget framesFile(commandLine.outputPath());
    OutputTarget reportFile(commandLine.requiredValue(kReport));
    framesFile.open();
    reportFile.open();
    io::writePoseCsv(framesFile, frames);
    reportFile.write(report);
    framesFile.commit();
    reportFile.commit();
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

// gyre-cli fit PROJECT.gyre --object NAME: the object's sketch fitted as the app's Fit fits it, and
// its motion written as bake writes it, over the scene's range.
void fitProjectObject(const VerbCommandLine& commandLine, double fps)
{
    for (const QString& option : kKeysFileOptions)
        if (commandLine.isSet(option))
            throw commandLine.error("--" + option.toStdString() + " goes with a keys file; a project holds its "
                                    "object's sketch and fit settings");
    const QString name = commandLine.requiredValue(kObject);
    const model::Scene scene = model::readProject(commandLine.inputPath());
    const model::MotionTrack& track = trackedObjectNamed(scene, name, commandLine.inputPath()).track;
    const model::BakeRange range = checkedOutputRange({scene.startTime, scene.endTime, fps}, track.keys.size(), commandLine);
    const model::SketchFitProblem problem = sketchProblem(commandLine, track, "cannot fit '" + name.toStdString() + "': ");
    fitAndWrite(commandLine, track, problem, range, true);
}

} // namespace

void runFit(const QStringList& arguments)
{
    const VerbCommandLine commandLine(QStringLiteral("fit"), arguments, fitOptions());
    refuseSharedFiles(commandLine);
    const double fps = commandLine.frameRate(kFps);
    if (isProject(commandLine.inputPath())) {
        fitProjectObject(commandLine, fps);
        return;
    }
    if (commandLine.isSet(kObject))
        throw commandLine.error("--object names an object of a project (a .gyre file)");
    const io::PoseTable keys = io::readPoseCsv(commandLine.inputPath(), commandLine.eulerConvention(), io::TimeColumn::Required);
    if (keys.rows.size() < 2)
        throw InputError(commandLine.inputPath(), keys.rows.back().line, "fit needs at least two keys");
    model::MotionTrack track = keyedTrack(commandLine, keys);
    model::SketchFitProblem problem = fitProblem(commandLine, track);
    if (commandLine.isSet(kFragment))
        problem.settings.fragmentSeconds = commandLine.positiveNumber(kFragment);
    try {
        fit::checkFragmentCount(*problem.settings.window, problem.settings.fragmentSeconds);
    } catch (const std::invalid_argument& refusal) {
        throw commandLine.error("--fragment: " + std::string(refusal.what()));
    }
    const std::vector<double> times = model::keyTimes(track);
    const model::BakeRange range = checkedOutputRange({times.front(), times.back(), fps}, times.size(), commandLine);
    fitAndWrite(commandLine, track, problem, range, keys.hasPosition);
}

} // namespace gyre::cli
