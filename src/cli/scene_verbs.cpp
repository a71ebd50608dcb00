// gyre-cli import, export and bake: scenes in and out through Assimp (in gyre-scene-worker), and a
// project's motion at its frames.

#include "cli/command_line.h"
#include "cli/import_report.h"
#include "cli/tracked_object.h"
#include "cli/verbs.h"
#include "io/pose_csv.h"
#include "io/scene_export.h"
#include "io/scene_import.h"
#include "io/scene_worker.h"
#include "model/output_target.h"
#include "model/project_file.h"
#include "model/input_error.h"
#include "model/rotation_mode.h"
#include "model/track_evaluation.h"

#include <cstdio>
#include <string>
#include <vector>

namespace gyre::cli {

namespace {

const QString kAnimationOption = QStringLiteral("animation");
const QString kFpsOption = QStringLiteral("fps");
const QString kObjectOption = QStringLiteral("object");
const QString kUnitOption = QStringLiteral("unit");
const QString kUpOption = QStringLiteral("up");
const QString kTimeOriginOption = QStringLiteral("time-origin");
const QString kEulerFilterOption = QStringLiteral("euler-filter");

void warnAll(const QStringList& warnings)
{
    for (const QString& warning : warnings)
        warn(warning.toStdString());
}

// --animation all, N or N,M,...
void readTakes(const VerbCommandLine& commandLine, io::ImportOptions& options)
{
    const QString value = commandLine.requiredValue(kAnimationOption);
    if (value == QLatin1String("all")) {
        options.takeSelection = io::TakeSelection::All;
        return;
    }
    options.takeSelection = io::TakeSelection::Listed;
    for (const QString& item : value.split(QLatin1Char(','))) {
        bool ok = false;
        const qulonglong index = item.trimmed().toULongLong(&ok);
        if (!ok || item.trimmed().startsWith(QLatin1Char('+')))
            throw commandLine.error("--animation: '" + value.toStdString() +
                                    "' is not all, an animation's number or a list of them such as 0,2");
        options.takes.push_back(static_cast<std::size_t>(index));
    }
}

io::ImportOptions importOptions(const VerbCommandLine& commandLine)
{
    io::ImportOptions options;
    if (commandLine.isSet(kAnimationOption))
        readTakes(commandLine, options);
    if (commandLine.isSet(kFpsOption))
        options.fps = commandLine.frameRate(kFpsOption);
    if (commandLine.isSet(kUnitOption))
        options.metresPerUnit = commandLine.positiveNumber(kUnitOption);
    if (commandLine.isSet(kUpOption))
        options.up = commandLine.choice(kUpOption, io::kUpAxisNames);
    if (commandLine.isSet(kTimeOriginOption))
        options.timeOrigin = commandLine.choice(kTimeOriginOption, io::kTimeOriginNames);
    return options;
}

std::vector<std::string_view> sceneFormatNames()
{
    std::vector<std::string_view> names;
    for (const auto& entry : io::kSceneFormatNames)
        names.push_back(entry.second);
    return names;
}

} // namespace

void runImport(const QStringList& arguments)
{
    const VerbCommandLine commandLine(QStringLiteral("import"), arguments,
                                      {QCommandLineOption(kAnimationOption, {}, QStringLiteral("takes")),
                                       QCommandLineOption(kFpsOption, {}, QStringLiteral("rate")),
                                       QCommandLineOption(kUnitOption, {}, QStringLiteral("metres")),
                                       QCommandLineOption(kUpOption, {}, QStringLiteral("axis")),
                                       QCommandLineOption(kTimeOriginOption, {}, QStringLiteral("origin")),
                                       QCommandLineOption(kEulerFilterOption)});
    const io::ImportOptions options = importOptions(commandLine);
    io::SceneImport imported = io::importSceneInWorker(commandLine.inputPath(), options);
    if (imported.takeRule == io::TakeRule::ChoiceNeeded)
        throw commandLine.error(commandLine.inputPath().toStdString() + " has " +
                                std::to_string(imported.animations.size()) +
                                " animations that move the same nodes; choose with --animation N (one), N,M,... "
                                "(merged, a later one winning a node it shares) or all:\n" +
                                animationList(imported));
    warnAll(imported.warnings);
    std::fprintf(stderr, "gyre-cli: imported at %s\n", settingsLine(imported).c_str());
    // The window's import option of the same name (scene_file_actions.h): extrinsic xyz, Blender's default XYZ.
    if (commandLine.isSet(kEulerFilterOption))
        for (model::SceneObject& object : imported.scene.objects)
            model::putInEulerMode(object.track, {});
    model::writeProject(commandLine.outputPath(), imported.scene);
}

void runExport(const QStringList& arguments)
{
    const VerbCommandLine commandLine(QStringLiteral("export"), arguments,
                                      {QCommandLineOption(kFpsOption, {}, QStringLiteral("rate"))});
    // The extension names the format, and glTF and OBJ write a second file named after the first.
    if (commandLine.outputPath() == OutputTarget::kStandardOutput)
        throw commandLine.error("-o -: a scene is written to a file whose extension names its format, not to "
                                "standard output");
    const std::optional<io::SceneFormat> format = io::sceneFormatOfPath(commandLine.outputPath());
    if (!format)
        throw commandLine.error("-o: the file's extension must name a scene format: " +
                                alternatives(sceneFormatNames()));
    const std::optional<double> fps =
        commandLine.isSet(kFpsOption) ? std::optional(commandLine.frameRate(kFpsOption)) : std::nullopt;
    const model::Scene scene = model::readProject(commandLine.inputPath());
    warnAll(io::exportSceneInWorker(scene, commandLine.outputPath(), *format, fps.value_or(scene.fps)).warnings);
}

void runBake(const QStringList& arguments)
{
    const VerbCommandLine commandLine(QStringLiteral("bake"), arguments,
                                      {QCommandLineOption(kObjectOption, {}, QStringLiteral("name")),
                                       QCommandLineOption(kFpsOption, {}, QStringLiteral("rate"))});
    const QString name = commandLine.requiredValue(kObjectOption);
    const double fps = commandLine.frameRate(kFpsOption);
    const model::Scene scene = model::readProject(commandLine.inputPath());
    const model::SceneObject& object = trackedObjectNamed(scene, name, commandLine.inputPath());
    const model::BakeRange range =
        checkedOutputRange({scene.startTime, scene.endTime, fps}, object.track.keys.size(), commandLine);
    std::vector<model::TimedPose> samples;
    try {
        samples = model::bakeTrack(object.track, range, model::flightBodyOf(object), scene.gravity);
    } catch (const std::invalid_argument& problem) {
        throw InputError(commandLine.inputPath(), "the motion of '" + name.toStdString() + "' cannot be baked: " +
                                                      problem.what());
    }
    io::PoseTable frames{io::RotationColumns::Quaternion, true, true, {}};
    for (const model::TimedPose& sample : samples)
        frames.rows.push_back({sample.time, sample.pose, 0});
    io::writePoseCsv(commandLine.outputPath(), frames);
}

} // namespace gyre::cli
