// The messages between Gyre and gyre-scene-worker: every field comes through exactly, and a reply
// that is cut short, padded, counts more than it holds or carries values the document forbids is
// refused with WireError, never read past its end or believed.

#include "io/scene_wire.h"
#include "model/project_file.h"

#include <QTest>
#include <QtEndian>

#include <cmath>

using namespace gyre;
using namespace gyre::io;
using namespace gyre::io::wire;

namespace {

// The offset of the first object count in a scene message: header (magic, version, kind: 7 bytes),
// four times (32), the gravity (8) and its up axis (1), the mesh count (8).
constexpr qsizetype kObjectCountOffset = 7 + 32 + 9 + 8;

model::Keyframe key(double time, double angle, bool constrained = true)
{
    const Eigen::Quaterniond q(Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 3).normalized()));
    return {time, Pose{q, {angle, -time, 0.125}}, constrained};
}

// Two meshes, one shared by two objects; a hierarchy; every kind of track state, sketch included.
model::Scene richScene()
{
    auto triangle = std::make_shared<model::Mesh>();
    triangle->positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0.5f}};
    triangle->normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    triangle->indices = {0, 1, 2};
    auto bare = std::make_shared<model::Mesh>();
    bare->positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 2, 0}};
    bare->indices = {0, 1, 2, 2, 1, 3};

    model::Scene scene;
    scene.fps = 30.0;
    scene.startTime = -0.5;
    scene.endTime = 7.25;
    scene.currentTime = 1.0 / 3.0;
    scene.gravity = {3.71, model::UpDirection::PlusY};
    model::SceneObject root{4, QStringLiteral("root ünïcode"), triangle, model::kNoObject, {}};
    root.track.keys = {key(-0.5, 0.1), key(1.0 / 3.0, 2.5, false), key(7.25, -3.0)};
    root.track.interpolation = InterpolationMethod::Screw;
    root.track.subdivision = {SubdivisionScheme::Jarek, 6, false, true};
    model::SketchState& sketch = root.track.sketch;
    sketch.directionStrokes = {{{Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()}, {0.0, 1.5}},
                               {{Eigen::Vector3d::UnitZ()}, {}}};
    sketch.magnitude = {{0.0, 1.0}, {2.0, 0.25}};
    sketch.pattern = {{0.0, 0.0}, {0.5, 1.0}, {1.0, 0.0}};
    sketch.patternRepeat = 7;
    sketch.window = std::pair{0.25, 5.0};
    sketch.alpha = 0.01;
    sketch.beta = 2.0;
    sketch.delta = 0.05;
    sketch.fittedCurve = {{0.25, Eigen::Quaterniond::Identity(), Eigen::Quaterniond(0, 0.5, 0, 0)},
                          {5.0, Eigen::Quaterniond(0, 1, 0, 0), Eigen::Quaterniond(0.1, 0, 0.2, 0)}};
    model::SceneObject child{9, QStringLiteral("child"), triangle, 4, {}};
    child.track.keys = {key(0.0, 0.7)};
    model::SceneObject other{2, QString(), bare, model::kNoObject, {}};
    other.track.keys = {key(1.0, 1.0), key(2.0, 1.5)};
    // Typed mass properties, which a ballistic export flies (not the mesh's).
    other.massOverride = MassProperties{2.5, {0.1, -0.2, 0.3}, inertiaTensor({0.5, 0.75, 1.0, 0.01, -0.02, 0.03})};
    model::SceneObject empty{3, QStringLiteral("no mesh"), nullptr, 9, {}};
    empty.track.keys = {key(0.0, 0.0)};
    empty.empty = true; // an Empty travels as one (wire version 7)
    scene.objects = {root, child, other, empty};
    scene.nextObjectId = 10;
    return scene;
}

// Every field of an import set, none to its default.
SceneImport richImport()
{
    SceneImport imported;
    imported.scene = richScene();
    imported.animations = {{QStringLiteral("Cube|CubeAction"), 2.5, {QStringLiteral("Cube"), QStringLiteral("lid ü")}},
                           {QString(), 0.0, {}},
                           {QStringLiteral("run"), 1.0 / 3.0, {QStringLiteral("Cube")}}};
    imported.takes = {2, 0};
    imported.takeRule = TakeRule::BlenderActions;
    imported.file = {{29.97, 0.01, UpAxis::Z}, QStringLiteral("the FBX time mode"), QStringLiteral("cm"), QString()};
    imported.applied = {30.0, 0.0254, UpAxis::Y};
    imported.timeShift = -1.0 / 30.0;
    imported.warnings << QStringLiteral("cameras and lights are not imported") << QString();
    return imported;
}

// An import reply of `scene`, its applied frame rate the scene's as importScene makes it.
SceneImport importOf(const model::Scene& scene)
{
    SceneImport imported;
    imported.scene = scene;
    imported.applied.fps = scene.fps;
    return imported;
}

// A scene of one object whose keys are `keys`.
model::Scene sceneWithKeys(std::vector<model::Keyframe> keys)
{
    model::Scene scene;
    model::SceneObject object{1, QStringLiteral("o"), nullptr, model::kNoObject, {}};
    object.track.keys = std::move(keys);
    scene.objects = {object};
    return scene;
}

QByteArray importReplyOf(const model::Scene& scene) { return encodeReply(importOf(scene)); }

// The settings of one import request, every option given.
ImportOptions everyOption()
{
    ImportOptions options;
    options.takeSelection = TakeSelection::Listed;
    options.takes = {4, 1, 4};
    options.fps = 120.0;
    options.metresPerUnit = 0.001;
    options.up = UpAxis::Z;
    options.timeOrigin = TimeOrigin::File;
    return options;
}

} // namespace

class TestSceneWire : public QObject {
    Q_OBJECT

private slots:
    // The project file writes every field of a scene in a fixed order, so equal project text is an
    // equal scene; the shared mesh must stay one mesh.
    void importReplyComesThroughExactly()
    {
        const SceneImport sent = richImport();
        const Reply reply = decodeReply(encodeReply(sent));
        const auto* received = std::get_if<SceneImport>(&reply);
        QVERIFY(received);
        QCOMPARE(model::projectBytes(received->scene), model::projectBytes(sent.scene));
        QCOMPARE(received->scene.nextObjectId, sent.scene.nextObjectId);
        QCOMPARE(received->scene.objects[0].mesh, received->scene.objects[1].mesh);
        QVERIFY(received->scene.objects[0].mesh != received->scene.objects[2].mesh);
        QCOMPARE(received->animations.size(), sent.animations.size());
        for (std::size_t i = 0; i < sent.animations.size(); ++i) {
            QCOMPARE(received->animations[i].name, sent.animations[i].name);
            QCOMPARE(received->animations[i].durationSeconds, sent.animations[i].durationSeconds);
            QCOMPARE(received->animations[i].nodes, sent.animations[i].nodes);
        }
        QCOMPARE(received->takes, sent.takes);
        QCOMPARE(received->takeRule, sent.takeRule);
        QCOMPARE(received->file.values.fps, sent.file.values.fps);
        QCOMPARE(received->file.values.metresPerUnit, sent.file.values.metresPerUnit);
        QCOMPARE(received->file.values.up, sent.file.values.up);
        QCOMPARE(received->file.fpsSource, sent.file.fpsSource);
        QCOMPARE(received->file.unitSource, sent.file.unitSource);
        QCOMPARE(received->file.upSource, sent.file.upSource);
        QCOMPARE(received->applied.fps, sent.applied.fps);
        QCOMPARE(received->applied.metresPerUnit, sent.applied.metresPerUnit);
        QCOMPARE(received->applied.up, sent.applied.up);
        QCOMPARE(received->timeShift, sent.timeShift);
        QCOMPARE(received->warnings, sent.warnings);
    }

    void exportRequestComesThroughExactly()
    {
        const ExportRequest sent{QStringLiteral("/tmp/out put.dae"), QStringLiteral("zh_CN"), SceneFormat::Collada, 48.0,
                                 richScene()};
        const Request request = decodeRequest(encodeRequest(sent));
        const auto* received = std::get_if<ExportRequest>(&request);
        QVERIFY(received);
        QCOMPARE(received->path, sent.path);
        QCOMPARE(received->locale, sent.locale);
        QCOMPARE(received->format, sent.format);
        QCOMPARE(received->fps, sent.fps);
        QCOMPARE(received->scene.gravity, sent.scene.gravity);
        QCOMPARE(model::projectBytes(received->scene), model::projectBytes(sent.scene));
        QVERIFY(received->scene.objects[3].empty);
        QVERIFY(!received->scene.objects[2].empty);
    }

    // The Empty flag is the request's last byte (the last object's); it is a flag, and an Empty has no mesh.
    void anEmptyIsAFlagWithoutAMesh()
    {
        ExportRequest sent{QStringLiteral("out.fbx"), {}, SceneFormat::Fbx, 24.0, richScene()};
        QByteArray notAFlag = encodeRequest(sent);
        QCOMPARE(notAFlag.back(), char{1});
        notAFlag.back() = 2;
        try {
            decodeRequest(notAFlag);
            QFAIL("a flag of 2 was accepted");
        } catch (const WireError& error) {
            QVERIFY2(QByteArray(error.what()).contains("a flag is 2"), error.what());
        }
        sent.scene.objects[2].empty = true;
        try {
            decodeRequest(encodeRequest(sent));
            QFAIL("an empty with a mesh was accepted");
        } catch (const WireError& error) {
            QVERIFY2(QByteArray(error.what()).contains("object 2: an empty has a mesh"), error.what());
        }
    }

    void importRequestAndOtherRepliesComeThrough()
    {
        const ImportOptions sent = everyOption();
        const Request request =
            decodeRequest(encodeRequest(ImportRequest{QStringLiteral("a.bvh"), QStringLiteral("de_DE"), sent}));
        QCOMPARE(std::get<ImportRequest>(request).path, QStringLiteral("a.bvh"));
        QCOMPARE(std::get<ImportRequest>(request).locale, QStringLiteral("de_DE"));
        const ImportOptions& options = std::get<ImportRequest>(request).options;
        QCOMPARE(options.takeSelection, sent.takeSelection);
        QCOMPARE(options.takes, sent.takes);
        QCOMPARE(options.fps, sent.fps);
        QCOMPARE(options.metresPerUnit, sent.metresPerUnit);
        QCOMPARE(options.up, sent.up);
        QCOMPARE(options.timeOrigin, sent.timeOrigin);
        // Options left to the file stay unset.
        const Request defaults = decodeRequest(encodeRequest(ImportRequest{QStringLiteral("a.fbx"), {}, {}}));
        const ImportOptions& unset = std::get<ImportRequest>(defaults).options;
        QCOMPARE(unset.takeSelection, TakeSelection::Automatic);
        QVERIFY(unset.takes.empty() && !unset.fps && !unset.metresPerUnit && !unset.up);
        QCOMPARE(unset.timeOrigin, TimeOrigin::FirstKey);

        const ExportReport report{{QStringLiteral("a.bin"), QStringLiteral("a.gltf")}, {QStringLiteral("w")}};
        const Reply exported = decodeReply(encodeReply(report));
        QCOMPARE(std::get<ExportReport>(exported).files, report.files);
        QCOMPARE(std::get<ExportReport>(exported).warnings, report.warnings);

        const Reply failed = decodeReply(encodeReply(Failure{Failure::Kind::Output, QStringLiteral("x.glb: no")}));
        QCOMPARE(std::get<Failure>(failed).kind, Failure::Kind::Output);
        QCOMPARE(std::get<Failure>(failed).message, QStringLiteral("x.glb: no"));
    }

    void everyShortenedOrPaddedReplyIsRefused()
    {
        const QByteArray whole = encodeReply(richImport());
        for (qsizetype size = 0; size < whole.size(); ++size)
            QVERIFY_THROWS_EXCEPTION(WireError, decodeReply(whole.left(size)));
        QVERIFY_THROWS_EXCEPTION(WireError, decodeReply(whole + '\0'));
        const QByteArray request = encodeRequest(ImportRequest{QStringLiteral("a.fbx"), {}, everyOption()});
        for (qsizetype size = 0; size < request.size(); ++size)
            QVERIFY_THROWS_EXCEPTION(WireError, decodeRequest(request.left(size)));
        QVERIFY_THROWS_EXCEPTION(WireError, decodeRequest(request + '\0'));
    }

    // Import settings and options that importScene would never give or accept.
    void importFieldsOutOfRangeAreRefused_data()
    {
        QTest::addColumn<QByteArray>("message");
        QTest::addColumn<bool>("isRequest");
        QTest::addColumn<QByteArray>("expected");
        const auto reply = [](const char* name, const char* expected, auto change) {
            SceneImport imported = richImport();
            change(imported);
            QTest::newRow(name) << encodeReply(imported) << false << QByteArray(expected);
        };
        reply("a take past the animations", "there is no animation 3", [](SceneImport& i) { i.takes = {0, 3}; });
        reply("an unknown take rule", "unknown take rule 7", [](SceneImport& i) { i.takeRule = static_cast<TakeRule>(7); });
        reply("the file's frame rate 0", "the file's settings", [](SceneImport& i) { i.file.values.fps = 0.0; });
        reply("a frame rate past 1000", "the applied settings", [](SceneImport& i) { i.applied.fps = 1001.0; });
        reply("a unit of 0 m", "the file's settings", [](SceneImport& i) { i.file.values.metresPerUnit = 0.0; });
        reply("a unit of nan m", "the applied settings", [](SceneImport& i) { i.applied.metresPerUnit = NAN; });
        reply("an unknown up axis", "unknown up axis 3", [](SceneImport& i) { i.applied.up = static_cast<UpAxis>(3); });
        reply("another frame rate than the scene's", "not the scene's", [](SceneImport& i) { i.applied.fps = 25.0; });
        reply("an infinite time shift", "time shift", [](SceneImport& i) { i.timeShift = INFINITY; });

        const auto request = [](const char* name, const char* expected, auto change) {
            ImportOptions options = everyOption();
            change(options);
            QTest::newRow(name) << encodeRequest(ImportRequest{QStringLiteral("a.fbx"), {}, options}) << true
                                << QByteArray(expected);
        };
        request("an unknown take selection", "unknown take selection 0",
                [](ImportOptions& o) { o.takeSelection = static_cast<TakeSelection>(0); });
        request("takes listed for all", "listed without being chosen",
                [](ImportOptions& o) { o.takeSelection = TakeSelection::All; });
        request("an option frame rate of -24", "frame rate option", [](ImportOptions& o) { o.fps = -24.0; });
        request("an option unit of -1 m", "unit option", [](ImportOptions& o) { o.metresPerUnit = -1.0; });
        request("an unknown up axis option", "unknown up axis 9", [](ImportOptions& o) { o.up = static_cast<UpAxis>(9); });
        request("an unknown time origin", "unknown time origin 3",
                [](ImportOptions& o) { o.timeOrigin = static_cast<TimeOrigin>(3); });
    }

    void importFieldsOutOfRangeAreRefused()
    {
        QFETCH(QByteArray, message);
        QFETCH(bool, isRequest);
        QFETCH(QByteArray, expected);
        try {
            if (isRequest)
                decodeRequest(message);
            else
                decodeReply(message);
            QFAIL("the message was accepted");
        } catch (const WireError& error) {
            QVERIFY2(QByteArray(error.what()).contains(expected), error.what());
        }
    }

    void aRequestIsNotAReplyNorTheOtherWayRound()
    {
        QVERIFY_THROWS_EXCEPTION(WireError, decodeReply(encodeRequest(ImportRequest{QStringLiteral("a"), {}, {}})));
        QVERIFY_THROWS_EXCEPTION(WireError, decodeRequest(encodeReply(ExportReport{})));
        QByteArray otherVersion = encodeReply(ExportReport{});
        otherVersion[4] = static_cast<char>(kVersion + 1);
        QVERIFY_THROWS_EXCEPTION(WireError, decodeReply(otherVersion));
    }

    // A count is checked against the bytes left before anything is allocated: 2⁶⁰ objects would
    // otherwise ask for far more memory than there is.
    void aCountLargerThanTheReplyIsRefusedBeforeAllocating()
    {
        QByteArray reply = importReplyOf(sceneWithKeys({key(0.0, 1.0)}));
        qToLittleEndian<quint64>(quint64{1} << 60, reply.data() + kObjectCountOffset);
        try {
            decodeReply(reply);
            QFAIL("a count of 2^60 objects was accepted");
        } catch (const WireError& error) {
            QVERIFY2(QByteArray(error.what()).contains("objects: a count of 1152921504606846976 does not fit"),
                     error.what());
        }
    }

    void valuesTheDocumentForbidsAreRefused_data()
    {
        QTest::addColumn<QByteArray>("reply");
        QTest::addColumn<QByteArray>("expected");
        QTest::newRow("zero quaternion") << importReplyOf(sceneWithKeys({{0.0, Pose{Eigen::Quaterniond(0, 0, 0, 0), Eigen::Vector3d::Zero()}, true}}))
                                         << QByteArray("object 0:");
        QTest::newRow("time not increasing") << importReplyOf(sceneWithKeys({key(1.0, 0.0), key(1.0, 0.5)}))
                                             << QByteArray("object 0:");
        QTest::newRow("infinite position") << importReplyOf(sceneWithKeys(
            {{0.0, Pose{Eigen::Quaterniond::Identity(), {INFINITY, 0, 0}}, true}}))
                                           << QByteArray("object 0:");

        model::Scene parentAfter = richScene();
        std::swap(parentAfter.objects[0], parentAfter.objects[1]);
        QTest::newRow("parent after its child") << importReplyOf(parentAfter) << QByteArray("is not an object before it");
        model::Scene sameId = richScene();
        sameId.objects[2].id = sameId.objects[0].id;
        QTest::newRow("an id twice") << importReplyOf(sameId) << QByteArray("is zero or taken");
        model::Scene ownParent = richScene();
        ownParent.objects[2].parent = ownParent.objects[2].id;
        QTest::newRow("its own parent") << importReplyOf(ownParent) << QByteArray("is not an object before it");
        model::Scene badMesh = richScene();
        auto mesh = std::make_shared<model::Mesh>(*badMesh.objects[2].mesh);
        mesh->indices.back() = 4; // one past the last position
        badMesh.objects[2].mesh = mesh;
        QTest::newRow("index past the positions") << importReplyOf(badMesh) << QByteArray("mesh:");
        model::Scene noSuchBody = richScene();
        noSuchBody.objects[2].massOverride->inertia = inertiaTensor({0.1, 0.1, 1.0, 0.0, 0.0, 0.0});
        QTest::newRow("inertia no body has") << importReplyOf(noSuchBody) << QByteArray("object 2 mass properties:");
        model::Scene badRate = richScene();
        badRate.fps = 0.0;
        QTest::newRow("frame rate 0") << importReplyOf(badRate) << QByteArray("scene:");
    }

    void valuesTheDocumentForbidsAreRefused()
    {
        QFETCH(QByteArray, reply);
        QFETCH(QByteArray, expected);
        try {
            decodeReply(reply);
            QFAIL("the reply was accepted");
        } catch (const WireError& error) {
            QVERIFY2(QByteArray(error.what()).contains(expected), error.what());
        }
    }
};

QTEST_GUILESS_MAIN(TestSceneWire)
#include "tst_scene_wire.moc"
