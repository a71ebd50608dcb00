// Gyre's binary FBX (io/fbx_scene_writer.h) read back two ways: by Assimp, the reader Gyre's import
// uses (importScene), and by a small reader of the node records written here, which checks what the
// file says independently of any importer: the frame rate, the time span, and the Euler curves.
// Every bundled sample and a scene with UTF-8, spaces, duplicate names, a parent chain and a spin of
// more than 180° between keys must come back with every object, its parent, and its orientation at
// every baked sample within 0.01° of model::bakeTrack of the original.

#include "io/fbx_scene_writer.h"
#include "io/scene_export.h"
#include "io/scene_import.h"
#include "model/project_file.h"
#include "model/track_evaluation.h"
#include "scene_test_support.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <QDir>
#include <QFile>
#include <QObject>
#include <QTemporaryDir>
#include <QTest>

#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <string>
#include <vector>

using namespace gyre;
using namespace gyre::io;
using namespace gyre::test;

namespace {

constexpr double kDegree = kPi / 180.0;
constexpr double kAngleTolerance = 0.01 * kDegree;

// --- a reader of binary FBX 7.4 node records, for the checks --------------------------------------

struct FbxNode {
    std::string name;
    std::vector<std::pair<char, std::string>> properties; // type and payload bytes (arrays: past their 12-byte head)
    std::vector<FbxNode> children;

    const FbxNode* child(const std::string& wanted) const
    {
        for (const FbxNode& c : children)
            if (c.name == wanted)
                return &c;
        return nullptr;
    }

    template <class T>
    T scalar(std::size_t index) const
    {
        T value;
        std::memcpy(&value, properties.at(index).second.data(), sizeof(T));
        return value;
    }

    template <class T>
    std::vector<T> array(std::size_t index) const
    {
        const std::string& bytes = properties.at(index).second;
        std::vector<T> values(bytes.size() / sizeof(T));
        if (!values.empty())
            std::memcpy(values.data(), bytes.data(), values.size() * sizeof(T));
        return values;
    }

    std::string text(std::size_t index) const { return properties.at(index).second; }
};

class FbxReader {
public:
    explicit FbxReader(const QByteArray& file)
        : data_(file.toStdString())
    {
    }

    // The top-level nodes; fails on a record whose end offset is not where its contents end.
    FbxNode read()
    {
        if (data_.compare(0, 23, std::string("Kaydara FBX Binary  \0\x1a\0", 23)) != 0 || word(23) != 7400)
            throw std::runtime_error("not binary FBX 7400");
        FbxNode root;
        std::size_t at = 27;
        while (word(at) != 0)
            root.children.push_back(node(at));
        return root;
    }

private:
    std::uint32_t word(std::size_t at) const
    {
        if (at + 4 > data_.size())
            throw std::runtime_error("past the end of the file");
        std::uint32_t value;
        std::memcpy(&value, data_.data() + at, 4);
        return value;
    }

    FbxNode node(std::size_t& at) const
    {
        const std::uint32_t end = word(at);
        const std::uint32_t count = word(at + 4);
        FbxNode result;
        result.name = data_.substr(at + 13, static_cast<unsigned char>(data_.at(at + 12)));
        at += 13 + result.name.size();
        for (std::uint32_t i = 0; i < count; ++i) {
            const char type = data_.at(at++);
            std::size_t size = 0;
            switch (type) {
            case 'C': size = 1; break;
            case 'Y': size = 2; break;
            case 'I': case 'F': size = 4; break;
            case 'D': case 'L': size = 8; break;
            case 'S': case 'R': size = word(at); at += 4; break;
            default: // an array: count, encoding (0 here), byte length
                if (word(at + 4) != 0)
                    throw std::runtime_error("compressed array");
                size = word(at + 8);
                at += 12;
            }
            result.properties.emplace_back(type, data_.substr(at, size));
            at += size;
        }
        if (at < end) {
            while (at < end - 13)
                result.children.push_back(node(at));
            at += 13;
        }
        if (at != end)
            throw std::runtime_error("a node's end offset is not where it ends: " + result.name);
        return result;
    }

    std::string data_;
};

FbxNode readFbx(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw std::runtime_error("cannot open the file");
    return FbxReader(file.readAll()).read();
}

// The value of a P entry of a Properties70 list (its fifth property).
const FbxNode* propertyEntry(const FbxNode& owner, const std::string& name)
{
    for (const FbxNode& p : owner.child("Properties70")->children)
        if (p.text(0) == name)
            return &p;
    return nullptr;
}

// The Lcl Rotation curves of every model that has them: each channel's key times, values (degrees) and flags.
struct RotationCurves {
    QString name;
    std::array<std::vector<std::int64_t>, 3> channelTimes;
    std::vector<std::vector<float>> angles;
    std::array<std::vector<std::int32_t>, 3> flags;
};

std::vector<RotationCurves> rotationCurvesOf(const FbxNode& fbx)
{
    const FbxNode& objects = *fbx.child("Objects");
    // Curves by id, and which curve feeds which channel of which curve node.
    std::map<std::int64_t, const FbxNode*> byId;
    for (const FbxNode& o : objects.children)
        byId[o.scalar<std::int64_t>(0)] = &o;
    std::map<std::int64_t, std::map<std::string, std::int64_t>> channels; // curve node -> d|X.. -> curve
    std::map<std::int64_t, std::pair<std::int64_t, std::string>> targets; // curve node -> model, property
    for (const FbxNode& c : fbx.child("Connections")->children)
        if (c.text(0) == "OP") {
            const std::int64_t source = c.scalar<std::int64_t>(1);
            const std::int64_t destination = c.scalar<std::int64_t>(2);
            if (byId.at(source)->name == "AnimationCurve")
                channels[destination][c.text(3)] = source;
            else
                targets[source] = {destination, c.text(3)};
        }
    std::vector<RotationCurves> result;
    for (const auto& [curveNode, target] : targets) {
        if (target.second != "Lcl Rotation")
            continue;
        RotationCurves rotation;
        const std::string modelName = byId.at(target.first)->text(1);
        rotation.name = QString::fromUtf8(modelName.substr(0, modelName.find('\0')));
        const auto& curves = channels.at(curveNode);
        std::size_t axis = 0;
        for (const char* channel : {"d|X", "d|Y", "d|Z"}) {
            const FbxNode& curve = *byId.at(curves.at(channel));
            rotation.channelTimes[axis] = curve.child("KeyTime")->array<std::int64_t>(0);
            rotation.angles.push_back(curve.child("KeyValueFloat")->array<float>(0));
            rotation.flags[axis] = curve.child("KeyAttrFlags")->array<std::int32_t>(0);
            ++axis;
        }
        result.push_back(std::move(rotation));
    }
    return result;
}

// --- comparing motion -------------------------------------------------------------------------------

// FBX's Euler XYZ written out independently of Gyre's core: R = Rz(z)·Ry(y)·Rx(x), angles in degrees.
Eigen::Quaterniond fbxEulerXyz(double x, double y, double z)
{
    using Eigen::AngleAxisd;
    return AngleAxisd(z * kDegree, Eigen::Vector3d::UnitZ()) * AngleAxisd(y * kDegree, Eigen::Vector3d::UnitY()) *
           AngleAxisd(x * kDegree, Eigen::Vector3d::UnitX());
}

const model::SceneObject* objectNamed(const model::Scene& scene, const QString& name)
{
    for (const model::SceneObject& object : scene.objects)
        if (object.name == name)
            return &object;
    return nullptr;
}

QString parentName(const model::Scene& scene, const model::SceneObject& object)
{
    for (const model::SceneObject& candidate : scene.objects)
        if (candidate.id == object.parent)
            return candidate.name;
    return {};
}

model::SceneObject spinner(model::Scene& scene, const char* name, model::ObjectId parent, const Eigen::Vector3d& axis,
                           double step, double keySpacing, int keys)
{
    model::SceneObject object;
    object.id = scene.nextObjectId++;
    object.name = QString::fromUtf8(name);
    object.parent = parent;
    object.track.interpolation = InterpolationMethod::Slerp;
    for (int k = 0; k < keys; ++k) {
        const Eigen::Quaterniond turned(Eigen::AngleAxisd(k * step, axis.normalized()));
        object.track.keys.push_back({k * keySpacing, {turned, {0.1 * k, 1.0, -0.5 * k}}, true});
    }
    return object;
}

// Names in UTF-8 with spaces, two objects named alike, a chain three deep, and spins whose Euler
// angles pass ±180°: 170° about z at every frame at 30 fps, and a tumble about a tilted axis.
model::Scene awkwardScene()
{
    model::Scene scene;
    scene.fps = 30.0;
    scene.startTime = 0.0;
    scene.endTime = 2.0;
    const model::SceneObject root =
        spinner(scene, "Würfel Ä 1", model::kNoObject, {0, 0, 1}, 170.0 * kDegree, 1.0 / 30.0, 61);
    model::SceneObject middle = spinner(scene, "twin", root.id, {1, 1, 0}, 100.0 * kDegree, 0.25, 9);
    middle.mesh = std::make_shared<model::Mesh>(model::Mesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {}, {0, 1, 2}, {}});
    const model::SceneObject leaf = spinner(scene, "twin", middle.id, {0.3, -1, 0.6}, 150.0 * kDegree, 0.5, 5);
    const model::SceneObject still = spinner(scene, "still one", model::kNoObject, {1, 0, 0}, 0.0, 1.0, 1);
    scene.objects = {root, middle, leaf, still};
    return scene;
}

} // namespace

class TstFbxExport : public QObject {
    Q_OBJECT

private slots:
    void everyObjectAtEverySample_data();
    void everyObjectAtEverySample();
    void curvesAreUnwrappedAndPlayTheShortWay();
    void aTwoTurnEulerSpinIsARampToTwoTurns();
    void frameRateAndSpanAreStored_data();
    void frameRateAndSpanAreStored();
    void aSpanBeyondFbxTicksIsRefused();
    void anEmptyIsANullModelWithANullAttribute();

private:
    QString path(const QString& name) const { return directory_.filePath(name); }
    QTemporaryDir directory_;
};

void TstFbxExport::everyObjectAtEverySample_data()
{
    QTest::addColumn<QString>("project");
    QTest::newRow("awkward names, chain, spins") << QString();
    const QDir samples(QStringLiteral(GYRE_SAMPLES_DIR));
    for (const QString& file : samples.entryList({QStringLiteral("*.gyre")}, QDir::Files, QDir::Name))
        QTest::newRow(qPrintable(file)) << QStringLiteral(GYRE_SAMPLES_DIR "/") + file;
}

void TstFbxExport::everyObjectAtEverySample()
{
    QFETCH(QString, project);
    const model::Scene original = project.isEmpty() ? awkwardScene() : model::readProject(project);
    const QString file = path(QStringLiteral("scene.fbx"));
    const ExportReport report = exportScene(original, file, SceneFormat::Fbx, original.fps);
    QCOMPARE(report.files, QStringList{file});
    const model::Scene back = importScene(file).scene;

    const model::BakeRange range{original.startTime, original.endTime, original.fps};
    QCOMPARE(back.objects.size(), original.objects.size());
    std::map<QString, int> seen;
    std::map<model::ObjectId, QString> exportedName;
    for (const model::SceneObject& before : original.objects) {
        // Duplicate names come back as the export made them unique: "twin", then "twin_2".
        const int repeat = ++seen[before.name];
        const QString name = repeat == 1 ? before.name : before.name + "_" + QString::number(repeat);
        exportedName[before.id] = name;
        const model::SceneObject* after = objectNamed(back, name);
        QVERIFY2(after, qPrintable(name + " is missing"));
        QCOMPARE(parentName(back, *after), before.parent == model::kNoObject ? QString() : exportedName.at(before.parent));

        const std::vector<model::TimedPose> baked =
            model::bakeTrack(before.track, range, model::flightBodyOf(before), original.gravity);
        const model::TrackMotion imported(after->track);
        const bool moves = before.track.keys.size() > 1 || !before.track.sketch.fittedCurve.empty();
        if (moves) {
            QCOMPARE(after->track.keys.size(), baked.size());
            QVERIFY(std::abs(after->track.keys.back().time - original.endTime) < 1e-9);
        }
        double worst = 0.0;
        double worstTime = 0.0;
        for (const model::TimedPose& sample : baked) {
            const Pose pose = imported.at(sample.time);
            const double angle = angleBetween(pose.orientation, sample.pose.orientation);
            if (angle > worst) {
                worst = angle;
                worstTime = sample.time;
            }
            GYRE_CHECK((pose.position - sample.pose.position).norm() < 1e-5 * std::max(1.0, sample.pose.position.norm()),
                       name + " moved at " + str(sample.time));
        }
        GYRE_CHECK(worst < kAngleTolerance,
                   QStringLiteral("%1: off by %2° at %3 s").arg(name, str(worst / kDegree), str(worstTime)));
    }
}

// In the file itself: each rotation curve's consecutive keys differ by at most 180°, the angles give
// the baked orientation as Rz·Ry·Rx, and for the spin about z (170° a frame) halfway between two
// keys the linearly interpolated angles give the orientation the project has there.
void TstFbxExport::curvesAreUnwrappedAndPlayTheShortWay()
{
    const model::Scene original = awkwardScene();
    const QString file = path(QStringLiteral("spins.fbx"));
    exportScene(original, file, SceneFormat::Fbx, original.fps);
    int rotationNodes = 0;
    for (const RotationCurves& rotation : rotationCurvesOf(readFbx(file))) {
        ++rotationNodes;
        const QString& name = rotation.name;
        const std::vector<std::int64_t>& times = rotation.channelTimes[0];
        const std::vector<std::vector<float>>& angles = rotation.angles;
        for (std::size_t axis = 0; axis < 3; ++axis) {
            QCOMPARE(rotation.channelTimes[axis], times);
            QCOMPARE(rotation.flags[axis], std::vector<std::int32_t>{4}); // linear
            for (std::size_t k = 1; k < times.size(); ++k)
                GYRE_CHECK(std::abs(angles[axis][k] - angles[axis][k - 1]) <= 180.0f,
                           name + " jumps at key " + QString::number(k));
        }
        const bool twin = name.startsWith(QStringLiteral("twin"));
        const model::SceneObject& before = original.objects[name == "twin_2" ? 2 : twin ? 1 : 0];
        const model::TrackMotion motion(before.track);
        for (std::size_t k = 0; k < times.size(); ++k) {
            const double time = static_cast<double>(times[k]) / static_cast<double>(kFbxTicksPerSecond);
            const Eigen::Quaterniond q = fbxEulerXyz(angles[0][k], angles[1][k], angles[2][k]);
            GYRE_CHECK(angleBetween(q, motion.at(time).orientation) < kAngleTolerance, name + " at " + str(time));
        }
        if (name != QStringLiteral("Würfel Ä 1"))
            continue;
        QCOMPARE(times.size(), std::size_t{61});
        for (std::size_t k = 1; k < times.size(); ++k) {
            const double mid = 0.5 * static_cast<double>(times[k - 1] + times[k]) / static_cast<double>(kFbxTicksPerSecond);
            const auto halfway = [&](int axis) { return 0.5 * (double{angles[axis][k - 1]} + double{angles[axis][k]}); };
            const Eigen::Quaterniond q = fbxEulerXyz(halfway(0), halfway(1), halfway(2));
            GYRE_CHECK(angleBetween(q, motion.at(mid).orientation) < kAngleTolerance, "halfway at " + str(mid));
        }
    }
    QCOMPARE(rotationNodes, 3); // the still object has no curves
}

// An object in Euler rotation mode keyed 0° and 720° about z, 2 s apart, linear in its angles: the exported z
// curve rises steadily through 360° at the middle to 720°, since it is unwrapped from the frames.
void TstFbxExport::aTwoTurnEulerSpinIsARampToTwoTurns()
{
    model::Scene scene;
    scene.fps = 24.0;
    scene.endTime = 2.0;
    model::SceneObject spin;
    spin.id = scene.nextObjectId++;
    spin.name = QStringLiteral("spin");
    spin.track.rotationMode.kind = model::RotationMode::Kind::Euler;
    spin.track.interpolation = InterpolationMethod::Euler;
    for (const double turns : {0.0, 2.0}) {
        model::Keyframe key;
        key.time = turns;
        key.eulerAngles = Eigen::Vector3d(0.0, 0.0, 2.0 * std::numbers::pi * turns);
        key.pose.orientation = fbxEulerXyz(0.0, 0.0, 360.0 * turns);
        spin.track.keys.push_back(key);
    }
    scene.objects = {spin};
    const QString file = path(QStringLiteral("two-turns.fbx"));
    exportScene(scene, file, SceneFormat::Fbx, scene.fps);
    const std::vector<RotationCurves> curves = rotationCurvesOf(readFbx(file));
    QCOMPARE(curves.size(), std::size_t{1});
    const std::vector<float>& z = curves.front().angles[2];
    const std::vector<std::int64_t>& times = curves.front().channelTimes[2];
    QCOMPARE(z.size(), std::size_t{49});
    for (std::size_t k = 0; k < z.size(); ++k) {
        const double time = static_cast<double>(times[k]) / static_cast<double>(kFbxTicksPerSecond);
        GYRE_CHECK(std::abs(double{z[k]} - 360.0 * time) < 1e-3, "z at " + str(time));
    }
    QVERIFY(std::abs(z[24] - 360.0f) < 1e-3f);
    QVERIFY(std::abs(z.back() - 720.0f) < 1e-3f);
}

void TstFbxExport::frameRateAndSpanAreStored_data()
{
    QTest::addColumn<double>("fps");
    QTest::addColumn<double>("start");
    QTest::addColumn<double>("end");
    QTest::addColumn<int>("timeMode");
    QTest::newRow("pen: 30 fps, 4.033 s") << 30.0 << 0.0 << 121.0 / 30.0 << 6;
    QTest::newRow("24 fps") << 24.0 << 0.0 << 2.5 << 11;
    QTest::newRow("120 fps") << 120.0 << 0.0 << 1.0 << 1;
    QTest::newRow("12.5 fps: custom") << 12.5 << 0.0 << 3.1 << 14;
    QTest::newRow("starting at 0.5 s") << 25.0 << 0.5 << 2.0 << 10;
}

// GlobalSettings carries the frame rate and the span exactly; Assimp reads the frame rate as ticks
// per second and keeps every key time, the last at the end.
void TstFbxExport::frameRateAndSpanAreStored()
{
    QFETCH(double, fps);
    QFETCH(double, start);
    QFETCH(double, end);
    QFETCH(int, timeMode);
    model::Scene scene;
    scene.fps = fps;
    scene.startTime = start;
    scene.endTime = end;
    scene.objects = {spinner(scene, "turning", model::kNoObject, {0, 1, 0}, 0.4, 0.7, 5)};
    const QString file = path(QStringLiteral("rate.fbx"));
    exportScene(scene, file, SceneFormat::Fbx, fps);

    const FbxNode fbx = readFbx(file);
    const FbxNode& settings = *fbx.child("GlobalSettings");
    QCOMPARE(propertyEntry(settings, "TimeMode")->scalar<std::int32_t>(4), timeMode);
    QCOMPARE(propertyEntry(settings, "CustomFrameRate")->scalar<double>(4), fps);
    QCOMPARE(propertyEntry(settings, "TimeSpanStart")->scalar<std::int64_t>(4), std::llround(start * 46186158000.0));
    QCOMPARE(propertyEntry(settings, "TimeSpanStop")->scalar<std::int64_t>(4), std::llround(end * 46186158000.0));
    // Gyre's world is z up (its viewport's ground is the xy plane) and its unit is a metre to Blender.
    QCOMPARE(propertyEntry(settings, "UpAxis")->scalar<std::int32_t>(4), 2);
    QCOMPARE(propertyEntry(settings, "UpAxisSign")->scalar<std::int32_t>(4), 1);
    QCOMPARE(propertyEntry(settings, "UnitScaleFactor")->scalar<double>(4), 100.0);

    Assimp::Importer importer;
    const aiScene* read = importer.ReadFile(QFile::encodeName(file).toStdString(), 0);
    QVERIFY2(read, importer.GetErrorString());
    QCOMPARE(read->mNumAnimations, 1u);
    const aiAnimation& animation = *read->mAnimations[0];
    QCOMPARE(animation.mTicksPerSecond, static_cast<double>(static_cast<float>(fps)));
    QVERIFY(std::abs(animation.mDuration / animation.mTicksPerSecond - end) < 1e-9);
    const aiNodeAnim& channel = *animation.mChannels[0];
    const std::vector<double> expected = model::bakeTimes(model::keyTimes(scene.objects[0].track), {start, end, fps});
    QCOMPARE(channel.mNumRotationKeys, static_cast<unsigned>(expected.size()));
    for (unsigned k = 0; k < channel.mNumRotationKeys; ++k)
        QVERIFY(std::abs(channel.mRotationKeys[k].mTime / animation.mTicksPerSecond - expected[k]) < 1e-9);
}

// FBX ticks are 64-bit: a range of 10^9 s cannot be written. The error names the file, and no file
// is left behind.
void TstFbxExport::aSpanBeyondFbxTicksIsRefused()
{
    model::Scene scene;
    scene.endTime = 1e9;
    scene.objects = {spinner(scene, "still", model::kNoObject, {0, 1, 0}, 0.0, 1.0, 1)};
    const QString file = path(QStringLiteral("too-long.fbx"));
    try {
        exportScene(scene, file, SceneFormat::Fbx, 24.0);
        QFAIL("a span beyond FBX's ticks was written");
    } catch (const OutputError& error) {
        QVERIFY2(QString::fromUtf8(error.what()).startsWith(file + ": cannot be written as FBX"), error.what());
    }
    QVERIFY(!QFile::exists(file));
}

// An Empty's Model carries a NodeAttribute Null, as Blender writes its Empties, and comes back an Empty;
// two objects without meshes joined as a skeleton's nodes are come back as joints, not Empties.
void TstFbxExport::anEmptyIsANullModelWithANullAttribute()
{
    model::Scene scene;
    scene.endTime = 1.0;
    model::SceneObject pivot = spinner(scene, "Pivot", model::kNoObject, {0, 0, 1}, 0.5, 0.5, 3);
    pivot.empty = true;
    model::SceneObject block = spinner(scene, "Block", pivot.id, {1, 0, 0}, 0.25, 1.0, 2);
    block.mesh = std::make_shared<model::Mesh>(model::Mesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {}, {0, 1, 2}, {}});
    const model::SceneObject hips = spinner(scene, "Hips", model::kNoObject, {0, 1, 0}, 0.3, 0.5, 3);
    const model::SceneObject knee = spinner(scene, "Knee", hips.id, {1, 0, 0}, 0.2, 0.5, 3);
    scene.objects = {pivot, block, hips, knee};
    const QString file = path(QStringLiteral("empty.fbx"));
    exportScene(scene, file, SceneFormat::Fbx, 24.0);

    const FbxNode fbx = readFbx(file);
    std::map<std::int64_t, std::string> modelNames;
    std::vector<std::int64_t> nullAttributes;
    for (const FbxNode& object : fbx.child("Objects")->children) {
        const std::string name = object.text(1).substr(0, object.text(1).find('\0'));
        if (object.name == "Model")
            modelNames[object.scalar<std::int64_t>(0)] = name;
        if (object.name == "NodeAttribute") {
            QCOMPARE(object.text(2), std::string("Null"));
            QCOMPARE(object.child("TypeFlags")->text(0), std::string("Null"));
            QCOMPARE(name, std::string("Pivot"));
            nullAttributes.push_back(object.scalar<std::int64_t>(0));
        }
    }
    QCOMPARE(nullAttributes.size(), std::size_t{1});
    std::vector<std::string> holders;
    for (const FbxNode& c : fbx.child("Connections")->children)
        if (c.text(0) == "OO" && c.scalar<std::int64_t>(1) == nullAttributes.front())
            holders.push_back(modelNames.at(c.scalar<std::int64_t>(2)));
    QCOMPARE(holders, std::vector<std::string>{"Pivot"});
    int counted = 0;
    for (const FbxNode& type : fbx.child("Definitions")->children)
        if (type.name == "ObjectType" && type.text(0) == "NodeAttribute")
            counted = type.child("Count")->scalar<std::int32_t>(0);
    QCOMPARE(counted, 1);

    const model::Scene back = importScene(file).scene;
    for (const auto& [name, empty] : {std::pair{"Pivot", true}, {"Block", false}, {"Hips", false}, {"Knee", false}}) {
        const model::SceneObject* object = objectNamed(back, QString::fromUtf8(name));
        QVERIFY2(object, name);
        QVERIFY2(object->empty == empty, name);
    }
    QVERIFY(objectNamed(back, QStringLiteral("Pivot"))->track.keys.size() > 2); // its motion came too
}

QTEST_GUILESS_MAIN(TstFbxExport)
#include "tst_fbx_export.moc"
