// Every glTF Gyre writes passes the Khronos glTF validator (npm gltf-validator, run by node through
// validate_gltf.mjs), and Gyre imports it back with its sampled times: the bundled samples and
// hostile projects (keys 1e-9 s apart, times near 1e6 s, times before 0 s, a single key, an Empty, a
// skinned mesh, UTF-8 names), each exported with the real gyre-cli as .glb and as .gltf. An Empty comes
// back an Empty, and a skinned mesh with a skin that puts its positions where Gyre's skinning did.

#include "cli_test_support.h"
#include "model/motion_cache.h"
#include "model/project_file.h"
#include "model/scene_motion.h"
#include "model/skinning.h"
#include "model/track_evaluation.h"

#include <QDir>
#include <QProcess>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <set>

using namespace gyre;
using gyre::test::CliTestCase;

namespace {

Pose pose(double angle, const Eigen::Vector3d& axis, const Eigen::Vector3d& position)
{
    return {Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized())), position};
}

std::shared_ptr<const model::Mesh> triangle()
{
    auto mesh = std::make_shared<model::Mesh>();
    mesh->positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh->indices = {0, 1, 2};
    return mesh;
}

model::SceneObject object(model::ObjectId id, const QString& name, std::vector<model::Keyframe> keys,
                          model::ObjectId parent = model::kNoObject, bool withMesh = true)
{
    model::SceneObject result;
    result.id = id;
    result.name = name;
    result.parent = parent;
    result.mesh = withMesh ? triangle() : nullptr;
    result.track.keys = std::move(keys);
    result.track.interpolation = InterpolationMethod::Slerp;
    return result;
}

model::Scene scene(std::vector<model::SceneObject> objects, double start, double end, double fps)
{
    model::Scene result;
    result.fps = fps;
    result.startTime = start;
    result.endTime = end;
    result.currentTime = start;
    result.nextObjectId = objects.size() + 1;
    result.objects = std::move(objects);
    return result;
}

const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();
const Eigen::Vector3d kTilted(1, 2, 3);

// Keys 1e-9 s apart, three within one float32 step at 0.5 s (6e-8 s), the first on a frame (0.5 s
// at 24 fps), and keys 3e-8 s apart at 0.75 s.
model::Scene closeKeys()
{
    return scene({object(1, "close", {{0.0, pose(0.0, kZ, {0, 0, 0})},
                                      {0.5, pose(1.0, kZ, {1, 0, 0})},
                                      {0.5 + 1e-9, pose(1.5, kTilted, {1, 1, 0})},
                                      {0.5 + 2e-9, pose(2.0, kTilted, {1, 2, 0})},
                                      {0.75, pose(2.5, kZ, {0, 2, 0})},
                                      {0.75 + 3e-8, pose(3.0, kZ, {0, 3, 0})},
                                      {1.0, pose(0.5, kTilted, {0, 0, 1})}})},
                 0.0, 1.0, 24.0);
}

// The last 2 s before 1e6 s, the latest time a project holds: there a float32 step is 1/16 s, so
// frames at 30 fps, 1/30 s apart, collide two by two.
model::Scene farTimes()
{
    const double t0 = 1e6 - 2.0;
    return scene({object(1, "far", {{t0, pose(0.0, kZ, {0, 0, 0})},
                                    {t0 + 0.3, pose(1.0, kTilted, {1, 0, 0})},
                                    {t0 + 0.3 + 1e-9, pose(1.2, kTilted, {1, 0, 0})},
                                    {1e6, pose(2.0, kZ, {0, 1, 0})}})},
                 t0, 1e6, 30.0);
}

// glTF times cannot be negative: the scene is written from 0 s.
model::Scene negativeTimes()
{
    return scene({object(1, "early", {{-1.5, pose(0.0, kZ, {0, 0, 0})},
                                      {-1e-9, pose(1.0, kTilted, {0, 1, 0})},
                                      {0.0, pose(1.1, kTilted, {0, 1, 0})},
                                      {0.5, pose(2.0, kZ, {1, 0, 0})}})},
                 -1.5, 0.5, 24.0);
}

model::Scene singleKey()
{
    return scene({object(1, "still", {{0.25, pose(0.7, kTilted, {1, 2, 3})}})}, 0.0, 1.0, 24.0);
}

Eigen::Matrix4f matrixOf(const Pose& pose)
{
    Eigen::Matrix4f result = Eigen::Matrix4f::Identity();
    result.topLeftCorner<3, 3>() = pose.orientation.toRotationMatrix().cast<float>();
    result.topRightCorner<3, 1>() = pose.position.cast<float>();
    return result;
}

// A moving Empty whose child has a mesh, skinned to two moving joints (Root, and Tip on it) from their
// poses at 0 s: one position follows Root, one both, and one Tip by 0.3 and its own object by the rest.
model::Scene emptyAndSkin()
{
    model::Scene result =
        scene({object(1, "empty", {{0.0, pose(0.0, kZ, {0, 0, 0})}, {1.0, pose(3.0, kZ, {2, 0, 0})}}, model::kNoObject, false),
               object(2, "child", {{0.0, pose(0.0, kTilted, {1, 0, 0})}, {0.5, pose(1.0, kTilted, {1, 0, 0})}}, 1),
               object(3, "Root", {{0.0, pose(0.0, kZ, {0, 1, 0})}, {1.0, pose(1.2, kZ, {0, 1, 0})}}, model::kNoObject, false),
               object(4, "Tip", {{0.0, pose(0.0, kTilted, {1, 0, 0})}, {1.0, pose(0.8, kTilted, {1, 0, 0})}}, 3, false)},
              0.0, 1.0, 25.0);
    result.objects[0].empty = true;
    const model::SceneMotion motion(result, [](const model::SceneObject& o) {
        return std::make_shared<const model::SharedTrackMotion>(o.track);
    });
    auto mesh = std::make_shared<model::Mesh>(*result.objects[1].mesh);
    mesh->skin.joints = {3, 4};
    for (const model::ObjectId joint : mesh->skin.joints)
        mesh->skin.inverseBinds.push_back(matrixOf(motion.worldPose(joint, 0.0).inverse() * motion.worldPose(2, 0.0)));
    mesh->skin.vertexJoints = {{0, 0, 0, 0}, {0, 1, 0, 0}, {1, 0, 0, 0}};
    mesh->skin.vertexWeights = {{1, 0, 0, 0}, {0.5F, 0.5F, 0, 0}, {0.3F, 0, 0, 0}};
    result.objects[1].mesh = mesh;
    return result;
}

// The world positions of the object's skinned mesh at `time`.
std::vector<Eigen::Vector3d> skinnedWorld(const model::Scene& scene, const model::SceneObject& object, double time)
{
    const model::SceneMotion motion(scene, [](const model::SceneObject& o) {
        return std::make_shared<const model::SharedTrackMotion>(o.track);
    });
    const Pose at = motion.worldPose(object.id, time);
    std::vector<Eigen::Vector3d> result;
    for (const Eigen::Vector3f& p :
         model::skinnedPositions(*object.mesh, model::jointMatrices(object.mesh->skin, object.id, motion, time)))
        result.push_back(at.apply(p.cast<double>()));
    return result;
}

model::Scene utf8Names()
{
    return scene({object(1, QString::fromUtf8("Würfel ✓"), {{0.0, pose(0.0, kZ, {0, 0, 0})}, {1.0, pose(2.0, kZ, {0, 0, 0})}}),
                  object(2, QString::fromUtf8("日本語 の 名前"), {{0.0, pose(0.0, kTilted, {0, 1, 0})}, {1.0, pose(1.0, kTilted, {0, 1, 0})}}, 1),
                  object(3, QString::fromUtf8("ελληνικά, spaces & \"quotes\""), {{0.0, pose(0.4, kZ, {2, 0, 0})}}, 1)},
                 0.0, 1.0, 24.0);
}

// The times Gyre bakes for `track` over the scene's range, moved to start at 0 if the scene starts
// before, as Gyre's import reads them back from glTF, without repeats: Assimp's reader takes each as
// float32 seconds times 1000 in float32, milliseconds. Whichever sample of a collision was kept, these
// are what the file must give.
std::vector<double> timesAsReadBack(const model::MotionTrack& track, const model::Scene& scene)
{
    const double shift = std::max(0.0, -scene.startTime);
    std::set<float> milliseconds;
    for (const double time : model::bakeTimes(model::keyTimes(track), {scene.startTime, scene.endTime, scene.fps}))
        milliseconds.insert(static_cast<float>(static_cast<float>(time + shift) * 1000.0f));
    std::vector<double> result;
    for (const float ms : milliseconds)
        result.push_back(static_cast<double>(ms) / 1000.0);
    return result;
}

double float32Step(double time)
{
    const auto single = static_cast<float>(time);
    return static_cast<double>(std::nextafter(std::abs(single), std::numeric_limits<float>::infinity()) - std::abs(single));
}

const model::SceneObject* named(const model::Scene& scene, const QString& name)
{
    for (const model::SceneObject& object : scene.objects)
        if (object.name == name)
            return &object;
    return nullptr;
}

} // namespace

class TestGltfValidator : public CliTestCase {
    Q_OBJECT

    // Runs the validator on `files`; true if it finds no error, else prints its report.
    static bool validates(const QStringList& files)
    {
        QProcess node;
        node.setProcessChannelMode(QProcess::MergedChannels);
        node.start(QStringLiteral(GYRE_NODE_PATH),
                   QStringList{GYRE_VALIDATE_GLTF_SCRIPT, "--validator", GYRE_GLTF_VALIDATOR_PREFIX} + files);
        const bool finished = node.waitForFinished(120'000);
        const QString report = QString::fromUtf8(node.readAll());
        if (finished && node.exitStatus() == QProcess::NormalExit && node.exitCode() == 0)
            return true;
        qWarning("validate_gltf.mjs: %s", qPrintable(report));
        return false;
    }

private slots:
    void validatesAndImportsBack_data()
    {
        QTest::addColumn<QString>("project");
        const QFileInfoList samples = QDir(GYRE_SAMPLES_DIR).entryInfoList({"*.gyre"}, QDir::Files, QDir::Name);
        QVERIFY2(!samples.isEmpty(), GYRE_SAMPLES_DIR);
        for (const QFileInfo& sample : samples)
            QTest::newRow(qPrintable(sample.fileName())) << sample.filePath();
        const std::pair<const char*, model::Scene> hostile[] = {
            {"keys 1e-9 s apart", closeKeys()}, {"times near 1e6 s", farTimes()},
            {"times before 0 s", negativeTimes()}, {"a single key", singleKey()},
            {"an Empty and a skinned mesh", emptyAndSkin()}, {"UTF-8 names", utf8Names()}};
        for (const auto& [name, project] : hostile) {
            const QString file = path(QString(name).replace(' ', '_') + ".gyre");
            model::writeProject(file, project);
            QTest::newRow(name) << file;
        }
    }

    // Exported as .glb and as .gltf, the project validates without error, imports back, and each
    // moving object's keys are at the times Gyre bakes as float32 seconds (read back as Assimp does),
    // each once, within a float32 step of the seconds.
    void validatesAndImportsBack()
    {
        QFETCH(QString, project);
        const model::Scene original = model::readProject(project);
        QVERIFY(!original.objects.empty());
        const QStringList exported{path("exported.glb"), path("exported.gltf")};
        for (const QString& file : exported)
            QVERIFY(succeeds({"export", project, "-o", file}));
        QVERIFY(validates(exported));

        for (const QString& file : exported) {
            const QString back = file + ".gyre";
            QVERIFY(succeeds({"import", file, "-o", back, "--time-origin", "file"}));
            const model::Scene imported = model::readProject(back);
            for (const model::SceneObject& object : original.objects) {
                const model::SceneObject* again = named(imported, object.name);
                QVERIFY2(again, qPrintable(object.name));
                if (object.empty)
                    QVERIFY2(again->empty, qPrintable(object.name + " is no longer an Empty"));
                if (object.mesh && !object.mesh->skin.empty()) {
                    QVERIFY2(again->mesh && !again->mesh->skin.empty(), qPrintable(object.name + " lost its skin"));
                    for (const double time : {0.25, 0.75}) {
                        const std::vector<Eigen::Vector3d> expected = skinnedWorld(original, object, time);
                        const std::vector<Eigen::Vector3d> skinned = skinnedWorld(imported, *again, time);
                        QCOMPARE(skinned.size(), expected.size());
                        for (std::size_t v = 0; v < expected.size(); ++v)
                            QVERIFY2((skinned[v] - expected[v]).norm() < 1e-4,
                                     qPrintable(QString("%1 vertex %2 at %3 s").arg(file).arg(v).arg(time)));
                    }
                }
                if (object.track.keys.size() < 2 && object.track.sketch.fittedCurve.empty())
                    continue; // written without animation
                const std::vector<double> expected = timesAsReadBack(object.track, original);
                const std::vector<double> times = model::keyTimes(again->track);
                QCOMPARE(times.size(), expected.size());
                for (std::size_t k = 0; k < times.size(); ++k)
                    QVERIFY2(std::abs(times[k] - expected[k]) <= float32Step(expected[k]),
                             qPrintable(QString("%1 %2: key %3 at %4 s, expected %5 s")
                                            .arg(file, object.name)
                                            .arg(k)
                                            .arg(times[k], 0, 'g', 17)
                                            .arg(expected[k], 0, 'g', 17)));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestGltfValidator)
#include "tst_gltf_validator.moc"
