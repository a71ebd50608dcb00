// gyre-cli info: a short summary of a project.

#include "cli/command_line.h"
#include "cli/verbs.h"
#include "core/number_text.h"
#include "model/project_file.h"
#include "model/scene_queries.h"

#include <cstdio>
#include <string>

namespace gyre::cli {

namespace {

using model::SceneObject;

std::string plural(std::size_t count, const char* noun)
{
    return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

// "  wheel (child of car): 3 keyframes from 0 to 2 s, screw"
std::string objectLine(const model::Scene& scene, const SceneObject& object)
{
    std::string line = "  " + object.name.toStdString();
    if (const SceneObject* parent = model::findObject(scene, object.parent))
        line += " (child of " + parent->name.toStdString() + ")";
    const std::vector<model::Keyframe>& keys = object.track.keys;
    line += ": " + plural(keys.size(), "keyframe");
    if (!keys.empty())
        line += " from " + formatNumber(keys.front().time) + " to " + formatNumber(keys.back().time) + " s";
    return line + ", " + std::string(interpolationMethodName(object.track.interpolation));
}

} // namespace

void runInfo(const QStringList& arguments)
{
    const VerbCommandLine commandLine(QStringLiteral("info"), arguments, {}, OutputFile::None);
    const model::Scene scene = model::readProject(commandLine.inputPath());
    std::string text = commandLine.inputPath().toStdString() + ": Gyre project\n";
    text += "time range: " + formatNumber(scene.startTime) + " to " + formatNumber(scene.endTime) + " s at " +
            formatNumber(scene.fps) + " fps\n";
    text += plural(scene.objects.size(), "object") + ", " + plural(model::keyframeCount(scene), "keyframe") + "\n";
    for (const SceneObject& object : scene.objects)
        text += objectLine(scene, object) + "\n";
    std::fputs(text.c_str(), stdout);
}

} // namespace gyre::cli
