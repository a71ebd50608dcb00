#include "fuzz_inputs.h"

#include "io/bvh_fixture.h"
#include "io/number_csv.h"
#include "io/pose_csv.h"
#include "io/scene_export.h"
#include "io/scene_worker.h"
#include "model/input_error.h"
#include "model/project_file.h"
#include "model/track_evaluation.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string_view>

namespace gyre::fuzz {

namespace {

using namespace gyre::io;

using model::Keyframe;
using model::Scene;
using model::SceneObject;

constexpr std::array<std::string_view, 4> kOmegaColumns{"time", "wx", "wy", "wz"};

// The seeds are a few kilobytes, which Assimp reads in milliseconds: a mutant that takes the worker
// longer than this has sent a reader into a loop, and costs a refusal, not a hung test.
const SceneWorkerLimits kSceneWorkerLimits{qint64{1} << 30, std::chrono::seconds(10)};

Eigen::Quaterniond turn(double degrees, const Eigen::Vector3d& axis)
{
    return Eigen::Quaterniond(Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0, axis.normalized()));
}

QByteArray contentsOf(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw std::runtime_error("cannot read the seed " + path.toStdString());
    return file.readAll();
}

// The same motion in each rotation column set, written by the pose writer.
std::vector<Seed> poseSeeds(const QString& scratchDir)
{
    PoseTable table{RotationColumns::Quaternion, true, true, {}};
    const std::array<Eigen::Vector3d, 4> axes{Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 2, 3),
                                              Eigen::Vector3d(-1, 0, 0.5), Eigen::Vector3d(0, 1, 0)};
    for (int i = 0; i < 6; ++i) {
        PoseRow row;
        row.time = 0.25 * i;
        row.pose.orientation = turn(37.0 * i, axes[static_cast<std::size_t>(i) % axes.size()]);
        row.pose.position = Eigen::Vector3d(i, -0.5 * i, 1e-3 * i * i);
        table.rows.push_back(row);
    }
    std::vector<Seed> seeds;
    for (const auto& [columns, name] : kRotationColumnsNames) {
        table.rotationColumns = columns;
        // Every other set without time or position, so that both layouts are seeded.
        table.hasTime = table.hasPosition = seeds.size() % 2 == 0;
        const QString fileName = QStringLiteral("pose-%1.csv").arg(QLatin1String(name));
        const QString path = QDir(scratchDir).filePath(fileName);
        writePoseCsv(path, table);
        seeds.push_back({fileName, Reader::PoseCsv, contentsOf(path)});
    }
    // What the writer never makes: a byte order mark, CRLF, comments, blank lines, spaces, columns out
    // of order.
    seeds.push_back({QStringLiteral("pose-by-hand.csv"), Reader::PoseCsv,
                     QByteArray("\xEF\xBB\xBF# a pose file written by hand\r\n"
                                "z, qx ,qy,qz,qw,time,x,y\r\n"
                                "\r\n"
                                "0,0,0,0,1,0,0,0\r\n"
                                "  # halfway\r\n"
                                "1.5,0,0.7071067811865476,0,0.7071067811865476,0.5,1,-2\r\n"
                                "3,0.5,0.5,0.5,0.5,1e0,2.5e-1,7\r\n")});
    return seeds;
}

std::vector<Seed> numberSeeds()
{
    return {{QStringLiteral("omega.csv"), Reader::NumberCsv,
             QByteArray("time,wx,wy,wz\n0,0,0,1\n0.1,0.5,0,1\n0.2,1,-0.25,0.5\n# end\n0.4,3.14159,0,0\n")},
            {QStringLiteral("omega-reordered.csv"), Reader::NumberCsv,
             QByteArray("wz,wy,time,wx\r\n1,0,0,0\r\n\r\n2,0,1,1e-3\r\n")}};
}

Keyframe key(double time, const Eigen::Quaterniond& orientation, const Eigen::Vector3d& position)
{
    Keyframe keyframe;
    keyframe.time = time;
    keyframe.pose = {orientation, position};
    return keyframe;
}

SceneObject object(model::ObjectId id, const char* name, InterpolationMethod method, int keyCount)
{
    SceneObject result;
    result.id = id;
    result.name = QString::fromUtf8(name);
    result.track.interpolation = method;
    for (int i = 0; i < keyCount; ++i)
        result.track.keys.push_back(key(0.5 * i, turn(50.0 * i, Eigen::Vector3d(1, i, 2)), Eigen::Vector3d(i, 0, -i)));
    return result;
}

// A tetrahedron with normals.
std::shared_ptr<const model::Mesh> tetrahedron()
{
    auto mesh = std::make_shared<model::Mesh>();
    mesh->positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const Eigen::Vector3f& position : mesh->positions)
        mesh->normals.push_back((position - Eigen::Vector3f(0.25f, 0.25f, 0.25f)).normalized());
    mesh->indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    return mesh;
}

Scene keyedScene()
{
    Scene scene;
    scene.objects.push_back(object(1, "cube", InterpolationMethod::Slerp, 4));
    scene.objects.push_back(object(2, "lid", InterpolationMethod::Euler, 2));
    scene.objects.back().parent = 1;
    scene.objects.push_back(object(3, "empty", InterpolationMethod::Nlerp, 0));
    scene.nextObjectId = 4;
    return scene;
}

// A squad track and a screw track sharing one mesh.
Scene meshScene()
{
    Scene scene;
    scene.fps = 30.0;
    scene.startTime = -1.0;
    scene.endTime = 4.0;
    scene.currentTime = 1.25;
    const auto mesh = tetrahedron();
    scene.objects.push_back(object(7, "top", InterpolationMethod::Squad, 5));
    scene.objects.push_back(object(9, "screw", InterpolationMethod::Screw, 4));
    scene.objects.back().track.subdivision = {SubdivisionScheme::BSpline, 3, true, false};
    for (SceneObject& each : scene.objects)
        each.mesh = mesh;
    scene.nextObjectId = 10;
    return scene;
}

// Sketch-editing state of every kind, and a fitted curve that gives the orientation inside its span.
Scene sketchScene()
{
    Scene scene;
    scene.objects.push_back(object(1, "sketched", InterpolationMethod::Hermite, 5));
    model::SketchState& sketch = scene.objects.back().track.sketch;
    sketch.directionStrokes.push_back({{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)}, {}});
    sketch.directionStrokes.push_back({{Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0.6, 0.8)}, {0.25, 1.5}});
    sketch.magnitude = {{0.0, 1.0}, {1.0, 2.5}, {2.0, 0.0}};
    sketch.pattern = {{0, 0}, {0.5, 0.2}, {1, 0}};
    sketch.patternRepeat = 3;
    sketch.window = std::pair{0.25, 1.75};
    sketch.alpha = 0.01;
    sketch.delta = 0.05;
    for (int i = 0; i < 4; ++i)
        sketch.fittedCurve.push_back({0.25 + 0.5 * i, turn(30.0 * i, Eigen::Vector3d(0, 1, 1)),
                                      Eigen::Quaterniond(0.0, 0.1 * i, -0.2, 0.05)});
    scene.nextObjectId = 2;
    return scene;
}

// The JSON examples of docs/file-format.md: a version 2 project and a version 1 one, the text
// formats Gyre still reads.
std::vector<QByteArray> documentedTextProjects()
{
    QFile document(QStringLiteral(GYRE_SOURCE_DIR "/docs/file-format.md"));
    if (!document.open(QIODevice::ReadOnly))
        throw std::runtime_error("cannot read docs/file-format.md");
    const QByteArray text = document.readAll();
    std::vector<QByteArray> examples;
    for (qsizetype start = text.indexOf("```json\n"); start >= 0; start = text.indexOf("```json\n", start)) {
        start += 8;
        examples.push_back(text.mid(start, text.indexOf("```", start) - start));
    }
    if (examples.size() != 2)
        throw std::runtime_error("docs/file-format.md no longer holds the two JSON examples");
    return examples;
}

// The mesh scene with its screw track the child of its squad track: a hierarchy for the scene formats.
Scene exchangeScene()
{
    Scene scene = meshScene();
    scene.objects.back().parent = scene.objects.front().id;
    return scene;
}

std::vector<Seed> projectSeeds()
{
    return {{QStringLiteral("keyed.gyre"), Reader::Project, model::projectBytes(keyedScene())},
            {QStringLiteral("mesh.gyre"), Reader::Project, model::projectBytes(meshScene())},
            {QStringLiteral("sketch.gyre"), Reader::Project, model::projectBytes(sketchScene())},
            {QStringLiteral("version-2.gyre"), Reader::Project, documentedTextProjects()[0]},
            {QStringLiteral("version-1.gyre"), Reader::Project, documentedTextProjects()[1]}};
}

void writeFile(const QString& path, const QByteArray& bytes)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(bytes) != bytes.size())
        throw std::runtime_error("cannot write the fuzz input " + path.toStdString());
}

std::string describe(const Eigen::Vector3d& v)
{
    return std::to_string(v.x()) + ' ' + std::to_string(v.y()) + ' ' + std::to_string(v.z());
}

std::vector<double> evaluationTimes(const Scene& scene, const model::MotionTrack& track)
{
    std::vector<double> times{scene.startTime, scene.endTime, scene.currentTime, 0.5 * (scene.startTime + scene.endTime),
                              scene.startTime - 1.0, scene.endTime + 1.0};
    // Each key, and a little before and after it; at most a handful of keys, spread over the track.
    const std::size_t step = std::max<std::size_t>(1, track.keys.size() / 8);
    for (std::size_t i = 0; i < track.keys.size(); i += step)
        for (const double offset : {-1e-3, 0.0, 1e-3})
            times.push_back(track.keys[i].time + offset);
    for (const HermiteControlPoint& point : track.sketch.fittedCurve)
        times.push_back(point.time);
    return times;
}

// What is wrong with the first value that is not finite, or nothing.
std::optional<std::string> evaluateTracks(const Scene& scene, Outcome& outcome)
{
    for (const SceneObject& each : scene.objects) {
        std::optional<model::TrackMotion> motion;
        try {
            motion.emplace(each.track);
        } catch (const std::invalid_argument&) {
            ++outcome.tracksRefusedByEvaluation;
            continue;
        }
        ++outcome.tracksEvaluated;
        for (const double time : evaluationTimes(scene, each.track)) {
            const Pose pose = motion->at(time);
            const Eigen::Vector3d omega = motion->angularVelocity(time);
            if (!pose.orientation.coeffs().allFinite() || !pose.position.allFinite() || !omega.allFinite())
                return "object " + std::to_string(each.id) + " at time " + std::to_string(time) +
                       ": orientation (xyzw) " + describe(pose.orientation.vec()) + ' ' +
                       std::to_string(pose.orientation.w()) + ", position " + describe(pose.position) +
                       ", angular velocity " + describe(omega);
        }
    }
    return std::nullopt;
}

} // namespace

std::vector<Seed> makeSceneSeeds(const QString& scratchDir)
{
    std::vector<Seed> seeds;
    for (const SceneFormat format : {SceneFormat::Glb, SceneFormat::Collada, SceneFormat::Fbx, SceneFormat::Obj}) {
        const std::string_view extension = nameOf(kSceneFormatNames, format);
        const QString fileName = QStringLiteral("scene.") + QLatin1String(extension.data(), extension.size());
        const QString path = QDir(scratchDir).filePath(fileName);
        exportScene(exchangeScene(), path, format, 10.0);
        seeds.push_back({fileName, Reader::Scene, contentsOf(path)});
    }
    seeds.push_back({QStringLiteral("capture.bvh"), Reader::Scene, test::bvhChain(3, 6, 1.0 / 30.0)});
    return seeds;
}

std::vector<Seed> makeSeeds(const QString& scratchDir)
{
    std::vector<Seed> seeds = poseSeeds(scratchDir);
    for (std::vector<Seed> more : {numberSeeds(), projectSeeds()})
        seeds.insert(seeds.end(), more.begin(), more.end());
    return seeds;
}

Outcome readInput(Reader reader, const QByteArray& bytes, const QString& path)
{
    writeFile(path, bytes);
    Outcome outcome;
    try {
        switch (reader) {
        case Reader::PoseCsv:
            readPoseCsv(path, EulerConvention{});
            break;
        case Reader::NumberCsv:
            readNumberCsv(path, {kOmegaColumns, {}, "time"});
            break;
        case Reader::Project: {
            const Scene scene = model::readProject(path);
            outcome.accepted = true;
            outcome.evaluationProblem = evaluateTracks(scene, outcome);
            return outcome;
        }
        case Reader::Scene: {
            const Scene scene = importSceneInWorker(path, {}, kSceneWorkerLimits).scene;
            outcome.accepted = true;
            outcome.evaluationProblem = evaluateTracks(scene, outcome);
            return outcome;
        }
        }
    } catch (const InputError& refusal) {
        outcome.refusal = refusal.what();
        return outcome;
    }
    outcome.accepted = true;
    return outcome;
}

std::optional<std::string> refusalProblem(Reader reader, const std::string& message, const QString& path)
{
    const std::string prefix = path.toStdString();
    if (!message.starts_with(prefix))
        return "does not begin with the file's path " + prefix;
    const QString rest = QString::fromStdString(message.substr(prefix.size()));
    // CSV: `path:line: what`. Project: `path: field: what`, `path: the top level: what`, or the JSON
    // parser's `path: not valid JSON: what at byte N`, or `path: is empty; ...`. Scene: `path: what`.
    static const QRegularExpression csvPlace(QStringLiteral("^:[1-9][0-9]*: \\S"));
    static const QRegularExpression scenePlace(QStringLiteral("^: \\S"));
    static const QRegularExpression projectPlace(
        QStringLiteral("^: (([A-Za-z]+(\\[[0-9]+\\])*)(\\.[A-Za-z]+(\\[[0-9]+\\])*)*: \\S|the top level: \\S|"
                       "not valid JSON: .* at byte [0-9]+$|is empty; )"));
    if (reader == Reader::Scene)
        return scenePlace.match(rest).hasMatch() ? std::nullopt : std::optional<std::string>("says nothing after the path");
    const QRegularExpression& place = reader == Reader::Project ? projectPlace : csvPlace;
    if (!place.match(rest).hasMatch())
        return "names no " + std::string(reader == Reader::Project ? "field" : "line") + " after the path";
    return std::nullopt;
}

} // namespace gyre::fuzz
