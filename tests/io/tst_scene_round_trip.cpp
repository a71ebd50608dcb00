// Scenes built in code, exported through Assimp and imported back: the same objects, hierarchy and
// meshes, and the same pose of every object at every frame, whatever its interpolation or fit.

#include "io/scene_export.h"
#include "io/scene_import.h"
#include "model/track_evaluation.h"
#include "scene_test_support.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QObject>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <map>

using namespace gyre;
using namespace gyre::io;
using namespace gyre::test;

namespace {

// How far a pose may move through a file. Every format stores single-precision values (relative
// error 6e-8 per number); glTF also stores times in seconds as floats (6e-8 s per second of scene),
// and FBX turns each rotation into XYZ Euler angles in degrees and back. With angular speeds of a
// few rad/s and positions within 10 units the worst of these is of the order of 1e-6; 1e-5 leaves a
// margin and still catches a wrong frame (1/24 s at 1 rad/s is 0.04) or a wrong key.
constexpr double kRoundTripTolerance = 1e-5;

Eigen::Quaterniond about(const Eigen::Vector3d& axis, double angle) { return axisAngleQuaternion(axis.normalized(), angle); }

std::shared_ptr<const model::Mesh> tetrahedron(double size)
{
    auto mesh = std::make_shared<model::Mesh>();
    mesh->positions = {{0, 0, 0}, {static_cast<float>(size), 0, 0}, {0, static_cast<float>(size), 0},
                       {0, 0, static_cast<float>(size)}};
    mesh->indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    return mesh;
}

model::SceneObject object(model::Scene& scene, const char* name, model::ObjectId parent, InterpolationMethod method,
                          std::uint64_t seed)
{
    Random random(seed);
    model::SceneObject result;
    result.id = scene.nextObjectId++;
    result.name = QString::fromLatin1(name);
    result.parent = parent;
    result.track.interpolation = method;
    for (const double time : {0.0, 0.5, 1.25, 2.0})
        result.track.keys.push_back({time, {random.rotationWithAngle(0.3, 2.5), random.vector(3.0)}, true});
    return result;
}

// Seven objects, every interpolation, a hierarchy three deep, a fit, a shared mesh and a still object.
model::Scene sceneWithEveryInterpolation()
{
    model::Scene scene;
    scene.fps = 24.0;
    scene.startTime = 0.0;
    scene.endTime = 2.0;
    const auto shared = tetrahedron(1.0);

    model::SceneObject base = object(scene, "base", model::kNoObject, InterpolationMethod::Hermite, 1);
    base.mesh = shared;
    model::SceneObject arm = object(scene, "arm", base.id, InterpolationMethod::Squad, 2);
    arm.mesh = tetrahedron(0.5);
    model::SceneObject hand = object(scene, "hand", arm.id, InterpolationMethod::Screw, 3);
    hand.track.subdivision = {SubdivisionScheme::FourPoint, 3, true, false};
    model::SceneObject spinner = object(scene, "spinner", model::kNoObject, InterpolationMethod::Euler, 4);
    spinner.mesh = shared;
    model::SceneObject wobbler = object(scene, "wobbler", spinner.id, InterpolationMethod::Nlerp, 5);
    model::SceneObject drifter = object(scene, "drifter", model::kNoObject, InterpolationMethod::Slerp, 6);
    drifter.track.sketch.fittedCurve = {{0.6, about({0, 1, 1}, 0.4), Eigen::Quaterniond(0, 0.3, -0.2, 0.5)},
                                        {1.4, about({1, 0, 1}, 1.1), Eigen::Quaterniond(0.1, 0, 0.4, 0)}};
    drifter.mesh = tetrahedron(2.0);
    model::SceneObject still = object(scene, "still", model::kNoObject, InterpolationMethod::Slerp, 7);
    still.track.keys.resize(1);
    still.mesh = tetrahedron(0.25);
    scene.objects = {base, arm, hand, spinner, wobbler, drifter, still};
    return scene;
}

QString parentName(const model::Scene& scene, const model::SceneObject& object)
{
    for (const model::SceneObject& candidate : scene.objects)
        if (candidate.id == object.parent)
            return candidate.name;
    return {};
}

// The object's pose in the world: its track composed with its ancestors'.
Pose worldPose(const model::Scene& scene, const model::SceneObject& object, double time)
{
    Pose pose = model::TrackMotion(object.track).at(time);
    for (model::ObjectId parent = object.parent; parent != model::kNoObject;) {
        const auto found = std::ranges::find(scene.objects, parent, &model::SceneObject::id);
        pose = model::TrackMotion(found->track).at(time) * pose;
        parent = found->parent;
    }
    return pose;
}

} // namespace

class TstSceneRoundTrip : public QObject {
    Q_OBJECT

private slots:
    void sameMotionAtEveryFrame_data();
    void sameMotionAtEveryFrame();
    void gltfWritesItsBufferBesideIt();
    void objKeepsTheMeshesPosedAtTheStart();
    void namesAreMadeUnique();
    void failedExportLeavesTheFileAlone();

private:
    QString path(const QString& name) const { return directory_.filePath(name); }
    QTemporaryDir directory_;
};

void TstSceneRoundTrip::sameMotionAtEveryFrame_data()
{
    QTest::addColumn<QString>("extension");
    for (const char* extension : {"gltf", "glb", "dae", "fbx"})
        QTest::newRow(extension) << QString::fromLatin1(extension);
}

void TstSceneRoundTrip::sameMotionAtEveryFrame()
{
    QFETCH(QString, extension);
    const model::Scene original = sceneWithEveryInterpolation();
    const QString file = path("every-interpolation." + extension);
    const ExportReport report = exportScene(original, file, *sceneFormatOfPath(file), original.fps);
    QVERIFY2(report.warnings.isEmpty(), qPrintable(report.warnings.join('\n')));
    const SceneImport imported = importScene(file);
    const model::Scene& back = imported.scene;

    QCOMPARE(back.objects.size(), original.objects.size());
    for (std::size_t i = 0; i < original.objects.size(); ++i) {
        const model::SceneObject& before = original.objects[i];
        const model::SceneObject& after = back.objects[i];
        QCOMPARE(after.name, before.name);
        QCOMPARE(parentName(back, after), parentName(original, before));
        QCOMPARE(bool(after.mesh), bool(before.mesh));
        if (before.mesh)
            QVERIFY(triangleDistance(canonicalTriangles(*after.mesh), canonicalTriangles(*before.mesh)) < 1e-6);

        const model::TrackMotion expected(before.track);
        const model::TrackMotion actual(after.track);
        double worst = 0.0;
        double worstTime = 0.0;
        for (int frame = 0; frame <= 48; ++frame) {
            const double time = frame / original.fps;
            const Pose a = actual.at(time);
            const Pose e = expected.at(time);
            const double distance = std::max(distanceUpToSign(a.orientation, e.orientation),
                                             (a.position - e.position).norm() / std::max(1.0, e.position.norm()));
            if (distance > worst) {
                worst = distance;
                worstTime = time;
            }
        }
        GYRE_CHECK(worst < kRoundTripTolerance,
                   QStringLiteral("%1: off by %2 at %3 s").arg(before.name, str(worst), str(worstTime)));
    }
}

void TstSceneRoundTrip::gltfWritesItsBufferBesideIt()
{
    const QString file = path("buffer.gltf");
    const ExportReport report = exportScene(sceneWithEveryInterpolation(), file, SceneFormat::Gltf, 24.0);
    QCOMPARE(report.files, (QStringList{path("buffer.bin"), file}));
    QFile gltf(file);
    QVERIFY(gltf.open(QIODevice::ReadOnly));
    QVERIFY(gltf.readAll().contains("\"buffer.bin\""));
    QVERIFY(QFileInfo(path("buffer.bin")).size() > 0);
}

// OBJ has no nodes or motion: every mesh is written in world space as posed at the start time.
void TstSceneRoundTrip::objKeepsTheMeshesPosedAtTheStart()
{
    model::Scene scene = sceneWithEveryInterpolation();
    scene.startTime = 0.7;
    const QString file = path("meshes.obj");
    const ExportReport report = exportScene(scene, file, SceneFormat::Obj, 24.0);
    QCOMPARE(report.warnings.size(), 1);
    QVERIFY(report.warnings[0].contains(QLatin1String("no motion")));

    std::vector<Triangle> expected;
    for (const model::SceneObject& object : scene.objects)
        if (object.mesh) {
            const std::vector<Triangle> posed = canonicalTriangles(*object.mesh, worldPose(scene, object, 0.7));
            expected.insert(expected.end(), posed.begin(), posed.end());
        }
    model::Mesh all;
    for (const model::SceneObject& object : importScene(file).scene.objects) {
        QVERIFY(object.mesh);
        const Pose pose = object.track.keys.at(0).pose;
        for (const std::uint32_t index : object.mesh->indices)
            all.indices.push_back(static_cast<std::uint32_t>(all.positions.size()) + index);
        for (const Eigen::Vector3f& p : object.mesh->positions)
            all.positions.push_back(pose.apply(p.cast<double>()).cast<float>());
    }
    model::Mesh reference;
    for (const Triangle& t : expected)
        for (const Eigen::Vector3d& corner : t) {
            reference.indices.push_back(static_cast<std::uint32_t>(reference.positions.size()));
            reference.positions.push_back(corner.cast<float>());
        }
    QVERIFY(triangleDistance(canonicalTriangles(all), canonicalTriangles(reference)) < 1e-5);
}

void TstSceneRoundTrip::namesAreMadeUnique()
{
    model::Scene scene;
    for (const char* name : {"twin", "twin", ""}) {
        model::SceneObject object;
        object.id = scene.nextObjectId++;
        object.name = QString::fromLatin1(name);
        object.mesh = tetrahedron(1.0);
        object.track.keys = {{0.0, {}, true}, {1.0, {about({0, 0, 1}, 1.0), {0, 0, 0}}, true}};
        scene.objects.push_back(object);
    }
    scene.endTime = 1.0;
    const QString file = path("names.glb");
    const ExportReport report = exportScene(scene, file, SceneFormat::Glb, 10.0);
    QCOMPARE(report.warnings.size(), 2);
    const SceneImport imported = importScene(file);
    QCOMPARE(imported.scene.objects.size(), std::size_t{3});
    QCOMPARE(imported.scene.objects[0].name, QStringLiteral("twin"));
    QCOMPARE(imported.scene.objects[1].name, QStringLiteral("twin_2"));
    QCOMPARE(imported.scene.objects[2].name, QStringLiteral("object_3"));
    for (const model::SceneObject& object : imported.scene.objects)
        QCOMPARE(object.track.keys.size(), std::size_t{11});
}

void TstSceneRoundTrip::failedExportLeavesTheFileAlone()
{
    const QString file = path("kept.glb");
    {
        QFile existing(file);
        QVERIFY(existing.open(QIODevice::WriteOnly));
        existing.write("old contents");
    }
    const model::Scene scene = sceneWithEveryInterpolation();
    for (const double fps : {0.0, -1.0, std::nan(""), 1e9}) {
        try {
            exportScene(scene, file, SceneFormat::Glb, fps);
            QFAIL("exported at a frame rate it should refuse");
        } catch (const OutputError& error) {
            QVERIFY2(QString::fromStdString(error.what()).startsWith(file + ": "), error.what());
        }
    }
    QFile kept(file);
    QVERIFY(kept.open(QIODevice::ReadOnly));
    QCOMPARE(kept.readAll(), QByteArray("old contents"));

    const QString nowhere = path("no-such-folder/scene.dae");
    QVERIFY_THROWS_EXCEPTION(OutputError, exportScene(scene, nowhere, SceneFormat::Collada, 24.0));
    QVERIFY(!QFileInfo::exists(nowhere));

    // A .gltf that cannot be written (a folder has its name) leaves the .bin beside it as it was: the
    // two files are written before either replaces what is there.
    QVERIFY(QDir(directory_.path()).mkpath(QStringLiteral("blocked.gltf")));
    const QString bin = path("blocked.bin");
    {
        QFile existing(bin);
        QVERIFY(existing.open(QIODevice::WriteOnly));
        existing.write("another export's buffer");
    }
    QVERIFY_THROWS_EXCEPTION(OutputError, exportScene(scene, path("blocked.gltf"), SceneFormat::Gltf, 24.0));
    QFile keptBin(bin);
    QVERIFY(keptBin.open(QIODevice::ReadOnly));
    QCOMPARE(keptBin.readAll(), QByteArray("another export's buffer"));
}

QTEST_GUILESS_MAIN(TstSceneRoundTrip)
#include "tst_scene_round_trip.moc"
