// Skinned meshes: a glTF file with a skin, written here as text (two joints and a bent bar),
// imported through gyre-scene-worker, skinned by model/skinning.h and checked against the joints'
// motion worked out here with poses; the skin survives a project saved and read back. Assimp scenes
// written in code check the four largest weights and the refusals.

#include "built_scene_worker.h"
#include "io/scene_import.h"
#include "io/scene_wire.h"
#include "io/scene_worker.h"
#include "model/project_file.h"
#include "model/skinning.h"
#include "scene_test_support.h"

#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QObject>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace gyre;
using namespace gyre::io;
using namespace gyre::test;

namespace {

constexpr double kTolerance = 1e-5;
constexpr float kWeightTolerance = 1e-5F;

// The bar: a square section 0.2 wide at x = 0, 1 and 2, at height 1 (glTF is Y-up).
constexpr int kSections = 3;
constexpr float kHalfWidth = 0.1F;
constexpr float kHeight = 1.0F;

template <class Value>
void appendBytes(QByteArray& bytes, const std::vector<Value>& values)
{
    bytes.append(reinterpret_cast<const char*>(values.data()), static_cast<qsizetype>(values.size() * sizeof(Value)));
}

// A glTF file: node "bar" holds the bar's mesh, skinned to "root" at (0, 1, 0) and its child "tip"
// at (1, 0, 0) from it. Section 0 follows root, section 1 both by halves, section 2 tip.
QByteArray skinnedBarGltf()
{
    std::vector<float> positions;
    std::vector<std::uint16_t> joints;
    std::vector<float> weights;
    for (int section = 0; section < kSections; ++section)
        for (const auto& [dy, dz] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
            positions.insert(positions.end(), {float(section), kHeight + dy * kHalfWidth, dz * kHalfWidth});
            joints.insert(joints.end(), {0, 1, 0, 0});
            const float tip = section * 0.5F;
            weights.insert(weights.end(), {1.0F - tip, tip, 0.0F, 0.0F});
        }
    std::vector<std::uint16_t> indices;
    for (int section = 0; section + 1 < kSections; ++section)
        for (int side = 0; side < 4; ++side) {
            const auto a = static_cast<std::uint16_t>(4 * section + side);
            const auto b = static_cast<std::uint16_t>(4 * section + (side + 1) % 4);
            indices.insert(indices.end(), {a, b, std::uint16_t(b + 4), a, std::uint16_t(b + 4), std::uint16_t(a + 4)});
        }
    // Column-major translations: root's inverse bind moves by (0, −1, 0), tip's by (−1, −1, 0).
    const std::vector<float> inverseBinds{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1,
                                          1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, -1, 0, 1};
    QByteArray buffer;
    QJsonArray views;
    QJsonArray accessors;
    const auto add = [&](const auto& values, int componentType, const char* type, qint64 count) {
        views.append(QJsonObject{{"buffer", 0}, {"byteOffset", buffer.size()},
                                 {"byteLength", static_cast<qint64>(values.size() * sizeof(values[0]))}});
        QJsonObject accessor{{"bufferView", views.size() - 1}, {"componentType", componentType}, {"count", count},
                             {"type", type}};
        if (QLatin1String(type) == QLatin1String("VEC3"))
            accessor.insert("min", QJsonArray{0, kHeight - kHalfWidth, -kHalfWidth}),
                accessor.insert("max", QJsonArray{kSections - 1, kHeight + kHalfWidth, kHalfWidth});
        appendBytes(buffer, values);
        accessors.append(accessor);
    };
    const qint64 vertices = 4 * kSections;
    add(positions, 5126, "VEC3", vertices);
    add(joints, 5123, "VEC4", vertices);
    add(weights, 5126, "VEC4", vertices);
    add(indices, 5123, "SCALAR", static_cast<qint64>(indices.size()));
    add(inverseBinds, 5126, "MAT4", 2);
    const QJsonObject gltf{
        {"asset", QJsonObject{{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", QJsonArray{QJsonObject{{"nodes", QJsonArray{0, 1}}}}},
        {"nodes", QJsonArray{QJsonObject{{"name", "bar"}, {"mesh", 0}, {"skin", 0}},
                             QJsonObject{{"name", "root"}, {"translation", QJsonArray{0, 1, 0}}, {"children", QJsonArray{2}}},
                             QJsonObject{{"name", "tip"}, {"translation", QJsonArray{1, 0, 0}}}}},
        {"meshes", QJsonArray{QJsonObject{{"primitives", QJsonArray{QJsonObject{
                       {"attributes", QJsonObject{{"POSITION", 0}, {"JOINTS_0", 1}, {"WEIGHTS_0", 2}}}, {"indices", 3}}}}}}},
        {"skins", QJsonArray{QJsonObject{{"joints", QJsonArray{1, 2}}, {"inverseBindMatrices", 4}, {"skeleton", 1}}}},
        {"accessors", accessors},
        {"bufferViews", views},
        {"buffers", QJsonArray{QJsonObject{{"byteLength", buffer.size()},
                                           {"uri", QStringLiteral("data:application/octet-stream;base64,") +
                                                       QString::fromLatin1(buffer.toBase64())}}}}};
    return QJsonDocument(gltf).toJson();
}

const model::SceneObject& objectNamed(const model::Scene& scene, const QString& name)
{
    for (const model::SceneObject& object : scene.objects)
        if (object.name == name)
            return object;
    throw std::runtime_error("no object " + name.toStdString());
}

model::SceneMotion motionOf(const model::Scene& scene)
{
    return model::SceneMotion(scene, [](const model::SceneObject& object) {
        return std::make_shared<const model::SharedTrackMotion>(object.track);
    });
}

} // namespace

class TestSkinnedImport : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { useBuiltSceneWorker(); }

    // The file's unit: a metre, and a centimetre that scales the mesh and the joints alike.
    void barFollowsItsJoints_data()
    {
        QTest::addColumn<double>("metresPerUnit");
        QTest::newRow("metre") << 1.0;
        QTest::newRow("centimetre") << 0.01;
    }

    void barFollowsItsJoints()
    {
        QFETCH(double, metresPerUnit);
        const QTemporaryDir directory;
        const QString path = directory.filePath(QStringLiteral("bar.gltf"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(skinnedBarGltf());
        file.close();
        ImportOptions options;
        options.metresPerUnit = metresPerUnit;
        model::Scene scene = importSceneInWorker(path, options).scene;

        const model::SceneObject& bar = objectNamed(scene, QStringLiteral("bar"));
        const model::ObjectId root = objectNamed(scene, QStringLiteral("root")).id;
        const model::ObjectId tip = objectNamed(scene, QStringLiteral("tip")).id;
        QVERIFY(bar.mesh);
        const model::Mesh& mesh = *bar.mesh;
        QCOMPARE(mesh.skin.joints, (std::vector<model::ObjectId>{root, tip}));
        // Each position's weight on tip is half its section (x / unit), the rest on root.
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            const double section = double(mesh.positions[v].x()) / metresPerUnit;
            double onTip = 0.0;
            for (int k = 0; k < 4; ++k)
                onTip += mesh.skin.vertexJoints[v][k] == 1 ? double(mesh.skin.vertexWeights[v][k]) : 0.0;
            QVERIFY2(std::abs(onTip - section / 2) < kTolerance, qPrintable(QString::number(v)));
            QVERIFY(std::abs(mesh.skin.vertexWeights[v].sum() - 1.0F) < kWeightTolerance);
        }

        // In the bind pose every joint matrix is the identity: the mesh is as modelled.
        for (const Eigen::Matrix4f& joint : model::jointMatrices(mesh.skin, bar.id, motionOf(scene), 0.0))
            QVERIFY(joint.isIdentity(static_cast<float>(kTolerance)));

        // Tip bent a quarter turn about its own z: a point carried by tip alone moves as tip's frame
        // does, from where it was at bind to tipNow · tipAtBind⁻¹ of it; a point of root's stays.
        const model::SceneMotion bindMotion = motionOf(scene);
        const Pose tipAtBind = bindMotion.worldPose(tip, 0.0);
        const Pose barWorld = bindMotion.worldPose(bar.id, 0.0);
        model::SceneObject& tipObject = *std::find_if(scene.objects.begin(), scene.objects.end(),
                                                      [&](const model::SceneObject& object) { return object.id == tip; });
        tipObject.track.keys[0].pose.orientation *=
            Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()));
        const model::SceneMotion bent = motionOf(scene);
        const Pose tipNow = bent.worldPose(tip, 0.0);
        const std::vector<Eigen::Vector3f> skinned =
            model::skinnedPositions(mesh, model::jointMatrices(mesh.skin, bar.id, bent, 0.0));
        int farEnd = 0;
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            const Eigen::Vector3d atBind = barWorld.apply(mesh.positions[v].cast<double>());
            const Eigen::Vector3d now = barWorld.apply(skinned[v].cast<double>());
            const double section = double(mesh.positions[v].x()) / metresPerUnit;
            if (section > 1.5) {
                ++farEnd;
                const Eigen::Vector3d expected = tipNow.apply(tipAtBind.inverse().apply(atBind));
                QVERIFY2((now - expected).norm() < kTolerance * metresPerUnit, qPrintable(QString::number(v)));
                QVERIFY((now - atBind).norm() > 0.5 * metresPerUnit);
            } else if (section < 0.5) {
                QVERIFY((now - atBind).norm() < kTolerance * metresPerUnit);
            }
        }
        QCOMPARE(farEnd, 4);

        // Saved in a project and read back, the skin is the same, value for value.
        const model::Scene reread = model::parseProject(model::projectBytes(scene), QStringLiteral("bar.gyre"));
        const model::Mesh& readMesh = *objectNamed(reread, QStringLiteral("bar")).mesh;
        QCOMPARE(readMesh.skin.joints, mesh.skin.joints);
        QVERIFY(readMesh.skin.inverseBinds == mesh.skin.inverseBinds);
        QVERIFY(readMesh.skin.vertexJoints == mesh.skin.vertexJoints);
        QVERIFY(readMesh.skin.vertexWeights == mesh.skin.vertexWeights);
    }

    // A vertex moved by five bones keeps the four largest weights, renormalised to sum 1.
    void keepsTheFourLargestWeights()
    {
        auto scene = emptyAssimpScene();
        aiMesh* mesh = triangleMesh({0, 0, 0});
        const char* names[] = {"a", "b", "c", "d", "e"};
        const float weights[] = {0.1F, 0.3F, 0.05F, 0.2F, 0.35F};
        mesh->mNumBones = 5;
        mesh->mBones = new aiBone*[5];
        for (unsigned b = 0; b < 5; ++b) {
            auto* bone = new aiBone;
            bone->mName.Set(names[b]);
            bone->mNumWeights = 1;
            bone->mWeights = new aiVertexWeight[1]{aiVertexWeight(0, weights[b])};
            mesh->mBones[b] = bone;
            addNode(*scene->mRootNode, names[b]);
        }
        setMeshes(*scene, {mesh});
        attachMeshes(*addNode(*scene->mRootNode, "skinned"), {0});
        const QTemporaryDir directory;
        const QString path = directory.filePath(QStringLiteral("five.assbin"));
        writeAssbin(*scene, path);
        ImportOptions options;
        options.up = UpAxis::Z;
        const model::Scene imported = importScene(path, options).scene;
        const model::Skin& skin = objectNamed(imported, QStringLiteral("skinned")).mesh->skin;
        QCOMPARE(skin.joints.size(), std::size_t{5});
        // Kept: e 0.35, b 0.3, d 0.2, a 0.1 of 0.95; c (0.05) is dropped.
        QVERIFY(std::abs(skin.vertexWeights[0].sum() - 1.0F) < kWeightTolerance);
        for (int k = 0; k < 4; ++k) {
            const model::ObjectId id = skin.joints[skin.vertexJoints[0][k]];
            const auto object = std::find_if(imported.objects.begin(), imported.objects.end(),
                                             [&](const model::SceneObject& each) { return each.id == id; });
            const int bone = static_cast<int>(std::find(std::begin(names), std::end(names), object->name.toStdString()) - std::begin(names));
            QVERIFY(bone != 2);
            QVERIFY(std::abs(skin.vertexWeights[0][k] - weights[bone] / 0.95F) < kWeightTolerance);
        }
        // The other vertices no bone moves weigh nothing: they follow the object.
        QCOMPARE(skin.vertexWeights[1], Eigen::Vector4f::Zero().eval());
    }

    // A skin that breaks the rules is refused where it comes in: from the worker, naming the mesh;
    // from a project, naming the field.
    void refusesABrokenSkin()
    {
        model::Scene scene;
        auto mesh = std::make_shared<model::Mesh>();
        mesh->positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        mesh->indices = {0, 1, 2};
        mesh->skin.joints = {1};
        mesh->skin.inverseBinds = {Eigen::Matrix4f::Identity()};
        mesh->skin.vertexJoints.assign(3, {0, 0, 0, 0});
        mesh->skin.vertexWeights.assign(3, Eigen::Vector4f(1, 0, 0, 0));
        scene.objects.push_back({1, QStringLiteral("held"), mesh, model::kNoObject, {}, true});
        scene.objects.back().track.keys = {model::Keyframe{}};
        scene.nextObjectId = 2;
        const auto decoded = [&] {
            SceneImport imported;
            imported.scene = scene;
            return wire::decodeReply(wire::encodeReply(imported));
        };
        QVERIFY(std::get<SceneImport>(decoded()).scene.objects[0].mesh->skin.joints == mesh->skin.joints);

        mesh->skin.vertexWeights[1] = Eigen::Vector4f(std::nanf(""), 0, 0, 0);
        QVERIFY_THROWS_EXCEPTION(wire::WireError, decoded());
        mesh->skin.vertexWeights[1] = Eigen::Vector4f(0.5F, 0.6F, 0, 0);
        QVERIFY_THROWS_EXCEPTION(wire::WireError, decoded());
        mesh->skin.vertexWeights[1] = Eigen::Vector4f(1, 0, 0, 0);
        mesh->skin.vertexJoints[2] = {0, 1, 0, 0};
        QVERIFY_THROWS_EXCEPTION(wire::WireError, decoded());
        mesh->skin.vertexJoints[2] = {0, 0, 0, 0};

        mesh->skin.joints = {7}; // no such object
        try {
            decoded();
            QFAIL("a skin joint that is no object was accepted from the worker");
        } catch (const wire::WireError& error) {
            QVERIFY2(QString::fromUtf8(error.what()).contains(QStringLiteral("joint 7")), error.what());
        }
        try {
            model::parseProject(model::projectBytes(scene), QStringLiteral("held.gyre"));
            QFAIL("a skin joint that is no object was accepted from a project");
        } catch (const std::exception& error) {
            QVERIFY2(QString::fromUtf8(error.what()).contains(QStringLiteral("meshes[0].skin.joints")), error.what());
        }
    }
};

QTEST_GUILESS_MAIN(TestSkinnedImport)
#include "tst_skinned_import.moc"
