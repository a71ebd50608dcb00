// Scenes Blender 3.4 exported with its default FBX, glTF (glb) and Collada settings
// (tests/interop/make_fixtures.py, files in tests/data): three objects, each with its own action
// (quaternion, Euler XYZ, Euler ZXY and parented), at 30 fps, and Blender's own evaluation of every
// object's world pose at every frame; and an animated Empty carrying an animated mesh object, as FBX and
// glb. Every object must move as Blender evaluated it, and the Empty come in as an Empty. A bar skinned to
// a two-bone armature must deform under Gyre's skinning as Blender deformed it.

#include "core/core_test_support.h"
#include "io/scene_export.h"
#include "io/scene_import.h"
#include "model/motion_cache.h"
#include "model/scene_motion.h"
#include "model/scene_queries.h"
#include "model/skinning.h"
#include "model/track_evaluation.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <map>

namespace gyre {

namespace {

using namespace gyre::io;

using test::kPi;

// The committed files, or a folder the script just wrote (tests/interop: Blender run live).
const QString kData = qEnvironmentVariableIsSet("GYRE_BLENDER_FILES") ? qEnvironmentVariable("GYRE_BLENDER_FILES")
                                                                     : QStringLiteral(GYRE_TEST_DATA);
const QStringList kObjects{QStringLiteral("Quat"), QStringLiteral("EulerXYZ"), QStringLiteral("ChildZXY")};

QString dataFile(const QString& name) { return kData + QLatin1Char('/') + name; }

// Blender's world pose of each object at each frame, in its Z-up world.
struct BlenderFrame {
    int frame = 0;
    std::map<QString, Pose> poses;
};

std::vector<BlenderFrame> blenderFrames(const QString& fileName)
{
    QFile file(dataFile(fileName));
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", qPrintable(file.fileName()));
    const QJsonObject root = QJsonDocument::fromJson(file.readAll()).object();
    std::vector<BlenderFrame> frames;
    for (const QJsonValue& entry : root.value(QStringLiteral("frames")).toArray()) {
        BlenderFrame frame;
        frame.frame = entry.toObject().value(QStringLiteral("frame")).toInt();
        const QJsonObject poses = entry.toObject().value(QStringLiteral("poses")).toObject();
        for (const QString& name : poses.keys()) {
            const QJsonArray n = poses.value(name).toArray();
            frame.poses[name] = {Eigen::Quaterniond(n[0].toDouble(), n[1].toDouble(), n[2].toDouble(), n[3].toDouble()),
                                 {n[4].toDouble(), n[5].toDouble(), n[6].toDouble()}};
        }
        frames.push_back(std::move(frame));
    }
    return frames;
}

const model::SceneObject* objectNamed(const model::Scene& scene, const QString& name)
{
    const auto found = std::find_if(scene.objects.begin(), scene.objects.end(),
                                    [&](const model::SceneObject& object) { return object.name == name; });
    return found == scene.objects.end() ? nullptr : &*found;
}

// The world pose of `object` at `time`: its track's pose after its ancestors'.
Pose worldPose(const model::Scene& scene, const model::SceneObject& object, double time)
{
    const Pose local = model::TrackMotion(object.track).at(time);
    const model::SceneObject* parent = model::findObject(scene, object.parent);
    return parent ? worldPose(scene, *parent, time) * local : local;
}

double degrees(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    return a.angularDistance(b) * 180.0 / kPi;
}

// A Y-up world seen Z-up, as Gyre's and Blender's are: +90° about X (Y up becomes Z up). Blender's
// exporters turn its world by the inverse for Y-up formats.
const Eigen::Quaterniond kYUpToZUp(Eigen::AngleAxisd(kPi / 2.0, Eigen::Vector3d::UnitX()));

// Every one of `names` moves (turns more than 20° from the first frame to the last), and at every
// frame its world pose in `scene` is Blender's within `toleranceDegrees` and 1e-4 m; `framesTurned`
// as in everyObjectMovesAsBlenderEvaluatedIt. A failed check fails the calling test (QVERIFY2 returns).
void checkAgainstBlender(const model::Scene& scene, const std::vector<BlenderFrame>& frames, const QStringList& names,
                         double toleranceDegrees, bool framesTurned, const QString& file)
{
    double worstDegrees = 0.0;
    double worstMetres = 0.0;
    for (const QString& name : names) {
        const model::SceneObject* object = objectNamed(scene, name);
        QVERIFY2(object, qPrintable(name));
        // Every animated object moves: its orientation at the last frame is not its first.
        const double last = (frames.back().frame - frames.front().frame) / 30.0;
        QVERIFY2(degrees(worldPose(scene, *object, 0.0).orientation, worldPose(scene, *object, last).orientation) > 20.0,
                 qPrintable(name));
        for (const BlenderFrame& frame : frames) {
            const double time = (frame.frame - frames.front().frame) / 30.0;
            const Pose gyre = worldPose(scene, *object, time);
            const Pose& blender = frame.poses.at(name);
            const Eigen::Quaterniond expected = framesTurned ? blender.orientation * kYUpToZUp : blender.orientation;
            const double angle = degrees(gyre.orientation, expected);
            const double distance = (gyre.position - blender.position).norm();
            worstDegrees = std::max(worstDegrees, angle);
            worstMetres = std::max(worstMetres, distance);
            QVERIFY2(angle <= toleranceDegrees,
                     qPrintable(QStringLiteral("%1 frame %2: %3°").arg(name).arg(frame.frame).arg(angle)));
            // In metres: a centimetre FBX must not arrive 100 times too large.
            QVERIFY2(distance <= 1e-4, qPrintable(QStringLiteral("%1 frame %2: %3 m").arg(name).arg(frame.frame).arg(distance)));
        }
    }
    qInfo("%s: worst %.6f° and %.2e m over %zu frames", qPrintable(file), worstDegrees, worstMetres, frames.size());
}

// Gyre's skinning of the object `evaluation` names against Blender's evaluated mesh at each of its
// frames: the largest distance from a vertex of either to the nearest of the other, and how far Blender's
// vertices move from the first frame to the last.
struct SkinnedComparison {
    bool skinned = false;
    std::size_t frames = 0;
    double worst = 0.0;
    double moved = 0.0;
};

SkinnedComparison compareSkinning(const model::Scene& scene, const QJsonObject& evaluation)
{
    SkinnedComparison result;
    const model::SceneObject* bar = objectNamed(scene, evaluation.value(QStringLiteral("object")).toString());
    result.skinned = bar && bar->mesh && !bar->mesh->skin.empty();
    if (!result.skinned)
        return result;
    const model::SceneMotion motion(scene, [](const model::SceneObject& object) {
        return std::make_shared<const model::SharedTrackMotion>(object.track);
    });
    const auto farthest = [](const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& others) {
        double worst = 0.0;
        for (const Eigen::Vector3d& p : points) {
            double nearest = INFINITY;
            for (const Eigen::Vector3d& q : others)
                nearest = std::min(nearest, (p - q).norm());
            worst = std::max(worst, nearest);
        }
        return worst;
    };
    const double fps = evaluation.value(QStringLiteral("fps")).toDouble();
    const int start = evaluation.value(QStringLiteral("frame_start")).toInt();
    std::vector<Eigen::Vector3d> first;
    for (const QJsonValue& entry : evaluation.value(QStringLiteral("frames")).toArray()) {
        std::vector<Eigen::Vector3d> blender;
        for (const QJsonValue& v : entry.toObject().value(QStringLiteral("vertices")).toArray())
            blender.emplace_back(v[0].toDouble(), v[1].toDouble(), v[2].toDouble());
        const double time = (entry.toObject().value(QStringLiteral("frame")).toInt() - start) / fps;
        const Pose at = motion.worldPose(bar->id, time);
        std::vector<Eigen::Vector3d> gyre;
        for (const Eigen::Vector3f& p :
             model::skinnedPositions(*bar->mesh, model::jointMatrices(bar->mesh->skin, bar->id, motion, time)))
            gyre.push_back(at.apply(p.cast<double>()));
        result.worst = std::max({result.worst, farthest(blender, gyre), farthest(gyre, blender)});
        if (first.empty())
            first = blender;
        for (std::size_t v = 0; v < std::min(first.size(), blender.size()); ++v)
            result.moved = std::max(result.moved, (blender[v] - first[v]).norm());
        ++result.frames;
    }
    return result;
}

} // namespace

class TstBlenderFixtures : public QObject {
    Q_OBJECT

private slots:
    void everyObjectMovesAsBlenderEvaluatedIt_data();
    void everyObjectMovesAsBlenderEvaluatedIt();
    void blenderTakesGiveEachObjectItsOwnAction();
    void overlappingAnimationsNeedAChoice();
    void optionsOverrideWhatTheFileSays();
    void colladaUnitAndUpAxisComeFromItsAsset();
    void blendersEmptyIsAnEmpty_data();
    void blendersEmptyIsAnEmpty();
    void blendersSkinnedBarDeformsAsInBlender();
};

void TstBlenderFixtures::everyObjectMovesAsBlenderEvaluatedIt_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<double>("toleranceDegrees");
    // Gyre's world is Z-up as Blender's. FBX turns the world (the root objects) to Y-up and Gyre turns
    // it back; glTF turns every node's frame too, so a world orientation R is C R C⁻¹ in the file
    // (C = kYUpToZUp⁻¹) and R·C⁻¹ after Gyre's turn; Collada stays Z-up and is not turned.
    QTest::addColumn<bool>("framesTurned");
    QTest::newRow("fbx") << "blender_three_objects.fbx" << 0.01 << false;
    QTest::newRow("glb") << "blender_three_objects.glb" << 0.2 << true;
    QTest::newRow("dae") << "blender_three_objects.dae" << 0.01 << false;
}

void TstBlenderFixtures::everyObjectMovesAsBlenderEvaluatedIt()
{
    QFETCH(QString, file);
    QFETCH(double, toleranceDegrees);
    QFETCH(bool, framesTurned);
    const SceneImport imported = importScene(dataFile(file));
    const model::Scene& scene = imported.scene;
    QCOMPARE(scene.fps, 30.0);
    QCOMPARE(scene.startTime, 0.0);
    QCOMPARE(scene.objects.size(), std::size_t{3});
    const std::vector<BlenderFrame> frames = blenderFrames(QStringLiteral("blender_three_objects.json"));
    QCOMPARE(frames.size(), std::size_t{11});
    checkAgainstBlender(scene, frames, kObjects, toleranceDegrees, framesTurned, file);
}

void TstBlenderFixtures::blenderTakesGiveEachObjectItsOwnAction()
{
    const SceneImport imported = importScene(dataFile(QStringLiteral("blender_three_objects.fbx")));
    QCOMPARE(imported.animations.size(), std::size_t{9}); // every action on every object
    QCOMPARE(imported.takeRule, TakeRule::BlenderActions);
    QCOMPARE(imported.takes.size(), std::size_t{3});
    QCOMPARE(imported.file.values.metresPerUnit, 0.01);
    QCOMPARE(imported.file.values.up, UpAxis::Y);
    QVERIFY2(imported.file.fpsSource.contains(QStringLiteral("FBX time mode")), qPrintable(imported.file.fpsSource));
    const QStringList taken = imported.warnings.filter(QStringLiteral("Blender's"));
    QCOMPARE(taken.size(), 1);
    for (const QString& object : kObjects) {
        const QString take = object + QLatin1Char('|') + object + QStringLiteral("Action");
        const auto index = static_cast<std::size_t>(
            std::find_if(imported.animations.begin(), imported.animations.end(),
                         [&](const AnimationSummary& animation) { return animation.name == take; }) -
            imported.animations.begin());
        QVERIFY2(index < imported.animations.size(), qPrintable(take));
        QVERIFY(std::find(imported.takes.begin(), imported.takes.end(), index) != imported.takes.end());
        const QString said = QStringLiteral("'%1' plays take %2 '%3'").arg(object).arg(index).arg(take);
        QVERIFY2(taken.front().contains(said), qPrintable(taken.front() + " lacks " + said));
    }
}

// Blender's glTF exporter writes an object's two actions ("Spin" on an NLA track, "Wobble" assigned)
// as two animations of the same node: neither is the object's alone.
void TstBlenderFixtures::overlappingAnimationsNeedAChoice()
{
    const QString file = dataFile(QStringLiteral("blender_two_actions.glb"));
    const SceneImport automatic = importScene(file);
    QCOMPARE(automatic.takeRule, TakeRule::ChoiceNeeded);
    QCOMPARE(automatic.takes, std::vector<std::size_t>{0});
    QCOMPARE(automatic.animations.at(0).name, QStringLiteral("Spin"));
    QCOMPARE(automatic.animations.at(1).name, QStringLiteral("Wobble"));
    QCOMPARE(automatic.animations.at(1).nodes, QStringList{QStringLiteral("Wheel")});

    // Spin turns about Blender's Z (glTF's Y) by 180°; Wobble tilts 30° about X and back.
    const auto turnAtEnd = [](const SceneImport& imported) {
        const model::MotionTrack& track = imported.scene.objects.at(0).track;
        return degrees(track.keys.front().pose.orientation, track.keys.back().pose.orientation);
    };
    QVERIFY(std::abs(turnAtEnd(automatic) - 180.0) < 0.2);

    ImportOptions wobble;
    wobble.takeSelection = TakeSelection::Listed;
    wobble.takes = {1};
    const SceneImport chosen = importScene(file, wobble);
    QCOMPARE(chosen.takeRule, TakeRule::Chosen);
    QVERIFY(turnAtEnd(chosen) < 0.2);

    ImportOptions all;
    all.takeSelection = TakeSelection::All;
    const SceneImport merged = importScene(file, all);
    QCOMPARE(merged.takes, (std::vector<std::size_t>{0, 1}));
    QVERIFY(turnAtEnd(merged) < 0.2); // the later animation wins the node
    QCOMPARE(merged.warnings.filter(QStringLiteral("'Wheel' is moved by more than one")).size(), 1);

    wobble.takes = {2};
    QVERIFY_THROWS_EXCEPTION(InputError, importScene(file, wobble));
}

void TstBlenderFixtures::optionsOverrideWhatTheFileSays()
{
    const QString fbx = dataFile(QStringLiteral("blender_three_objects.fbx"));
    const SceneImport asTheFileSays = importScene(fbx);
    ImportOptions options;
    options.fps = 24.0;
    options.metresPerUnit = 1.0;
    const SceneImport overridden = importScene(fbx, options);
    QCOMPARE(overridden.scene.fps, 24.0);
    QCOMPARE(overridden.applied.metresPerUnit, 1.0);
    QCOMPARE(overridden.file.values.fps, 30.0); // what the file says stays known
    const auto& a = asTheFileSays.scene.objects;
    const auto& b = overridden.scene.objects;
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t k = 0; k < a[i].track.keys.size(); ++k) {
            QCOMPARE(b[i].track.keys[k].time, a[i].track.keys[k].time); // keys are never resampled
            QVERIFY((b[i].track.keys[k].pose.position - 100.0 * a[i].track.keys[k].pose.position).norm() < 1e-9);
        }

    // glb: frame f at f/30 in the file; by default the first key is at 0.
    const QString glb = dataFile(QStringLiteral("blender_three_objects.glb"));
    ImportOptions fileTimes;
    fileTimes.timeOrigin = TimeOrigin::File;
    fileTimes.up = UpAxis::Z;
    const SceneImport shifted = importScene(glb);
    const SceneImport unshifted = importScene(glb, fileTimes);
    QVERIFY(std::abs(shifted.timeShift + 1.0 / 30.0) < 1e-6);
    QCOMPARE(unshifted.timeShift, 0.0);
    QVERIFY(std::abs(unshifted.scene.objects.at(0).track.keys.front().time - 1.0 / 30.0) < 1e-6);
    // Read as Z-up, the top-level objects miss the turn a Y-up file gets, +90° about X.
    const Pose turned = shifted.scene.objects.at(0).track.keys.back().pose;
    const Pose asIs = unshifted.scene.objects.at(0).track.keys.back().pose;
    QVERIFY(degrees(turned.orientation, kYUpToZUp * asIs.orientation) < 1e-9);
    QVERIFY((turned.position - kYUpToZUp * asIs.position).norm() < 1e-9);
}

// Blender's Collada says <unit meter="1"/> and Z_UP. The same file in centimetres comes in 100 times
// smaller; said to be Y-up, it is turned Z-up; said to be X-up, it is read as Y-up with a warning.
void TstBlenderFixtures::colladaUnitAndUpAxisComeFromItsAsset()
{
    QFile original(dataFile(QStringLiteral("blender_three_objects.dae")));
    QVERIFY(original.open(QIODevice::ReadOnly));
    const QByteArray text = original.readAll();
    QVERIFY(text.contains(R"(<unit name="meter" meter="1"/>)") && text.contains("<up_axis>Z_UP</up_axis>"));
    QTemporaryDir folder;
    const auto variant = [&](const char* name, QByteArray unit, QByteArray up) {
        QByteArray changed = text;
        changed.replace(R"(<unit name="meter" meter="1"/>)", unit).replace("<up_axis>Z_UP</up_axis>", up);
        const QString path = folder.filePath(QLatin1String(name));
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly) || file.write(changed) != changed.size())
            qFatal("cannot write %s", qPrintable(path));
        return path;
    };
    const SceneImport metres = importScene(original.fileName());
    const SceneImport centimetres =
        importScene(variant("cm.dae", R"(<unit name="centimeter" meter="0.01"/>)", "<up_axis>Z_UP</up_axis>"));
    QCOMPARE(centimetres.file.values.metresPerUnit, 0.01);
    QCOMPARE(centimetres.scene.objects.size(), metres.scene.objects.size()); // no root object for the unit
    for (std::size_t i = 0; i < metres.scene.objects.size(); ++i) {
        const Pose a = metres.scene.objects[i].track.keys.back().pose;
        const Pose b = centimetres.scene.objects[i].track.keys.back().pose;
        QVERIFY((b.position - 0.01 * a.position).norm() < 1e-9);
        QVERIFY(degrees(a.orientation, b.orientation) < 1e-9);
    }

    const SceneImport yUp = importScene(variant("y.dae", R"(<unit meter="1"/>)", "<up_axis>Y_UP</up_axis>"));
    QCOMPARE(yUp.file.values.up, UpAxis::Y);
    const Pose asIs = metres.scene.objects.front().track.keys.back().pose;
    const Pose turned = yUp.scene.objects.front().track.keys.back().pose;
    QVERIFY(degrees(turned.orientation, kYUpToZUp * asIs.orientation) < 1e-9);

    const SceneImport xUp = importScene(variant("x.dae", R"(<unit meter="1"/>)", "<up_axis>X_UP</up_axis>"));
    QCOMPARE(xUp.file.values.up, UpAxis::Y);
    QCOMPARE(xUp.warnings.filter(QStringLiteral("its up axis is X_UP")).size(), 1);
}

void TstBlenderFixtures::blendersEmptyIsAnEmpty_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<double>("toleranceDegrees");
    QTest::addColumn<bool>("framesTurned");
    QTest::newRow("fbx") << "blender_empty_and_mesh.fbx" << 0.01 << false;
    QTest::newRow("glb") << "blender_empty_and_mesh.glb" << 0.2 << true;
}

// Blender's animated Empty (a Null Model in FBX, a node without a mesh in glTF) with a mesh object as its
// child: the Empty comes in as an Empty, the mesh object as none, and both move as Blender evaluated them.
void TstBlenderFixtures::blendersEmptyIsAnEmpty()
{
    QFETCH(QString, file);
    QFETCH(double, toleranceDegrees);
    QFETCH(bool, framesTurned);
    const model::Scene scene = importScene(dataFile(file)).scene;
    QCOMPARE(scene.objects.size(), std::size_t{2});
    const model::SceneObject* pivot = objectNamed(scene, QStringLiteral("Pivot"));
    const model::SceneObject* blade = objectNamed(scene, QStringLiteral("Blade"));
    QVERIFY(pivot && blade);
    QVERIFY(pivot->empty);
    QVERIFY(pivot->mesh == nullptr);
    QVERIFY(!blade->empty);
    QVERIFY(blade->mesh != nullptr);
    QCOMPARE(blade->parent, pivot->id);
    const std::vector<BlenderFrame> frames = blenderFrames(QStringLiteral("blender_empty_and_mesh.json"));
    QCOMPARE(frames.size(), std::size_t{11});
    checkAgainstBlender(scene, frames, {QStringLiteral("Pivot"), QStringLiteral("Blade")}, toleranceDegrees, framesTurned,
                        file);
}

// Blender's bar weighted to a two-bone armature whose bones turn (glb): skinned by Gyre (model/skinning.h)
// at each frame's time, every vertex lies within 1e-4 m of a vertex of Blender's evaluated mesh, and the
// other way round; so too after Gyre writes it as FBX (a Skin deformer, a Cluster per joint) or Collada (a
// skin controller) and reads that back. The bar deforms: a vertex moves more than 0.5 m.
void TstBlenderFixtures::blendersSkinnedBarDeformsAsInBlender()
{
    QFile file(dataFile(QStringLiteral("blender_skinned_bar.json")));
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonObject evaluation = QJsonDocument::fromJson(file.readAll()).object();
    const model::Scene scene = importScene(dataFile(QStringLiteral("blender_skinned_bar.glb"))).scene;
    for (const QString& bone : {QStringLiteral("Upper"), QStringLiteral("Lower")}) {
        const model::SceneObject* joint = objectNamed(scene, bone);
        QVERIFY2(joint && !joint->empty, qPrintable(bone));
    }
    QTemporaryDir folder;
    std::vector<std::pair<QString, model::Scene>> scenes{{QString(), scene}};
    for (const QString& extension : {QStringLiteral("fbx"), QStringLiteral("dae")}) {
        const QString path = folder.filePath(QStringLiteral("bar.") + extension);
        exportScene(scene, path, *sceneFormatOfPath(path), scene.fps);
        scenes.emplace_back(QStringLiteral(" through ") + extension, importScene(path).scene);
    }
    for (const auto& [through, skinned] : scenes) {
        const SkinnedComparison compared = compareSkinning(skinned, evaluation);
        QVERIFY2(compared.skinned, qPrintable(QStringLiteral("the bar%1 has no skin").arg(through)));
        QCOMPARE(compared.frames, std::size_t{11});
        QVERIFY2(compared.moved > 0.5, qPrintable(QString::number(compared.moved)));
        QVERIFY2(compared.worst <= 1e-4, qPrintable(QStringLiteral("worst vertex%1 %2 m").arg(through).arg(compared.worst)));
        qInfo("skinned bar%s: worst vertex %.2e m over %zu frames", qPrintable(through), compared.worst, compared.frames);
    }
}

} // namespace gyre

QTEST_GUILESS_MAIN(gyre::TstBlenderFixtures)
#include "tst_blender_fixtures.moc"
