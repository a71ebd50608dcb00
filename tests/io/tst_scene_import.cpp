// Scene import: Assimp scenes written in code (assbin keeps every double as given) and a BVH file
// written in code, imported and compared with values worked out independently here; and hostile
// files, which must give an InputError naming the file and nothing else.

#include "bvh_fixture.h"
#include "io/scene_export.h"
#include "io/scene_import.h"
#include "scene_test_support.h"

#include <QDir>
#include <QFile>
#include <QObject>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <random>

using namespace gyre;
using namespace gyre::io;
using namespace gyre::test;

namespace {

// Assimp keeps rotations and positions in single precision.
constexpr double kFloatTolerance = 1e-6;

// The file's poses as they are: taken as Z-up, Gyre's world, so nothing is turned. The tests of keys,
// hierarchy and scale use it; a file's up axis is tested on its own (bvhStandsUp, tst_blender_fixtures).
SceneImport importAsIs(const QString& file)
{
    ImportOptions options;
    options.up = UpAxis::Z;
    return importScene(file, options);
}

const model::SceneObject* objectNamed(const model::Scene& scene, const QString& name)
{
    for (const model::SceneObject& object : scene.objects)
        if (object.name == name)
            return &object;
    return nullptr;
}

Eigen::Quaterniond aboutZd(double angle) { return axisAngleQuaternion(Eigen::Vector3d::UnitZ(), angle); }

void writeFile(const QString& path, const QByteArray& bytes)
{
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    QCOMPARE(file.write(bytes), bytes.size());
}

QByteArray readFile(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// An animated scene of two objects with meshes, exported by Gyre: the material the damaged files
// are made from.
model::Scene smallAnimatedScene()
{
    auto mesh = std::make_shared<model::Mesh>();
    mesh->positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh->indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    model::Scene scene;
    scene.endTime = 1.0;
    for (int i = 0; i < 2; ++i) {
        model::SceneObject object;
        object.id = scene.nextObjectId++;
        object.name = QStringLiteral("part%1").arg(i);
        object.parent = i == 0 ? model::kNoObject : 1;
        object.mesh = mesh;
        object.track.keys = {{0.0, {aboutZd(0.1 * i), {0, 0, 0}}, true}, {1.0, {aboutZd(1.0), {1, 2, 3}}, true}};
        scene.objects.push_back(object);
    }
    return scene;
}

} // namespace

class TstSceneImport : public QObject {
    Q_OBJECT

private slots:
    void keysAtTheUnionOfRotationAndPositionTimes();
    void defaultTicksPerSecond();
    void hierarchyMeshesAndStaticNodes();
    void rootThatCarriesSomethingIsAnObject();
    void scaleIsBakedIntoMeshesAndPositions();
    void scaleThatCannotBeKeptIsReported();
    void refusesKeysItCannotUse_data();
    void refusesKeysItCannotUse();
    void choosesAmongAnimations();
    void plansTakes_data();
    void plansTakes();
    void frameRateFromTheKeys_data();
    void frameRateFromTheKeys();
    void bvhKeysComeThroughExactly();
    void bvhStandsUp();
    void missingEmptyAndDirectory();
    void meshThatIsNotFiniteIsRefusedNamingItsNode();
    void randomBytes_data();
    void randomBytes();
    void truncatedAndBitFlippedExports_data();
    void truncatedAndBitFlippedExports();

private:
    QString path(const QString& name) const { return directory_.filePath(name); }
    QTemporaryDir directory_;
};

// Rotation keys at ticks 0, 10, 20 (angles about z 0, 0.6, 1.0), position keys at ticks 5, 20, 30,
// 10 ticks per second: keyframes at 0, 0.5, 1, 2 and 3 s. Between rotation keys about one axis slerp
// turns the angle linearly; positions are linear; both are held outside their keys.
void TstSceneImport::keysAtTheUnionOfRotationAndPositionTimes()
{
    auto scene = emptyAssimpScene();
    addNode(*scene->mRootNode, "joint");
    const std::vector<aiVector3D> p{{1, 0, 0}, {1, 2, 0}, {4, 2, 1}};
    setAnimations(*scene, {animation("take", 10.0, 30.0,
                                     {nodeAnimation("joint", {{0, aboutZ(0.0)}, {10, aboutZ(0.6)}, {20, aboutZ(1.0)}},
                                                    {{5, p[0]}, {20, p[1]}, {30, p[2]}})})});
    writeAssbin(*scene, path("union.assbin"));
    const SceneImport imported = importAsIs(path("union.assbin"));

    QCOMPARE(imported.scene.objects.size(), std::size_t{1});
    const model::MotionTrack& track = imported.scene.objects[0].track;
    QCOMPARE(track.interpolation, InterpolationMethod::Slerp);
    const struct {
        double time;
        double angle;
        Eigen::Vector3d position;
    } expected[] = {{0.0, 0.0, {1, 0, 0}},
                    {0.5, 0.3, {1, 0, 0}},
                    {1.0, 0.6, Eigen::Vector3d(1, 0, 0) + (5.0 / 15.0) * Eigen::Vector3d(0, 2, 0)},
                    {2.0, 1.0, {1, 2, 0}},
                    {3.0, 1.0, {4, 2, 1}}};
    QCOMPARE(track.keys.size(), std::size_t{5});
    for (std::size_t i = 0; i < 5; ++i) {
        QCOMPARE(track.keys[i].time, expected[i].time);
        QVERIFY(distanceUpToSign(track.keys[i].pose.orientation, aboutZd(expected[i].angle)) < kFloatTolerance);
        QVERIFY((track.keys[i].pose.position - expected[i].position).norm() < kFloatTolerance);
    }
    QCOMPARE(imported.scene.startTime, 0.0);
    QCOMPARE(imported.scene.endTime, 3.0);
}

void TstSceneImport::defaultTicksPerSecond()
{
    auto scene = emptyAssimpScene();
    addNode(*scene->mRootNode, "joint");
    setAnimations(*scene, {animation("", 0.0, 50.0, {nodeAnimation("joint", {{0, aboutZ(0)}, {50, aboutZ(1)}}, {})})});
    writeAssbin(*scene, path("no-rate.assbin"));
    const SceneImport imported = importScene(path("no-rate.assbin"));
    const model::MotionTrack& track = imported.scene.objects.at(0).track;
    QCOMPARE(track.keys.size(), std::size_t{2});
    QCOMPARE(track.keys[1].time, 50.0 / kDefaultTicksPerSecond);
    QCOMPARE(imported.animations.at(0).durationSeconds, 50.0 / kDefaultTicksPerSecond);
}

// root (identity, no mesh: left out) → body (meshes 0 and 1) → head (mesh 1); root → lamp.
void TstSceneImport::hierarchyMeshesAndStaticNodes()
{
    auto scene = emptyAssimpScene();
    const aiVector3D offsets[] = {{0, 0, 0}, {5, 0, 0}};
    setMeshes(*scene, {triangleMesh(offsets[0]), triangleMesh(offsets[1])});
    aiMatrix4x4 bodyTransform;
    aiMatrix4x4::Translation({1, 2, 3}, bodyTransform);
    aiNode* body = addNode(*scene->mRootNode, "body", bodyTransform);
    attachMeshes(*body, {0, 1});
    aiMatrix4x4 headTransform;
    aiMatrix4x4::RotationZ(0.5f, headTransform);
    attachMeshes(*addNode(*body, "head", headTransform), {1});
    addNode(*scene->mRootNode, "lamp");
    writeAssbin(*scene, path("hierarchy.assbin"));
    const SceneImport imported = importAsIs(path("hierarchy.assbin"));

    const std::vector<model::SceneObject>& objects = imported.scene.objects;
    QCOMPARE(objects.size(), std::size_t{3});
    QCOMPARE(objects[0].name, QStringLiteral("body"));
    QCOMPARE(objects[1].name, QStringLiteral("head"));
    QCOMPARE(objects[2].name, QStringLiteral("lamp"));
    QCOMPARE(objects[0].parent, model::kNoObject);
    QCOMPARE(objects[1].parent, objects[0].id);
    QCOMPARE(objects[2].parent, model::kNoObject);
    QVERIFY(objects[0].id != objects[1].id && objects[1].id != objects[2].id && objects[0].id != model::kNoObject);
    QVERIFY(imported.animations.empty());

    const auto triangleAt = [](const aiVector3D& o) {
        model::Mesh mesh;
        mesh.positions = {{o.x, o.y, o.z}, {o.x + 1, o.y, o.z}, {o.x, o.y + 1, o.z}};
        mesh.indices = {0, 1, 2};
        return canonicalTriangles(mesh);
    };
    std::vector<Triangle> both = triangleAt(offsets[0]);
    const std::vector<Triangle> second = triangleAt(offsets[1]);
    both.insert(both.end(), second.begin(), second.end());
    QVERIFY(triangleDistance(canonicalTriangles(*objects[0].mesh), both) < kFloatTolerance);
    QVERIFY(triangleDistance(canonicalTriangles(*objects[1].mesh), second) < kFloatTolerance);
    QCOMPARE(objects[0].mesh->normals.size(), objects[0].mesh->positions.size());
    QVERIFY(objects[2].mesh == nullptr);

    for (const model::SceneObject& object : objects)
        QCOMPARE(object.track.keys.size(), std::size_t{1});
    QVERIFY(poseDistance(objects[0].track.keys[0].pose, {Eigen::Quaterniond::Identity(), {1, 2, 3}}) < kFloatTolerance);
    QVERIFY(poseDistance(objects[1].track.keys[0].pose, {aboutZd(0.5), Eigen::Vector3d::Zero()}) < kFloatTolerance);
    // A still scene gets a new project's span, so it can be saved and keyed.
    QCOMPARE(imported.scene.startTime, 0.0);
    QCOMPARE(imported.scene.endTime, model::Scene{}.endTime);
}

void TstSceneImport::rootThatCarriesSomethingIsAnObject()
{
    auto scene = emptyAssimpScene();
    setMeshes(*scene, {triangleMesh({0, 0, 0})});
    aiMatrix4x4::Translation({0, 0, 4}, scene->mRootNode->mTransformation);
    attachMeshes(*addNode(*scene->mRootNode, "child"), {0});
    writeAssbin(*scene, path("root.assbin"));
    const SceneImport imported = importAsIs(path("root.assbin"));
    QCOMPARE(imported.scene.objects.size(), std::size_t{2});
    QCOMPARE(imported.scene.objects[0].name, QStringLiteral("root"));
    QCOMPARE(imported.scene.objects[1].parent, imported.scene.objects[0].id);
    QVERIFY((imported.scene.objects[0].track.keys[0].pose.position - Eigen::Vector3d(0, 0, 4)).norm() < kFloatTolerance);
}

// big: translate (1,0,0), scale 2; its child small: translate (0,1,0). In Assimp a vertex v of small
// is at (1,0,0) + 2·((0,1,0) + v); in Gyre big keeps (1,0,0), small moves to (0,2,0) and both meshes
// are doubled.
void TstSceneImport::scaleIsBakedIntoMeshesAndPositions()
{
    auto scene = emptyAssimpScene();
    setMeshes(*scene, {triangleMesh({0, 0, 0})});
    aiNode* big = addNode(*scene->mRootNode, "big", aiMatrix4x4({2, 2, 2}, aiQuaternion(), {1, 0, 0}));
    attachMeshes(*big, {0});
    aiMatrix4x4 smallTransform;
    aiMatrix4x4::Translation({0, 1, 0}, smallTransform);
    attachMeshes(*addNode(*big, "small", smallTransform), {0});
    writeAssbin(*scene, path("scaled.assbin"));
    const SceneImport imported = importScene(path("scaled.assbin"));

    QVERIFY2(imported.warnings.isEmpty(), qPrintable(imported.warnings.join('\n')));
    const model::SceneObject& bigObject = imported.scene.objects.at(0);
    const model::SceneObject& smallObject = imported.scene.objects.at(1);
    const Pose bigPose = bigObject.track.keys.at(0).pose;
    const Pose smallPose = smallObject.track.keys.at(0).pose;
    QVERIFY((bigPose.position - Eigen::Vector3d(1, 0, 0)).norm() < kFloatTolerance);
    QVERIFY((smallPose.position - Eigen::Vector3d(0, 2, 0)).norm() < kFloatTolerance);
    model::Mesh doubled;
    doubled.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
    doubled.indices = {0, 1, 2};
    QVERIFY(triangleDistance(canonicalTriangles(*bigObject.mesh), canonicalTriangles(doubled)) < kFloatTolerance);
    QVERIFY(triangleDistance(canonicalTriangles(*smallObject.mesh), canonicalTriangles(doubled)) < kFloatTolerance);
    QVERIFY(bigObject.mesh == smallObject.mesh); // the same meshes at the same scale are shared
}

void TstSceneImport::scaleThatCannotBeKeptIsReported()
{
    auto scene = emptyAssimpScene();
    aiNode* stretched = addNode(*scene->mRootNode, "stretched", aiMatrix4x4({1, 3, 1}, aiQuaternion(), {0, 0, 0}));
    addNode(*stretched, "child");
    addNode(*scene->mRootNode, "growing");
    aiNodeAnim* growing = nodeAnimation("growing", {{0, aboutZ(0)}}, {});
    growing->mNumScalingKeys = 2;
    growing->mScalingKeys = new aiVectorKey[2]{{0, {1, 1, 1}}, {1, {2, 2, 2}}};
    setAnimations(*scene, {animation("take", 1.0, 1.0, {growing, nodeAnimation("ghost", {{0, aboutZ(0)}}, {})})});
    writeAssbin(*scene, path("bad-scale.assbin"));
    const QStringList warnings = importScene(path("bad-scale.assbin")).warnings;
    QCOMPARE(warnings.size(), 3);
    QVERIFY(warnings.filter(QStringLiteral("'stretched' has a non-uniform scale")).size() == 1);
    QVERIFY(warnings.filter(QStringLiteral("'growing': its scale changes over time")).size() == 1);
    QVERIFY(warnings.filter(QStringLiteral("moves 'ghost', which is not in the scene")).size() == 1);
}

enum class KeyDamage { NanRotation, InfinitePosition, ZeroQuaternion, TimeGoingBack };

void TstSceneImport::refusesKeysItCannotUse_data()
{
    QTest::addColumn<int>("damage");
    QTest::addColumn<QString>("problem");
    QTest::newRow("nan rotation") << int(KeyDamage::NanRotation) << "rotation key 1 is not finite";
    QTest::newRow("infinite position") << int(KeyDamage::InfinitePosition) << "position key 2 is not finite";
    QTest::newRow("zero quaternion") << int(KeyDamage::ZeroQuaternion) << "rotation key 2 is not a rotation";
    QTest::newRow("time going back") << int(KeyDamage::TimeGoingBack) << "position key 1 is not after the key before it";
}

void TstSceneImport::refusesKeysItCannotUse()
{
    QFETCH(int, damage);
    QFETCH(QString, problem);
    std::vector<aiQuatKey> rotations{{0, aboutZ(0)}, {1, aboutZ(1)}, {2, aboutZ(2)}};
    std::vector<aiVectorKey> positions{{0, {0, 0, 0}}, {1, {1, 0, 0}}, {2, {2, 0, 0}}};
    switch (KeyDamage(damage)) {
    case KeyDamage::NanRotation:
        rotations[1].mValue.y = std::nanf("");
        break;
    case KeyDamage::InfinitePosition:
        positions[2].mValue.z = INFINITY;
        break;
    case KeyDamage::ZeroQuaternion:
        rotations[2].mValue = aiQuaternion(0, 0, 0, 0);
        break;
    case KeyDamage::TimeGoingBack:
        positions[1].mTime = 0;
        break;
    }
    auto scene = emptyAssimpScene();
    addNode(*scene->mRootNode, "joint");
    setAnimations(*scene, {animation("take", 1.0, 2.0, {nodeAnimation("joint", rotations, positions)})});
    const QString file = path("bad-keys.assbin");
    writeAssbin(*scene, file);
    try {
        importScene(file);
        QFAIL("imported keys it cannot use");
    } catch (const InputError& error) {
        const QString message = QString::fromStdString(error.what());
        QVERIFY2(message.startsWith(file + ": node 'joint': " + problem), qPrintable(message));
    }
}

// walk and run both move a: neither disjoint nor Blender's takes, so a choice is needed; animation 0
// is what the import holds until one is made.
void TstSceneImport::choosesAmongAnimations()
{
    auto scene = emptyAssimpScene();
    addNode(*scene->mRootNode, "a");
    addNode(*scene->mRootNode, "b");
    setAnimations(*scene, {animation("walk", 10.0, 20.0, {nodeAnimation("a", {{0, aboutZ(0)}, {20, aboutZ(1)}}, {})}),
                           animation("run", 20.0, 10.0,
                                     {nodeAnimation("a", {{0, aboutZ(0)}, {5, aboutZ(0.5)}, {10, aboutZ(2)}}, {}),
                                      nodeAnimation("b", {{0, aboutZ(0)}, {10, aboutZ(1)}}, {})})});
    const QString file = path("two-takes.assbin");
    writeAssbin(*scene, file);
    const SceneImport first = importScene(file);
    QCOMPARE(first.animations.size(), std::size_t{2});
    QCOMPARE(first.animations[0].name, QStringLiteral("walk"));
    QCOMPARE(first.animations[0].durationSeconds, 2.0);
    QCOMPARE(first.animations[0].nodes, QStringList{QStringLiteral("a")});
    QCOMPARE(first.animations[1].name, QStringLiteral("run"));
    QCOMPARE(first.animations[1].durationSeconds, 0.5);
    QCOMPARE(first.animations[1].nodes, (QStringList{QStringLiteral("a"), QStringLiteral("b")}));
    QCOMPARE(first.takeRule, TakeRule::ChoiceNeeded);
    QCOMPARE(first.takes, std::vector<std::size_t>{0});
    QCOMPARE(first.scene.objects[0].track.keys.size(), std::size_t{2});

    ImportOptions run;
    run.takeSelection = TakeSelection::Listed;
    run.takes = {1};
    const SceneImport second = importScene(file, run);
    QCOMPARE(second.scene.objects[0].track.keys.size(), std::size_t{3});
    QCOMPARE(second.scene.objects[0].track.keys[1].time, 0.25);
    QCOMPARE(second.scene.endTime, 0.5);
    run.takes = {2};
    QVERIFY_THROWS_EXCEPTION(InputError, importScene(file, run));

    // Merged, run then walk: walk wins a (2 keys over 2 s), run keeps b.
    ImportOptions both;
    both.takeSelection = TakeSelection::Listed;
    both.takes = {1, 0};
    const SceneImport merged = importScene(file, both);
    QCOMPARE(merged.scene.objects[0].track.keys.size(), std::size_t{2});
    QCOMPARE(merged.scene.objects[0].track.keys[1].time, 2.0);
    QCOMPARE(merged.scene.objects[1].track.keys.size(), std::size_t{2});
    QCOMPARE(merged.scene.objects[1].track.keys[1].time, 0.5);
    QCOMPARE(merged.scene.endTime, 2.0);
    QCOMPARE(merged.warnings.filter(QStringLiteral("'a' is moved by more than one")).size(), 1);
}

void TstSceneImport::plansTakes_data()
{
    QTest::addColumn<QStringList>("names");
    QTest::addColumn<QStringList>("movedNodes"); // the nodes each moves, joined by '+'
    QTest::addColumn<int>("rule");
    QTest::addColumn<QList<int>>("takes");
    QTest::newRow("none") << QStringList{} << QStringList{} << int(TakeRule::NoAnimation) << QList<int>{};
    QTest::newRow("one") << QStringList{"take"} << QStringList{"a+b"} << int(TakeRule::Single) << QList<int>{0};
    QTest::newRow("glTF, one per action") << QStringList{"AAction", "BAction", "CAction"} << QStringList{"a", "b+c", "d"}
                                          << int(TakeRule::Disjoint) << QList<int>{0, 1, 2};
    QTest::newRow("overlapping") << QStringList{"walk", "run"} << QStringList{"a", "a+b"} << int(TakeRule::ChoiceNeeded)
                                 << QList<int>{0};
    QTest::newRow("Blender's takes") << QStringList{"A|BAction", "A|AAction", "B|BAction", "B|AAction"}
                                     << QStringList{"A", "A", "B", "B"} << int(TakeRule::BlenderActions) << QList<int>{1, 2};
    // B's action is renamed "Spin": B gets it, as AAction is named after A.
    QTest::newRow("an action not named after its object")
        << QStringList{"A|AAction", "A|Spin", "B|AAction", "B|Spin"} << QStringList{"A", "A", "B", "B"}
        << int(TakeRule::BlenderActions) << QList<int>{0, 3};
    QTest::newRow("a later action of the object") << QStringList{"A|BAction", "A|AAction.001", "B|BAction", "B|AAction.001"}
                                                  << QStringList{"A", "A", "B", "B"} << int(TakeRule::BlenderActions)
                                                  << QList<int>{1, 2};
    // A take named like Blender's that moves another node is not Blender's.
    QTest::newRow("a take moving another node") << QStringList{"A|AAction", "A|BAction"} << QStringList{"A", "A+B"}
                                                << int(TakeRule::ChoiceNeeded) << QList<int>{0};
}

void TstSceneImport::plansTakes()
{
    QFETCH(QStringList, names);
    QFETCH(QStringList, movedNodes);
    QFETCH(int, rule);
    QFETCH(QList<int>, takes);
    std::vector<AnimationSummary> animations;
    for (qsizetype i = 0; i < names.size(); ++i)
        animations.push_back({names[i], 1.0, movedNodes[i].split('+')});
    const TakePlan plan = planTakes(animations);
    QCOMPARE(int(plan.rule), rule);
    QCOMPARE(plan.takes, std::vector<std::size_t>(takes.begin(), takes.end()));
    QCOMPARE(plan.warnings.size(), rule == int(TakeRule::BlenderActions) ? 1 : 0);
    if (rule == int(TakeRule::BlenderActions))
        for (const int take : takes)
            QVERIFY2(plan.warnings.front().contains(QStringLiteral("take %1 '%2'").arg(take).arg(names[take])),
                     qPrintable(plan.warnings.front()));
}

void TstSceneImport::frameRateFromTheKeys_data()
{
    QTest::addColumn<QList<double>>("ticks"); // at 600 ticks per second
    QTest::addColumn<double>("fps");
    QTest::addColumn<QString>("source");
    QTest::newRow("every frame at 30") << QList<double>{20, 40, 60, 80} << 30.0 << "every key is on a frame of 30 fps";
    QTest::newRow("sparse keys at 60") << QList<double>{0, 10, 70, 590} << 60.0 << "every key is on a frame of 60 fps";
    QTest::newRow("whole seconds") << QList<double>{0, 600, 1200} << 24.0 << "every key is on a frame of 24 fps";
    QTest::newRow("no common rate") << QList<double>{0, 7, 600} << 24.0 << "on the frames of no common rate";
}

// A format that states no frame rate gets the lowest common rate on whose frames every key falls.
void TstSceneImport::frameRateFromTheKeys()
{
    QFETCH(QList<double>, ticks);
    QFETCH(double, fps);
    QFETCH(QString, source);
    std::vector<aiQuatKey> keys;
    for (const double tick : ticks)
        keys.push_back({tick, aboutZ(tick / 1000.0)});
    auto scene = emptyAssimpScene();
    addNode(*scene->mRootNode, "joint");
    setAnimations(*scene, {animation("take", 600.0, ticks.back(), {nodeAnimation("joint", keys, {})})});
    const QString file = path("rate.assbin");
    writeAssbin(*scene, file);
    const SceneImport imported = importScene(file);
    QCOMPARE(imported.scene.fps, fps);
    QVERIFY2(imported.file.fpsSource.contains(source), qPrintable(imported.file.fpsSource));
    QCOMPARE(imported.file.values.metresPerUnit, 1.0);
    QCOMPARE(imported.file.values.up, UpAxis::Y);
}

// BVH turns each joint by its channels in file order about moving axes: Zrotation Xrotation
// Yrotation is R = Rz·Rx·Ry; frame k is at k·frame time. Every frame is a key, none added.
void TstSceneImport::bvhKeysComeThroughExactly()
{
    const int joints = 3;
    const int frames = 7;
    const double frameTime = 1.0 / 30.0;
    const QString file = path("chain.bvh");
    writeFile(file, bvhChain(joints, frames, frameTime));
    const SceneImport imported = importAsIs(file);
    QVERIFY(std::abs(imported.scene.fps - 1.0 / frameTime) < 1e-4); // Assimp reads the frame time as a float
    QCOMPARE(imported.file.fpsSource, QStringLiteral("the BVH frame time"));
    for (int j = 0; j < joints; ++j) {
        const model::SceneObject* joint = objectNamed(imported.scene, QStringLiteral("joint%1").arg(j));
        QVERIFY(joint);
        QCOMPARE(joint->track.keys.size(), std::size_t(frames));
        for (int k = 0; k < frames; ++k) {
            const model::Keyframe& key = joint->track.keys[std::size_t(k)];
            // Assimp reads the frame time as a float: a relative error of 6e-8.
            GYRE_CHECK(std::abs(key.time - k * frameTime) <= 1e-7 * (k * frameTime), str(key.time) + " " + str(k * frameTime));
            const auto angle = [&](int axis) { return bvhAngleDegrees(j, k, axis) * kPi / 180.0; };
            const Eigen::Matrix3d expected =
                elementaryRotation(2, angle(0)) * elementaryRotation(0, angle(1)) * elementaryRotation(1, angle(2));
            QVERIFY((key.pose.orientation.toRotationMatrix() - expected).cwiseAbs().maxCoeff() < 1e-5);
            const Eigen::Vector3d position = j == 0 ? Eigen::Vector3d(bvhRootX(k), 0, 0)
                                                    : Eigen::Vector3d(0, kBvhBoneLength, 0);
            QVERIFY((key.pose.position - position).norm() < 1e-5);
        }
    }
}

// BVH is Y-up: by default its root joint, the only top-level object, is turned +90° about X into
// Gyre's Z-up world, so the skeleton's bones, along +Y in the file, point up (+Z); the joints below
// keep their keys. Taken as Z-up it would lie on the floor.
void TstSceneImport::bvhStandsUp()
{
    const QString file = path("standing.bvh");
    writeFile(file, bvhChain(3, 4, 1.0 / 30.0));
    const SceneImport standing = importScene(file);
    const SceneImport lying = importAsIs(file);
    QCOMPARE(standing.file.values.up, UpAxis::Y);
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(kPi / 2.0, Eigen::Vector3d::UnitX()));
    for (std::size_t i = 0; i < standing.scene.objects.size(); ++i) {
        const bool topLevel = standing.scene.objects[i].parent == model::kNoObject;
        QCOMPARE(topLevel, i == 0);
        for (std::size_t k = 0; k < standing.scene.objects[i].track.keys.size(); ++k) {
            const Pose a = lying.scene.objects[i].track.keys[k].pose;
            const Pose expected = topLevel ? Pose{turn * a.orientation, turn * a.position} : a;
            QVERIFY(poseDistance(standing.scene.objects[i].track.keys[k].pose, expected) < 1e-12);
        }
    }
    // Up in the file is up in Gyre: the first bone's height above the floor (its y in the file, Y-up)
    // is its z in Gyre, and its depth (z in the file, toward the viewer) is −y.
    const Eigen::Vector3d bone = standing.scene.objects[0].track.keys[0].pose.orientation * Eigen::Vector3d::UnitY();
    const Eigen::Vector3d fileBone = lying.scene.objects[0].track.keys[0].pose.orientation * Eigen::Vector3d::UnitY();
    QVERIFY(std::abs(bone.z() - fileBone.y()) < 1e-12 && std::abs(bone.y() + fileBone.z()) < 1e-12);
}

void TstSceneImport::missingEmptyAndDirectory()
{
    writeFile(path("empty.fbx"), {});
    QDir(directory_.path()).mkdir(QStringLiteral("folder.dae"));
    for (const QString& file : {path("missing.glb"), path("empty.fbx"), path("folder.dae")}) {
        try {
            importScene(file);
            QFAIL(qPrintable(file + " imported"));
        } catch (const InputError& error) {
            QVERIFY2(QString::fromStdString(error.what()).startsWith(file + ": "), error.what());
        }
    }
}

// Found by tst_fuzz_readers: a vertex that overflows float came through the worker, whose parent then
// refused its reply as malformed, blaming Gyre for the file.
void TstSceneImport::meshThatIsNotFiniteIsRefusedNamingItsNode()
{
    const QString file = path(QStringLiteral("overflowing-vertex.obj"));
    writeFile(file, "o plate\nv 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n");
    try {
        importScene(file);
        QFAIL("a vertex at infinity was imported");
    } catch (const InputError& error) {
        const QString message = QString::fromUtf8(error.what());
        QVERIFY2(message.startsWith(file + QStringLiteral(": node '")), error.what());
        QVERIFY2(message.contains(QStringLiteral("mesh position is not finite")), error.what());
    }
}

void TstSceneImport::randomBytes_data()
{
    QTest::addColumn<QString>("extension");
    for (const char* extension : {"fbx", "obj", "gltf", "glb", "dae", "bvh", "x", "3ds", "ase", "assbin", "bin"})
        QTest::newRow(extension) << QString::fromLatin1(extension);
}

void TstSceneImport::randomBytes()
{
    QFETCH(QString, extension);
    std::mt19937 random(0x5eed);
    for (const int size : {1, 16, 300, 5000}) {
        QByteArray bytes(size, '\0');
        for (char& byte : bytes)
            byte = static_cast<char>(random() & 0xff);
        const QString file = path(QStringLiteral("random-%1.%2").arg(size).arg(extension));
        writeFile(file, bytes);
        try {
            importScene(file);
            QFAIL(qPrintable(file + " imported"));
        } catch (const InputError& error) {
            QVERIFY2(QString::fromStdString(error.what()).startsWith(file + ": "), error.what());
        }
    }
}

void TstSceneImport::truncatedAndBitFlippedExports_data()
{
    QTest::addColumn<QString>("extension");
    for (const char* extension : {"glb", "gltf", "dae", "fbx"})
        QTest::newRow(extension) << QString::fromLatin1(extension);
}

// A damaged file may still happen to read as a scene (a flipped bit in a coordinate, a cut after the
// last element Assimp needs); what may not happen is a crash, an error of another kind, or an error
// that does not name the file. Most truncations must fail.
void TstSceneImport::truncatedAndBitFlippedExports()
{
    QFETCH(QString, extension);
    const QString original = path("intact." + extension);
    exportScene(smallAnimatedScene(), original, *sceneFormatOfPath(original), 24.0);
    const QByteArray intact = readFile(original);
    QVERIFY(!intact.isEmpty());
    QCOMPARE(importScene(original).scene.objects.size(), std::size_t{2});

    std::vector<QByteArray> damaged;
    for (const double fraction : {0.05, 0.25, 0.5, 0.75, 0.95})
        damaged.push_back(intact.left(static_cast<qsizetype>(fraction * static_cast<double>(intact.size()))));
    std::mt19937 random(0xb17f11b);
    for (int variant = 0; variant < 40; ++variant) {
        QByteArray flipped = intact;
        for (int flip = 0; flip < 1 + variant % 4; ++flip) {
            const auto bit = random() % (static_cast<unsigned>(flipped.size()) * 8);
            flipped[bit / 8] = static_cast<char>(flipped[bit / 8] ^ (1 << (bit % 8)));
        }
        damaged.push_back(flipped);
    }
    int truncationsRefused = 0;
    for (std::size_t i = 0; i < damaged.size(); ++i) {
        const QString file = path(QStringLiteral("damaged-%1.%2").arg(i).arg(extension));
        writeFile(file, damaged[i]);
        try {
            importScene(file);
        } catch (const InputError& error) {
            QVERIFY2(QString::fromStdString(error.what()).startsWith(file + ": "), error.what());
            truncationsRefused += i < 5 ? 1 : 0;
        }
    }
    QVERIFY2(truncationsRefused >= 4, qPrintable(QString::number(truncationsRefused)));
}

QTEST_GUILESS_MAIN(TstSceneImport)
#include "tst_scene_import.moc"
