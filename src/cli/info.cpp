// gyre-cli info: a short summary of a project or a scene file.

#include "cli/command_line.h"
#include "cli/import_report.h"
#include "cli/verbs.h"
#include "core/number_text.h"
#include "io/scene_import.h"
#include "io/scene_worker.h"
#include "model/object_mass.h"
#include "model/project_file.h"
#include "model/scene_queries.h"

#include <cmath>
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

// Four significant digits: what a mass or a moment of inertia is known to; a value below `zero` shows as 0.
std::string rounded(double value, double zero = 0.0)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", std::abs(value) < zero ? 0.0 : value);
    return text;
}

// "    mass 635.8 kg (from the mesh, solid), centre (0, 0, 0.6551) m, principal moments 74.51, 74.51, 103.3 kg·m²"
std::string massLine(const SceneObject& object)
{
    // A mesh's float positions put the centre of a symmetric body a few 1e-8 m off its axis.
    constexpr double kMicrometre = 1e-6;
    const model::ObjectMass mass = model::objectMassProperties(object);
    const Eigen::Vector3d& centre = mass.properties.centre;
    const Eigen::Vector3d moments = principalAxes(mass.properties.inertia).moments;
    return "    mass " + rounded(mass.properties.mass) + " kg (" + model::massSourceText(mass.source).toStdString() +
           "), centre (" + rounded(centre.x(), kMicrometre) + ", " + rounded(centre.y(), kMicrometre) + ", " +
           rounded(centre.z(), kMicrometre) +
           ") m, principal moments " + rounded(moments[0]) + ", " + rounded(moments[1]) + ", " + rounded(moments[2]) +
           " kg·m²";
}

// A project by its .gyre extension; any other file is a scene for Assimp, whose animations are listed.
bool isProject(const QString& path) { return path.endsWith(QStringLiteral(".gyre"), Qt::CaseInsensitive); }

// The file's animations, which the import takes, and the settings it applies.
std::string sceneLines(const io::SceneImport& imported)
{
    std::string text = plural(imported.animations.size(), "animation") + (imported.animations.empty() ? "\n" : ":\n");
    text += animationList(imported);
    if (!imported.animations.empty())
        text += takeChoiceLine(imported) + "\n";
    return text + "import settings: " + settingsLine(imported) + "\n";
}

} // namespace

void runInfo(const QStringList& arguments)
{
    const VerbCommandLine commandLine(QStringLiteral("info"), arguments, {}, OutputFile::None);
    const QString& path = commandLine.inputPath();
    std::string text;
    model::Scene scene;
    if (isProject(path)) {
        scene = model::readProject(path);
        text = path.toStdString() + ": Gyre project\n";
    } else {
        io::SceneImport imported = io::importSceneInWorker(path);
        scene = std::move(imported.scene);
        text = path.toStdString() + ": scene\n" + sceneLines(imported);
    }
    text += "time range: " + formatNumber(scene.startTime) + " to " + formatNumber(scene.endTime) + " s at " +
            formatNumber(scene.fps) + " fps\n";
    text += plural(scene.objects.size(), "object") + ", " + plural(model::keyframeCount(scene), "keyframe") + "\n";
    for (const SceneObject& object : scene.objects)
        text += objectLine(scene, object) + "\n" + massLine(object) + "\n";
    std::fputs(text.c_str(), stdout);
}

} // namespace gyre::cli
