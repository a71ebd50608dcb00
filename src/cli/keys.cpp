// gyre-cli keys: one object's keyframes from a project, as a pose file.

#include "cli/command_line.h"
#include "cli/verbs.h"
#include "io/pose_csv.h"
#include "model/project_file.h"

namespace gyre::cli {

namespace {

const QString kObjectOption = QStringLiteral("object");

// The one object of the scene named `name` that has keyframes. Throws InputError naming the file.
const model::SceneObject& objectNamed(const model::Scene& scene, const QString& name, const QString& path)
{
    std::vector<const model::SceneObject*> named;
    for (const model::SceneObject& object : scene.objects)
        if (object.name == name)
            named.push_back(&object);
    const std::string quoted = "'" + name.toStdString() + "'";
    if (named.empty())
        throw InputError(path, "--object: no object is named " + quoted);
    if (named.size() > 1)
        throw InputError(path, "--object: " + std::to_string(named.size()) + " objects are named " + quoted +
                                   "; the name must single out one");
    if (named.front()->track.keys.empty())
        throw InputError(path, "--object: object " + quoted + " has no keyframes");
    return *named.front();
}

} // namespace

void runKeys(const QStringList& arguments)
{
    const VerbCommandLine commandLine(QStringLiteral("keys"), arguments,
                                      {QCommandLineOption(kObjectOption, {}, QStringLiteral("name"))});
    const QString name = commandLine.requiredValue(kObjectOption);
    const model::Scene scene = model::readProject(commandLine.inputPath());
    const model::SceneObject& object = objectNamed(scene, name, commandLine.inputPath());
    PoseTable table;
    table.rotationColumns = RotationColumns::Quaternion;
    table.hasTime = true;
    table.hasPosition = true;
    for (const model::Keyframe& key : object.track.keys)
        table.rows.push_back({key.time, key.pose, 0});
    writePoseCsv(commandLine.outputPath(), table);
}

} // namespace gyre::cli
