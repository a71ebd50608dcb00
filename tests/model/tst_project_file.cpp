// The project file as its users meet it: what is saved loads back exactly, older versions load,
// newer ones are refused with a clear message, and no input, however broken, crashes the reader or
// half-loads a scene. Every refusal names the file and the field. The fixtures are written here,
// by hand, following docs/file-format.md rather than the writer: version 2's JSON text, and version
// 3's header and blocks.

#include "model_test_support.h"

#include "model/input_error.h"
#include "model/project_file.h"
#include "model/value_checks.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>
#include <QtEndian>

#include <cstring>
#include <functional>
#include <random>
#include <set>

using namespace gyre;
using namespace gyre::model;

namespace {

QJsonArray array(std::initializer_list<double> values)
{
    QJsonArray result;
    for (double value : values)
        result.append(value);
    return result;
}

QJsonObject keyframe(double time, QJsonArray orientation = array({1, 0, 0, 0}))
{
    return {{"time", time}, {"orientation", orientation}, {"position", array({0, 0, 0})}, {"constrained", true}};
}

QJsonObject emptySketch()
{
    return {{"directionStrokes", QJsonArray()}, {"magnitude", QJsonArray()}, {"pattern", QJsonArray()},
            {"patternRepeat", 0},           {"window", QJsonValue()},    {"alpha", 0.002},
            {"beta", 1},                    {"delta", 0.1},              {"fittedCurve", QJsonArray()}};
}

QJsonObject object(int id, QJsonValue parent = QJsonValue())
{
    return {{"id", id},
            {"name", QStringLiteral("object %1").arg(id)},
            {"parent", parent},
            {"mesh", QJsonValue()},
            {"interpolation", "slerp"},
            {"subdivision", QJsonObject{{"scheme", "jarek"}, {"levels", 4}, {"cyclic", true}, {"decoupled", false}}},
            {"keyframes", QJsonArray{keyframe(0), keyframe(0.75), keyframe(1.5)}},
            {"sketch", emptySketch()}};
}

// One triangle: positions (0,0,0), (1,0,0), (0,1,0) as little-endian float32, indices 0, 1, 2 as uint32.
QJsonObject triangleMesh()
{
    return {{"positions", "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"},
            {"normals", ""},
            {"indices", "AAAAAAEAAAACAAAA"}};
}

// A valid version 2 project: object 1 with child 2, which uses the triangle mesh.
QJsonObject validProject()
{
    QJsonObject child = object(2, 1);
    child["mesh"] = 0;
    return {{"format", "gyre-project"}, {"version", 2},          {"fps", 24},
            {"startTime", 0},           {"endTime", 10},         {"currentTime", 0},
            {"meshes", QJsonArray{triangleMesh()}}, {"objects", QJsonArray{object(1), child}}};
}

QByteArray bytes(const QJsonObject& project) { return QJsonDocument(project).toJson(); }

// Sets the value at a path of members and array indices, such as {"objects", 0, "name"}.
void setAt(QJsonValueRef target, QVariantList path, const QJsonValue& value, bool remove = false)
{
    if (path.isEmpty()) {
        target = value;
        return;
    }
    const QVariant step = path.takeFirst();
    if (step.typeId() == QMetaType::Int) {
        QJsonArray inner = target.toArray();
        setAt(inner[step.toInt()], path, value, remove);
        target = inner;
    } else {
        QJsonObject inner = target.toObject();
        if (remove && path.isEmpty())
            inner.remove(step.toString());
        else
            setAt(inner[step.toString()], path, value, remove);
        target = inner;
    }
}

QByteArray projectWith(const QVariantList& path, const QJsonValue& value)
{
    QJsonArray root{validProject()};
    setAt(root[0], path, value);
    return bytes(root[0].toObject());
}

QByteArray projectWithout(const QVariantList& path)
{
    QJsonArray root{validProject()};
    setAt(root[0], path, QJsonValue(), true);
    return bytes(root[0].toObject());
}

// Values as the blocks of a version 3 file hold them: little-endian.
template <class Value>
QByteArray little(std::initializer_list<Value> values)
{
    QByteArray bytes;
    for (Value value : values) {
        char at[sizeof(Value)];
        qToLittleEndian(value, at);
        bytes.append(at, sizeof at);
    }
    return bytes;
}

// A version 3 file: "gyre-project", the version and the header's length, the header, the blocks.
QByteArray binaryProject(const QByteArray& header, const QByteArray& blocks, quint32 version = 3)
{
    return QByteArray("gyre-project") + little<quint32>({version}) + little<quint64>({quint64(header.size())}) + header +
           blocks;
}

QByteArray binaryProject(const QJsonObject& header, const QByteArray& blocks)
{
    return binaryProject(QJsonDocument(header).toJson(), blocks);
}

// The header of a version 3 file.
QJsonObject headerOf(const QByteArray& file)
{
    const auto length = qFromLittleEndian<quint64>(file.constData() + 16);
    return QJsonDocument::fromJson(file.mid(24, static_cast<qsizetype>(length))).object();
}

QJsonObject keyLayout(int count, int times, QJsonValue position = QJsonValue(), QJsonValue constrained = QJsonValue())
{
    return {{"count", count}, {"times", times}, {"position", position}, {"constrained", constrained}};
}

// A valid version 3 header: one object with three keys, at the times of list 0, their positions and
// flags listed in the block; `controlPoints` of an applied fit in the block after them; no keys before
// a fit, at the empty list 1.
QJsonObject binaryHeader(QJsonObject keyframes = keyLayout(3, 0), int controlPoints = 0)
{
    QJsonObject sketch = emptySketch();
    sketch["fittedCurve"] = QJsonObject{{"count", controlPoints}};
    sketch["keysBeforeFit"] = keyLayout(0, 1);
    QJsonObject only = object(1);
    only["keyframes"] = keyframes;
    only["sketch"] = sketch;
    return {{"fps", 24},          {"startTime", 0},           {"endTime", 10},
            {"currentTime", 0},   {"meshes", QJsonArray()},   {"times", QJsonArray{3, 0}},
            {"objects", QJsonArray{only}}};
}

// Its blocks, in order: time list 0, then the keys: orientations, positions, flags.
struct BinaryBlocks {
    QByteArray times = little<double>({0, 0.5, 1});
    QByteArray orientations = little<double>({1, 0, 0, 0, 0, 0, 0, 1, 0.6, 0.8, 0, 0});
    QByteArray positions = little<double>({0, 0, 0, 1, 2, 3, 4, 5, 6});
    QByteArray flags = QByteArray("\1\0\1", 3);

    QByteArray all() const { return times + orientations + positions + flags; }
};

// The valid blocks with the float64 at `index` of `member` replaced.
QByteArray blocksWith(QByteArray BinaryBlocks::*member, int index, double value)
{
    BinaryBlocks blocks;
    (blocks.*member).replace(index * 8, 8, little<double>({value}));
    return blocks.all();
}

// Version 3's blocks damaged or lying about their lengths: each refused, naming the field, and a
// length the file does not hold refused before anything is allocated for it. Rows of
// refusesMalformedFiles.
void damagedBlockRows()
{
    const auto row = [](const char* name, const QByteArray& contents, const QString& message) {
        QTest::newRow(name) << contents << message;
    };
    const QByteArray valid = BinaryBlocks().all();
    const double nan = std::nan("");
    row("truncated block", binaryProject(binaryHeader(), valid.chopped(5)),
        "objects[0].keyframes: its block needs 171 bytes; the file has 166 left");
    row("bytes after the last block", binaryProject(binaryHeader(), valid + "x"),
        "the top level: the file goes on after its last block");
    row("NaN quaternion", binaryProject(binaryHeader(), blocksWith(&BinaryBlocks::orientations, 4, nan)),
        "objects[0].keyframes[1].orientation: not all components are finite");
    row("quaternion far from unit", binaryProject(binaryHeader(), blocksWith(&BinaryBlocks::orientations, 0, 2)),
        "objects[0].keyframes[0].orientation: the quaternion has length 2; it must have length 1");
    row("infinite position",
        binaryProject(binaryHeader(), blocksWith(&BinaryBlocks::positions, 5, std::numeric_limits<double>::infinity())),
        "objects[0].keyframes[1].position: not all components are finite");
    row("position beyond the bound", binaryProject(binaryHeader(), blocksWith(&BinaryBlocks::positions, 0, -1e308)),
        "objects[0].keyframes[0].position: position coordinate 1e+308 is beyond ±1e+09");
    row("NaN time", binaryProject(binaryHeader(), blocksWith(&BinaryBlocks::times, 1, nan)),
        "times[0][1]: nan is not a finite number");
    row("times out of order", binaryProject(binaryHeader(), blocksWith(&BinaryBlocks::times, 2, 0.25)),
        "times[0][2]: time 0.25 does not come after the time before it, 0.5");
    BinaryBlocks badFlag;
    badFlag.flags[1] = 2;
    row("flag neither 0 nor 1", binaryProject(binaryHeader(), badFlag.all()),
        "objects[0].keyframes[1].constrained: 2 is neither 0 nor 1");
    row("more keys than times", binaryProject(binaryHeader(keyLayout(4, 0)), valid),
        "objects[0].keyframes.times: time list 0 holds 3 times for 4 keys");
    row("no such time list", binaryProject(binaryHeader(keyLayout(3, 2)), valid),
        "objects[0].keyframes.times: 2 is outside 0 to 1");
    row("keys past the budget", binaryProject(binaryHeader(keyLayout(8388609, 0)), valid),
        "objects[0].keyframes.count: these 8388609 keys bring the file past the 8388608 keys a project may hold");
    QJsonObject manyTimes = binaryHeader(keyLayout(8000000, 0));
    manyTimes["times"] = QJsonArray{8000000, 0};
    row("count the file does not hold", binaryProject(manyTimes, valid),
        "times[0]: its block needs 64000000 bytes; the file has 195 left");
    manyTimes["times"] = QJsonArray{8388609, 0};
    row("times past the budget", binaryProject(manyTimes, valid),
        "times[0]: these 8388609 times bring the file past the 8388608 times a project may hold");
    const QByteArray header = QJsonDocument(binaryHeader()).toJson();
    QByteArray longHeader = binaryProject(header, valid);
    longHeader.replace(16, 8, little<quint64>({1'000'000}));
    row("header longer than the file", longHeader,
        QStringLiteral("header: its block needs 1000000 bytes; the file has %1 left").arg(header.size() + valid.size()));
    longHeader.replace(16, 8, little<quint64>({quint64{1} << 40}));
    row("header past its limit", longHeader, "header: 1099511627776 bytes; a header may hold at most 16777216");
    row("header not JSON", binaryProject(QByteArray("{\"fps\": "), valid), "header: not valid JSON: ");
    row("header an array", binaryProject(QByteArray("[]"), valid), "the top level: expected an object, found an array");
    row("version 2 in binary", binaryProject(header, valid, 2), "version: a version 2 file is JSON text, not binary");
    row("newer version in binary", binaryProject(header, valid, 4),
        "version: the file has version 4, newer than this build of Gyre reads (3 and older)");
    row("cut inside the preamble", QByteArray("gyre-project\3\0"), "the top level: the file ends inside its first 24 bytes");
    QJsonObject withMesh = binaryHeader();
    withMesh["meshes"] = QJsonArray{QJsonObject{{"positions", 3}, {"normals", 0}, {"indices", 3}}};
    const QByteArray triangle = little<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}) + little<quint32>({0, 1, 5});
    row("mesh index beyond its positions", binaryProject(withMesh, triangle + valid),
        "meshes[0]: mesh index 5 is beyond its 3 positions");
    row("mesh block cut", binaryProject(withMesh, triangle.left(20)),
        "meshes[0]: its block needs 48 bytes; the file has 20 left");
    // An applied fit's control points follow the keys: time, value w, x, y, z, derivative w, x, y, z.
    const QByteArray firstPoint = little<double>({0, 1, 0, 0, 0, 0, 0, 0, 0});
    row("fitted value zero in its block",
        binaryProject(binaryHeader(keyLayout(3, 0), 2), valid + firstPoint + little<double>({1, 0, 0, 0, 0, 0, 0, 0, 0})),
        "objects[0].sketch.fittedCurve[1].value: the value has length 0; a fitted value needs length at least 0.001");
    row("fitted times out of order",
        binaryProject(binaryHeader(keyLayout(3, 0), 2), valid + firstPoint + little<double>({0, 1, 0, 0, 0, 0, 0, 0, 0})),
        "objects[0].sketch.fittedCurve[1].time: time 0 does not come after the time before it, 0");
    row("fitted derivative too long",
        binaryProject(binaryHeader(keyLayout(3, 0), 1), valid + little<double>({0, 1, 0, 0, 0, 1e300, 0, 0, 0})),
        "objects[0].sketch.fittedCurve[0].derivative: the derivative has length 1e+300 per second");
    row("fitted curve past the budget", binaryProject(binaryHeader(keyLayout(3, 0), 8388606), valid),
        "objects[0].sketch.fittedCurve.count: these 8388606 control points bring the file past the 8388608 keys a "
        "project may hold");
    row("fitted curve cut", binaryProject(binaryHeader(keyLayout(3, 0), 2), valid + firstPoint),
        "objects[0].sketch.fittedCurve: its block needs 144 bytes; the file has 72 left");
}

std::uint64_t bitsOf(double value)
{
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

} // namespace

class TstProjectFile : public QObject {
    Q_OBJECT

private slots:
    void savedScenesLoadBackExactly();
    void numbersReadBackToTheSameBits();
    void ballisticTracksKeepTheirFlightChoices();
    void emptiesStayEmpties();
    void sharedMeshesStayShared();
    void tracksShareTimesAndConstantValues();
    void readsTheHandWrittenBinaryProject();
    void readsTheHandWrittenExample();
    void readsTheDocumentedExamples();
    void driftedQuaternionsAreNormalised();
    void migratesVersionOne();
    void anAbsoluteDeltaKeepsItsThreshold();
    void refusesMalformedFiles_data();
    void refusesMalformedFiles();
    void refusesUnusableFiles();
    void refusesFilesLargerThanTheCap();
    void neverCrashesOnDamagedFiles();
    void failedSaveKeepsTheOldFile();
    void aLongFitFitsAndAHeaderPastItsLimitIsNotSaved();
    void refusesToSaveWhatWouldNotReadBack();

private:
    QString write(const QString& name, const QByteArray& contents);
    QTemporaryDir directory_;
};

QString TstProjectFile::write(const QString& name, const QByteArray& contents)
{
    const QString path = directory_.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(contents) != contents.size())
        qFatal("cannot write the fixture %s", qPrintable(path));
    return path;
}

void TstProjectFile::savedScenesLoadBackExactly()
{
    for (unsigned seed : {1u, 2u, 3u}) {
        const Scene scene = test::RandomEdits(seed).scene(10);
        const QString path = directory_.filePath(QStringLiteral("round-trip-%1.gyre").arg(seed));
        writeProject(path, scene);
        const Scene loaded = readProject(path);
        QCOMPARE(projectBytes(loaded), projectBytes(scene));
        QCOMPARE(loaded.objects.size(), scene.objects.size());
        QCOMPARE(loaded.nextObjectId, scene.nextObjectId);
    }
}

void TstProjectFile::ballisticTracksKeepTheirFlightChoices()
{
    Scene scene;
    SceneObject object;
    object.id = 1;
    object.name = QStringLiteral("coin");
    object.track.interpolation = InterpolationMethod::Ballistic;
    object.track.keys = {{0.0, {}, true, 2}, {0.5, {}, true, -1}, {1.0, {}, true, 1}, {1.5, {}, true, -1}};
    scene.objects.push_back(object);
    scene.nextObjectId = 2;
    const QString path = directory_.filePath(QStringLiteral("ballistic.gyre"));
    writeProject(path, scene);
    const Scene loaded = readProject(path);
    QCOMPARE(loaded.objects.front().track.interpolation, InterpolationMethod::Ballistic);
    std::vector<int> choices;
    for (const Keyframe& key : loaded.objects.front().track.keys)
        choices.push_back(key.flightSolution);
    QCOMPARE(choices, (std::vector<int>{2, -1, 1, -1}));
    const auto written = [](const Scene& saved) {
        return headerOf(projectBytes(saved)).value("objects")[0].toObject().value("flightSolutions").toArray();
    };
    QCOMPARE(written(loaded), (QJsonArray{2, -1, 1}));
    // A track that never chose writes no choices.
    for (Keyframe& key : scene.objects.front().track.keys.edit())
        key.flightSolution = -1;
    QVERIFY(written(scene).isEmpty());
    // The scene's gravity: saved when set, and absent (today's default) when it is the default.
    QCOMPARE(readProject(path).gravity, Gravity{});
    scene.gravity = {1.62, UpDirection::MinusY};
    writeProject(path, scene);
    QCOMPARE(readProject(path).gravity, (Gravity{1.62, UpDirection::MinusY}));
}

void TstProjectFile::emptiesStayEmpties()
{
    Scene scene;
    SceneObject pivot;
    pivot.id = 1;
    pivot.name = QStringLiteral("pivot");
    pivot.empty = true;
    SceneObject block = pivot;
    block.id = 2;
    block.parent = 1;
    block.empty = false;
    scene.objects = {pivot, block};
    scene.nextObjectId = 3;
    const QByteArray bytes = projectBytes(scene);
    const Scene loaded = parseProject(bytes, QStringLiteral("empty.gyre"));
    QVERIFY(loaded.objects[0].empty && loaded.objects[0].mesh == nullptr);
    QVERIFY(!loaded.objects[1].empty);
    // Written for the empty alone: a file of objects without it is as before there were empties.
    QCOMPARE(bytes.count("\"empty\""), 1);
}

void TstProjectFile::numbersReadBackToTheSameBits()
{
    std::mt19937_64 engine(7);
    Scene scene;
    SceneObject object;
    object.id = 1;
    double time = -1e-300;
    for (int i = 0; i < 500; ++i) {
        // Random bit patterns cover every exponent a position may have; those that are not finite or
        // beyond kMaxPositionCoordinate are skipped.
        const std::uint64_t bits = engine();
        double value = 0;
        std::memcpy(&value, &bits, sizeof value);
        if (!(std::abs(value) <= kMaxPositionCoordinate))
            continue;
        time = std::nextafter(time + std::abs(std::fmod(value, 1.0)), INFINITY);
        object.track.keys.push_back({time, {Eigen::Quaterniond::Identity(), {value, 0.1, 1.0 / 3.0}}, true});
    }
    scene.objects.push_back(object);
    const Scene loaded = parseProject(projectBytes(scene), QStringLiteral("numbers.gyre"));
    const std::vector<Keyframe>& keys = loaded.objects.front().track.keys;
    QCOMPARE(keys.size(), object.track.keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i) {
        QCOMPARE(bitsOf(keys[i].time), bitsOf(object.track.keys[i].time));
        QCOMPARE(bitsOf(keys[i].pose.position.x()), bitsOf(object.track.keys[i].pose.position.x()));
        QCOMPARE(bitsOf(keys[i].pose.position.z()), bitsOf(1.0 / 3.0));
    }
}

void TstProjectFile::sharedMeshesStayShared()
{
    const Scene scene = test::RandomEdits(5).scene(12);
    const Scene loaded = parseProject(projectBytes(scene), QStringLiteral("meshes.gyre"));
    int shared = 0;
    for (std::size_t a = 0; a < scene.objects.size(); ++a)
        for (std::size_t b = a + 1; b < scene.objects.size(); ++b) {
            const bool sameBefore = scene.objects[a].mesh && scene.objects[a].mesh == scene.objects[b].mesh;
            QCOMPARE(loaded.objects[a].mesh && loaded.objects[a].mesh == loaded.objects[b].mesh, sameBefore);
            shared += sameBefore;
        }
    QVERIFY(shared > 0);
    // Each mesh once in the file.
    std::set<const Mesh*> distinct;
    for (const SceneObject& object : scene.objects)
        if (object.mesh)
            distinct.insert(object.mesh.get());
    const QJsonArray meshes = headerOf(projectBytes(scene))["meshes"].toArray();
    QCOMPARE(static_cast<std::size_t>(meshes.size()), distinct.size());
}

// The joints of a capture share their key times and most keep one position: each list of times is
// stored once, and a position or flag common to every key once, in the header.
void TstProjectFile::tracksShareTimesAndConstantValues()
{
    Scene scene;
    for (ObjectId id = 1; id <= 4; ++id) {
        SceneObject joint;
        joint.id = id;
        joint.parent = id - 1;
        for (int k = 0; k < 100; ++k) {
            const double time = id == 4 ? 0.5 * k : k / 120.0;
            const Eigen::Vector3d position = id == 1 ? Eigen::Vector3d(0.25 * k, 0, 0) : Eigen::Vector3d(0, 2, 0);
            joint.track.keys.push_back(
                {time, {Eigen::Quaterniond(Eigen::AngleAxisd(0.01 * k * id, Eigen::Vector3d::UnitZ())), position}, k != 7});
        }
        scene.objects.push_back(joint);
    }
    scene.nextObjectId = 5;
    const QByteArray file = projectBytes(scene);
    const QJsonObject header = headerOf(file);
    // Two lists of 100 times and the empty list of the keys before fit, in the order tracks use them.
    QCOMPARE(header["times"].toArray(), (QJsonArray{100, 0, 100}));
    const QJsonArray objects = header["objects"].toArray();
    QCOMPARE(objects[2]["keyframes"]["times"].toInt(), 0);
    QCOMPARE(objects[2]["sketch"]["keysBeforeFit"]["times"].toInt(), 1);
    QCOMPARE(objects[3]["keyframes"]["times"].toInt(), 2);
    QVERIFY(objects[0]["keyframes"]["position"].isNull());
    QCOMPARE(objects[1]["keyframes"]["position"].toArray(), array({0, 2, 0}));
    // Each key a quaternion; the root's positions and every track's flags listed (one key is free).
    const qsizetype blocks = 200 * 8 + 400 * 32 + 100 * 24 + 400;
    QCOMPARE(file.size(), 24 + qsizetype(qFromLittleEndian<quint64>(file.constData() + 16)) + blocks);
    const Scene loaded = parseProject(file, QStringLiteral("capture.gyre"));
    QCOMPARE(projectBytes(loaded), file);
    QVERIFY(!loaded.objects[3].track.keys[7].constrained);
    QCOMPARE(loaded.objects[3].track.keys[99].time, 49.5);
}

void TstProjectFile::readsTheHandWrittenBinaryProject()
{
    const Scene scene = parseProject(binaryProject(binaryHeader(), BinaryBlocks().all()), QStringLiteral("binary.gyre"));
    QCOMPARE(scene.objects.size(), std::size_t{1});
    const std::vector<Keyframe>& keys = scene.objects[0].track.keys;
    QCOMPARE(keys.size(), std::size_t{3});
    QCOMPARE(keys[1].time, 0.5);
    QCOMPARE(keys[1].pose.orientation.coeffs(), Eigen::Vector4d(0, 0, 1, 0)); // x, y, z, w
    QCOMPARE(keys[2].pose.orientation.w(), 0.6);
    QCOMPARE(keys[2].pose.position, Eigen::Vector3d(4, 5, 6));
    QCOMPARE(keys[1].constrained, false);
    QCOMPARE(keys[2].constrained, true);
    QVERIFY(scene.objects[0].track.sketch.keysBeforeFit.empty());
    // A position and a flag for every key, in the header.
    const Scene shared = parseProject(binaryProject(binaryHeader(keyLayout(3, 0, array({7, 8, 9}), false)),
                                                    BinaryBlocks().times + BinaryBlocks().orientations),
                                      QStringLiteral("shared.gyre"));
    for (const Keyframe& key : shared.objects[0].track.keys) {
        QCOMPARE(key.pose.position, Eigen::Vector3d(7, 8, 9));
        QVERIFY(!key.constrained);
    }
}

void TstProjectFile::readsTheHandWrittenExample()
{
    const Scene scene = parseProject(bytes(validProject()), QStringLiteral("example.gyre"));
    QCOMPARE(scene.objects.size(), std::size_t{2});
    const SceneObject& child = scene.objects[1];
    QCOMPARE(child.id, ObjectId{2});
    QCOMPARE(child.parent, ObjectId{1});
    QCOMPARE(child.track.interpolation, InterpolationMethod::Slerp);
    QCOMPARE(child.track.subdivision.scheme, SubdivisionScheme::Jarek);
    QCOMPARE(child.track.keys[1].time, 0.75);
    QVERIFY(child.mesh);
    QCOMPARE(child.mesh->positions.size(), std::size_t{3});
    QCOMPARE(child.mesh->positions[2], Eigen::Vector3f(0, 1, 0));
    QCOMPARE(child.mesh->indices, (std::vector<std::uint32_t>{0, 1, 2}));
    QVERIFY(!scene.objects[0].mesh);
    QCOMPARE(scene.nextObjectId, ObjectId{3});
}

// The examples in docs/file-format.md stay valid: the version 2 example and the version 1 one.
void TstProjectFile::readsTheDocumentedExamples()
{
    QFile document(QStringLiteral(GYRE_SOURCE_DIR "/docs/file-format.md"));
    QVERIFY(document.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(document.readAll());
    QStringList examples;
    for (qsizetype start = text.indexOf("```json\n"); start >= 0; start = text.indexOf("```json\n", start)) {
        start += 8;
        examples << text.mid(start, text.indexOf("```", start) - start);
    }
    QCOMPARE(examples.size(), 2);
    const Scene current = parseProject(examples[0].toUtf8(), QStringLiteral("example 1"));
    QCOMPARE(current.objects.size(), std::size_t{2});
    QCOMPARE(current.objects[1].track.sketch.directionStrokes.size(), std::size_t{1});
    QCOMPARE(current.objects[1].track.sketch.patternRepeat, 3);
    QCOMPARE(current.objects[1].mesh->indices.size(), std::size_t{3});
    const Scene migrated = parseProject(examples[1].toUtf8(), QStringLiteral("example 2"));
    QCOMPARE(migrated.objects.front().track.keys.size(), std::size_t{2});
    QVERIFY(migrated.objects.front().track.sketch.fittedCurve.empty());
}

// A file from before δ became relative holds `delta` in rad²/s: it reads as δ_abs/S̄ for the object's
// target, here 2 rad/s about z (S̄ = 4 rad²/s²), so that a fit stops where it stopped before. Saved, the
// file holds the relative δ as `relativeDelta`, which reads back as it is.
void TstProjectFile::anAbsoluteDeltaKeepsItsThreshold()
{
    QJsonArray root{validProject()};
    const QJsonObject stroke{{"points", QJsonArray{array({0, 0, 1}), array({0, 0, 1})}}, {"times", array({0.25, 1.25})}};
    setAt(root[0], {"objects", 0, "sketch", "directionStrokes"}, QJsonArray{stroke});
    setAt(root[0], {"objects", 0, "sketch", "magnitude"},
          QJsonArray{QJsonObject{{"time", 0.25}, {"magnitude", 2}}, QJsonObject{{"time", 1.25}, {"magnitude", 2}}});
    const Scene old = parseProject(bytes(root[0].toObject()), QStringLiteral("old.gyre"));
    QVERIFY2(std::abs(old.objects[0].track.sketch.delta - 0.025) < 1e-12, qPrintable(QString::number(old.objects[0].track.sketch.delta)));
    QCOMPARE(old.objects[1].track.sketch.delta, 0.1);  // nothing sketched: no threshold to keep

    const QByteArray saved = projectBytes(old);
    QVERIFY(saved.contains("\"relativeDelta\"") && !saved.contains("\"delta\""));
    QCOMPARE(parseProject(saved, QStringLiteral("new.gyre")).objects[0].track.sketch.delta, old.objects[0].track.sketch.delta);
}

void TstProjectFile::driftedQuaternionsAreNormalised()
{
    const Scene scene =
        parseProject(projectWith({"objects", 0, "keyframes", 1, "orientation"}, array({0, 0.6003, 0, 0.8})),
                     QStringLiteral("drift.gyre"));
    const Eigen::Quaterniond q = scene.objects[0].track.keys[1].pose.orientation;
    QCOMPARE(q.norm(), 1.0);
    QVERIFY(std::abs(q.x() - 0.6003 / std::hypot(0.6003, 0.8)) < 1e-15);
    QCOMPARE(q.y(), 0.0);
}

void TstProjectFile::migratesVersionOne()
{
    QJsonObject project = validProject();
    project["version"] = 1;
    QJsonArray objects = project["objects"].toArray();
    for (QJsonValueRef value : objects) {
        QJsonObject withoutSketch = value.toObject();
        withoutSketch.remove("sketch");
        value = withoutSketch;
    }
    project["objects"] = objects;
    const QString path = write("version-1.gyre", bytes(project));
    const Scene scene = readProject(path);
    QCOMPARE(scene.objects.size(), std::size_t{2});
    QCOMPARE(scene.objects[0].track.keys.size(), std::size_t{3});
    QVERIFY(scene.objects[0].track.sketch.directionStrokes.empty());
    QCOMPARE(scene.objects[0].track.sketch.alpha, SketchState().alpha);
    // Saved again, it is version 3 and reads back the same.
    const QByteArray saved = projectBytes(scene);
    QVERIFY(saved.startsWith("gyre-project"));
    QCOMPARE(qFromLittleEndian<quint32>(saved.constData() + 12), quint32{3});
    QVERIFY(headerOf(saved)["objects"][0].toObject().contains("sketch"));
    QCOMPARE(projectBytes(parseProject(projectBytes(scene), path)), projectBytes(scene));
}

void TstProjectFile::refusesMalformedFiles_data()
{
    QTest::addColumn<QByteArray>("contents");
    QTest::addColumn<QString>("message"); // what follows "PATH: "

    const auto row = [](const char* name, const QByteArray& contents, const QString& message) {
        QTest::newRow(name) << contents << message;
    };
    const QByteArray valid = bytes(validProject());
    row("wrong type", projectWith({"objects", 0, "name"}, 5), "objects[0].name: expected a string, found a number");
    row("missing field", projectWithout({"objects", 1, "keyframes", 2, "time"}), "objects[1].keyframes[2].time: missing");
    row("NaN as a string", projectWith({"objects", 0, "keyframes", 1, "time"}, "NaN"),
        "objects[0].keyframes[1].time: expected a number, found the string \"NaN\"");
    row("bare NaN", QByteArray(valid).replace("0.75", "NaN"), "not valid JSON: illegal number at byte");
    row("beyond a double", QByteArray(valid).replace("0.75", "1e999"), "not valid JSON: illegal number at byte");
    row("zero quaternion", projectWith({"objects", 1, "keyframes", 2, "orientation"}, array({0, 0, 0, 0})),
        "objects[1].keyframes[2].orientation: the quaternion is zero");
    row("far from unit", projectWith({"objects", 0, "keyframes", 0, "orientation"}, array({2, 0, 0, 0})),
        "objects[0].keyframes[0].orientation: the quaternion has length 2; it must have length 1");
    row("three numbers for four", projectWith({"objects", 0, "keyframes", 0, "orientation"}, array({1, 0, 0})),
        "objects[0].keyframes[0].orientation: expected 4 numbers, found 3");
    row("a flight choice past the spans", projectWith({"objects", 0, "flightSolutions"}, QJsonArray{0, -1, 1}),
        "objects[0].flightSolutions: 3 flight choices for 2 spans between the keys: one a span at most");
    row("a flight choice below -1", projectWith({"objects", 0, "flightSolutions"}, QJsonArray{-2}),
        "objects[0].flightSolutions[0]:");
    const auto mass = [](double value, QJsonArray inertia) {
        return QJsonObject{{"mass", value}, {"centre", array({0, 0, 0})}, {"inertia", inertia}};
    };
    row("negative gravity", projectWith({"gravity"}, QJsonObject{{"acceleration", -9.81}, {"up", "+z"}}),
        "gravity.acceleration: -9.81 is negative");
    row("an up that is no axis", projectWith({"gravity"}, QJsonObject{{"acceleration", 9.81}, {"up", "z"}}),
        "gravity.up: unknown value \"z\"; expected one of +x, -x, +y, -y, +z, -z");
    row("a body that cannot be", projectWith({"objects", 0, "massProperties"}, mass(1.5, array({1, 1, 3, 0, 0, 0}))),
        "objects[0].massProperties: no body has this inertia");
    row("no mass", projectWith({"objects", 0, "massProperties"}, mass(0, array({1, 1, 1, 0, 0, 0}))),
        "objects[0].massProperties: the mass must be a number above 0");
    row("five moments", projectWith({"objects", 0, "massProperties"}, mass(1, array({1, 1, 1, 0, 0}))),
        "objects[0].massProperties.inertia: the inertia needs six numbers");
    row("times that do not increase", projectWith({"objects", 1, "keyframes", 2, "time"}, 0.75),
        "objects[1].keyframes[2].time: time 0.75 does not come after the time before it, 0.75");
    row("keys to restore without a fit",
        projectWith({"objects", 0, "sketch", "keysBeforeFit"}, QJsonArray{keyframe(0.75)}),
        "objects[0].sketch.keysBeforeFit: keys to restore without an applied fit");
    row("keys to restore out of order",
        projectWith({"objects", 0, "sketch", "keysBeforeFit"}, QJsonArray{keyframe(1), keyframe(0.5)}),
        "objects[0].sketch.keysBeforeFit[1].time: time 0.5 does not come after the time before it, 1");
    row("dangling parent", projectWith({"objects", 1, "parent"}, 99), "objects[1].parent: no object has id 99");
    QJsonObject cycle = validProject();
    QJsonArray cycleObjects{object(1, 2), object(2, 1)};
    cycle["objects"] = cycleObjects;
    row("parent cycle", bytes(cycle), "objects[0].parent: object 1 is its own ancestor");
    QJsonObject late = validProject();
    late["objects"] = QJsonArray{object(1, 2), object(2)};
    row("parent after child", bytes(late),
        "objects[0].parent: object 2 comes after it in the file; parents come before their children");
    row("duplicate ids", projectWith({"objects", 1, "id"}, 1), "objects[1].id: 1 is also the id of objects[0]");
    row("fractional id", projectWith({"objects", 1, "id"}, 1.5), "objects[1].id: 1.5 is not a whole number");
    row("zero id", projectWith({"objects", 1, "id"}, 0), "objects[1].id: 0 is outside 1 to 9007199254740992");
    row("newer version", projectWith({"version"}, 4),
        "version: the file has version 4, newer than this build of Gyre reads (3 and older); open it with a newer Gyre");
    row("version 3 as JSON text", projectWith({"version"}, 3),
        "version: a version 3 file starts with \"gyre-project\" and its version in binary, not with JSON text");
    row("version zero", projectWith({"version"}, 0), "version: 0 is outside 1 to");
    row("wrong format", projectWith({"format"}, "blender-scene"),
        "format: expected \"gyre-project\", found \"blender-scene\"; this is not a Gyre project");
    row("no format", projectWithout({"format"}), "format: missing");
    row("top level array", QByteArray("[1, 2]"), "the top level: expected an object, found an array");
    row("truncated", valid.left(valid.size() / 2), "not valid JSON: ");
    row("empty file", QByteArray(), "is empty; a project file holds a JSON object");
    row("only spaces", QByteArray("  \n\t "), "is empty; a project file holds a JSON object");
    row("random bytes", QByteArray("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16), "not valid JSON: ");
    row("deep arrays", QByteArray(100'000, '[') + QByteArray(100'000, ']'), "not valid JSON: too deeply nested document");
    row("deep objects", QByteArray("{\"a\":").repeated(100'000), "not valid JSON: too deeply nested document");
    row("mesh out of range", projectWith({"objects", 1, "mesh"}, 1), "objects[1].mesh: 1 is outside 0 to 0");
    row("not base64", projectWith({"meshes", 0, "positions"}, "****"), "meshes[0].positions: not valid base64");
    row("partial vector", projectWith({"meshes", 0, "positions"}, "AAAAAAAAAAA="),
        "meshes[0].positions: 8 bytes are not a whole number of 12-byte items");
    row("index beyond positions", projectWith({"meshes", 0, "indices"}, "AAAAAAEAAAAFAAAA"),
        "meshes[0]: mesh index 5 is beyond its 3 positions");
    row("unknown interpolation", projectWith({"objects", 0, "interpolation"}, "cubic"),
        "objects[0].interpolation: unknown value \"cubic\"; expected one of slerp, nlerp, squad, hermite, euler, euler-cubic, screw, ballistic");
    row("too many levels", projectWith({"objects", 0, "subdivision", "levels"}, 17),
        "objects[0].subdivision.levels: 17 is outside 0 to 16");
    row("zero fps", projectWith({"fps"}, 0), "fps: 0 is not positive");
    row("empty time range", projectWith({"endTime"}, 0),
        "endTime: the end time 0 does not come after the start time 0");
    row("zero delta", projectWith({"objects", 0, "sketch", "delta"}, 0), "objects[0].sketch.delta: 0 is not positive");
    QJsonObject stroke{{"points", QJsonArray{array({0, 0, 0})}}, {"times", QJsonArray()}};
    row("zero direction", projectWith({"objects", 0, "sketch", "directionStrokes"}, QJsonArray{stroke}),
        "objects[0].sketch.directionStrokes[0].points[0]: the direction is zero");
    row("reversed window", projectWith({"objects", 0, "sketch", "window"}, array({2, 1})),
        "objects[0].sketch.window: time 1 does not come after the time before it, 2");
    row("version 2 without a sketch", projectWithout({"objects", 0, "sketch"}), "objects[0].sketch: missing");

    // Values a reader once accepted that crashed the window or made evaluation write zero quaternions.
    const auto fitted = [](QJsonArray value, QJsonArray derivative) {
        return QJsonArray{QJsonObject{{"time", 0}, {"value", array({1, 0, 0, 0})}, {"derivative", array({0, 0, 0, 0})}},
                          QJsonObject{{"time", 1}, {"value", value}, {"derivative", derivative}}};
    };
    row("zero fitted value", projectWith({"objects", 0, "sketch", "fittedCurve"}, fitted(array({0, 0, 0, 0}), array({0, 0, 0, 0}))),
        "objects[0].sketch.fittedCurve[1].value: the value has length 0; a fitted value needs length at least 0.001");
    row("denormal fitted value", projectWith({"objects", 0, "sketch", "fittedCurve"}, fitted(array({1e-300, 0, 0, 0}), array({0, 0, 0, 0}))),
        "objects[0].sketch.fittedCurve[1].value: the value has length ");
    row("huge fitted derivative", projectWith({"objects", 0, "sketch", "fittedCurve"}, fitted(array({1, 0, 0, 0}), array({0, 1e300, 0, 0}))),
        "objects[0].sketch.fittedCurve[1].derivative: the derivative has length 1e+300 per second; the most it may have is 1e+06");
    // Budgets: a small file that would take unbounded time or memory.
    row("end time beyond the bound", projectWith({"endTime"}, 1e300), "endTime: time 1e+300 is beyond ±1e+06 s");
    row("first key beyond the bound", projectWith({"objects", 0, "keyframes", 0, "time"}, -2e6),
        "objects[0].keyframes[0].time: time -2e+06 is beyond ±1e+06 s");
    row("too many frames", projectWith({"endTime"}, 1e6),
        "endTime: 1e+06 s at 24 fps make 24,000,000 frames; the budget is 16,777,216");
    QJsonObject screw = object(1);
    screw["interpolation"] = "screw";
    screw["subdivision"] = QJsonObject{{"scheme", "jarek"}, {"levels", 16}, {"cyclic", true}, {"decoupled", false}};
    QJsonArray thousandKeys;
    for (int k = 0; k < 1000; ++k)
        thousandKeys.append(keyframe(k * 0.01));
    screw["keyframes"] = thousandKeys;
    QJsonObject bigScrew = validProject();
    bigScrew["objects"] = QJsonArray{screw};
    row("subdivision past the pose budget", bytes(bigScrew),
        "objects[0].subdivision.levels: 1,000 keys at 16 levels make 65,536,000 poses; the budget is 1,048,576");
    damagedBlockRows();
}

// Each malformed file is refused with a message naming the file and the field.
void TstProjectFile::refusesMalformedFiles()
{
    QFETCH(QByteArray, contents);
    QFETCH(QString, message);
    const QString path = write("malformed.gyre", contents);
    try {
        readProject(path);
        QFAIL("the file was accepted");
    } catch (const InputError& error) {
        const QString text = QString::fromUtf8(error.what());
        QVERIFY2(text.startsWith(path + ": " + message), qPrintable(text));
    }
}

void TstProjectFile::refusesUnusableFiles()
{
    QVERIFY_THROWS_EXCEPTION(InputError, readProject(directory_.path()));
    try {
        readProject(directory_.path());
    } catch (const InputError& error) {
        QCOMPARE(QString::fromUtf8(error.what()), directory_.path() + ": is a directory, not a file");
    }
    try {
        readProject(directory_.filePath("missing.gyre"));
        QFAIL("a missing file was read");
    } catch (const InputError& error) {
        QVERIFY(QString::fromUtf8(error.what()).startsWith(directory_.filePath("missing.gyre") + ": cannot open: "));
    }
}

void TstProjectFile::refusesFilesLargerThanTheCap()
{
    // A sparse file: its size is past the cap without a gigabyte on disk.
    const QString path = directory_.filePath("huge.gyre");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    QVERIFY(file.resize(kMaxProjectBytes + 1));
    file.close();
    try {
        readProject(path);
        QFAIL("a file over the cap was read");
    } catch (const InputError& error) {
        QCOMPARE(QString::fromUtf8(error.what()), path + ": is larger than 1 GiB, the most a project file may hold");
    }
}

// Damaged copies of a valid file, and random bytes, are either read or refused with InputError:
// never a crash, never another exception. Under the sanitizers this also checks memory safety.
void TstProjectFile::neverCrashesOnDamagedFiles()
{
    // Version 3 as Gyre writes it, and version 2's text.
    const QByteArray valid[] = {projectBytes(test::RandomEdits(9).scene(3)), bytes(validProject())};
    std::mt19937 engine(11);
    const auto at = [&](qsizetype size) { return std::uniform_int_distribution<qsizetype>(0, size - 1)(engine); };
    int refused = 0;
    int read = 0;
    for (int trial = 0; trial < 1200; ++trial) {
        QByteArray damaged = valid[trial % 8 / 4];
        switch (trial % 4) {
        case 0: // flip bytes
            for (int i = 0; i < 3; ++i)
                damaged[at(damaged.size())] = static_cast<char>(engine());
            break;
        case 1: // cut
            damaged.truncate(at(damaged.size()));
            break;
        case 2: // a digit somewhere for a character: numbers in the wrong places, odd times
            damaged[at(damaged.size())] = static_cast<char>('0' + engine() % 10);
            break;
        default: // random bytes
            damaged = QByteArray(static_cast<qsizetype>(engine() % 200), Qt::Uninitialized);
            for (char& c : damaged)
                c = static_cast<char>(engine());
        }
        try {
            parseProject(damaged, QStringLiteral("damaged.gyre"));
            ++read;
        } catch (const InputError&) {
            ++refused;
        }
    }
    QVERIFY(refused > 0);
    QVERIFY(read > 0);
}

void TstProjectFile::failedSaveKeepsTheOldFile()
{
    const Scene scene = test::RandomEdits(3).scene(2);
    // The longest name a file may have here: QSaveFile cannot add the suffix of its temporary file to
    // it, so the save fails after the old file was written.
    const QString path = write(QString(255, 'p'), "precious\n");
    QVERIFY_THROWS_EXCEPTION(OutputError, writeProject(path, scene));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), QByteArray("precious\n"));
    QCOMPARE(QDir(directory_.path()).entryList({"ppp*"}, QDir::Files).size(), 1);

    const QString missingFolder = directory_.filePath("no-such-folder/project.gyre");
    try {
        writeProject(missingFolder, scene);
        QFAIL("saved into a missing folder");
    } catch (const OutputError& error) {
        QVERIFY2(QString::fromUtf8(error.what()).startsWith(missingFolder + ": cannot write: "), error.what());
    }
    QVERIFY(!QFileInfo::exists(directory_.filePath("no-such-folder")));
}

// A glTF spline's fit holds a control point a key: 200,000 of them would be some 86 MB of JSON text, past
// the header's 16 MiB; in their block they save and open exactly. What the header must hold, a stroke
// of 150,000 points (some 27 MB of JSON), is refused before anything is written, the old file kept.
void TstProjectFile::aLongFitFitsAndAHeaderPastItsLimitIsNotSaved()
{
    Scene scene = test::RandomEdits(5).scene(1);
    SketchState& sketch = scene.objects[0].track.sketch;
    sketch.keysBeforeFit.clear();
    sketch.fittedCurve.clear();
    for (int i = 0; i < 200'000; ++i)
        sketch.fittedCurve.push_back({i * 0.001, Eigen::Quaterniond(1.0, 0.001 * i, 0.5, -0.25),
                                      Eigen::Quaterniond(0.0, 1.0, -2.0, 1.0 / 3.0)});
    const QString path = directory_.filePath(QStringLiteral("long-fit.gyre"));
    writeProject(path, scene);
    QVERIFY(QFileInfo(path).size() > 200'000 * 72);
    const Scene loaded = readProject(path);
    QCOMPARE(loaded.objects[0].track.sketch.fittedCurve.size(), std::size_t{200'000});
    QCOMPARE(loaded.objects[0].track.sketch.fittedCurve[123'456].value.coeffs(),
             sketch.fittedCurve[123'456].value.coeffs());
    QCOMPARE(projectBytes(loaded), projectBytes(scene));

    DirectionStroke stroke;
    for (int i = 0; i < 150'000; ++i)
        stroke.points.push_back(Eigen::Vector3d(std::cos(i * 1e-5), std::sin(i * 1e-5), 0.0));
    sketch.directionStrokes = {stroke};
    const QString kept = write("kept-header.gyre", "precious\n");
    try {
        writeProject(kept, scene);
        QFAIL("a header past 16 MiB was saved");
    } catch (const OutputError& error) {
        QVERIFY2(QString::fromUtf8(error.what()).contains("more than the 16777216 a project may hold"), error.what());
    }
    QFile file(kept);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), QByteArray("precious\n"));
}

void TstProjectFile::refusesToSaveWhatWouldNotReadBack()
{
    Scene scene = test::RandomEdits(4).scene(2);
    scene.objects[1].track.keys = test::RandomEdits(4).keyframes(2);
    scene.objects[1].track.keys[0].pose.position.y() = std::nan("");
    const QString path = write("kept.gyre", "precious\n");
    try {
        writeProject(path, scene);
        QFAIL("a scene holding NaN was saved");
    } catch (const OutputError& error) {
        QCOMPARE(QString::fromUtf8(error.what()),
                 path + ": not saved, because the file would not read back: objects[1].keyframes[0].position: not "
                        "all components are finite");
    }
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), QByteArray("precious\n"));
}

QTEST_GUILESS_MAIN(TstProjectFile)
#include "tst_project_file.moc"
