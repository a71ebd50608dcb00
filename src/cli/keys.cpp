// gyre-cli keys: one object's keyframes from a project, as a pose file.

#include "cli/command_line.h"
#include "cli/tracked_object.h"
#include "cli/verbs.h"
#include "io/pose_csv.h"
#include "model/project_file.h"

namespace gyre::cli {

namespace {

const QString kObjectOption = QStringLiteral("object");

} // namespace

void runKeys(const QStringList& arguments)
{
    const VerbCommandLine commandLine(QStringLiteral("keys"), arguments,
                                      {QCommandLineOption(kObjectOption, {}, QStringLiteral("name"))});
    const QString name = commandLine.requiredValue(kObjectOption);
    const model::Scene scene = model::readProject(commandLine.inputPath());
    const model::SceneObject& object = trackedObjectNamed(scene, name, commandLine.inputPath());
    io::PoseTable table;
    table.rotationColumns = io::RotationColumns::Quaternion;
    table.hasTime = true;
    table.hasPosition = true;
    for (const model::Keyframe& key : object.track.keys)
        table.rows.push_back({key.time, key.pose, 0});
    io::writePoseCsv(commandLine.outputPath(), table);
}

} // namespace gyre::cli
