// gyre-cli import, export and bake: scenes in and out through Assimp (in gyre-scene-worker), and a
// project's motion at its frames.

#include "cli/command_line.h"
#include "cli/tracked_object.h"
#include "cli/verbs.h"
#include "io/pose_csv.h"
#include "io/scene_export.h"
#include "io/scene_import.h"
#include "io/scene_worker.h"
#include "model/output_target.h"
#include "model/project_file.h"
#include "model/input_error.h"
#include "model/track_evaluation.h"

#include <string>
#include <vector>

namespace gyre::cli {

namespace {

const QString kAnimationOption = QStringLiteral("animation");
const QString kFpsOption = QStringLiteral("fps");
const QString kObjectOption = QStringLiteral("object");

void warnAll(const QStringList& warnings)
{
    for (const QString& warning : warnings)
        warn(warning.toStdString());
}

std::vector<std::string_view> sceneFormatNames()
{
    std::vector<std::string_view> names;
    for (const auto& entry : kSceneFormatNames)
        names.push_back(entry.second);
    return names;
}

} // namespace

void runImport(const QStringList& arguments)
{
    const VerbCommandLine commandLine(QStringLiteral("import"), arguments,
                                      {QCommandLineOption(kAnimationOption, {}, QStringLiteral("index"))});
    ImportOptions options;
    if (commandLine.isSet(kAnimationOption))
        options.animationIndex = static_cast<std::size_t>(commandLine.nonNegativeInteger(kAnimationOption));
    const SceneImport imported = importSceneInWorker(commandLine.inputPath(), options);
    warnAll(imported.warnings);
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
    const std::optional<SceneFormat> format = sceneFormatOfPath(commandLine.outputPath());
    if (!format)
        throw commandLine.error("-o: the file's extension must name a scene format: " +
                                alternatives(sceneFormatNames()));
    const std::optional<double> fps =
        commandLine.isSet(kFpsOption) ? std::optional(commandLine.frameRate(kFpsOption)) : std::nullopt;
    const model::Scene scene = model::readProject(commandLine.inputPath());
    warnAll(exportSceneInWorker(scene, commandLine.outputPath(), *format, fps.value_or(scene.fps)).warnings);
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
        samples = model::bakeTrack(object.track, range);
    } catch (const std::invalid_argument& problem) {
        throw InputError(commandLine.inputPath(), "the motion of '" + name.toStdString() + "' cannot be baked: " +
                                                      problem.what());
    }
    PoseTable frames{RotationColumns::Quaternion, true, true, {}};
    for (const model::TimedPose& sample : samples)
        frames.rows.push_back({sample.time, sample.pose, 0});
    writePoseCsv(commandLine.outputPath(), frames);
}

} // namespace gyre::cli
