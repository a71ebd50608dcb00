// The project file as its users meet it: what is saved loads back exactly, older versions load,
// newer ones are refused with a clear message, and no input, however broken, crashes the reader or
// half-loads a scene. Every refusal names the file and the field. The fixtures are written here,
// by hand, following docs/file-format.md rather than the writer.

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
    void sharedMeshesStayShared();
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
        QCOMPARE(projectJson(loaded), projectJson(scene));
        QCOMPARE(loaded.objects.size(), scene.objects.size());
        QCOMPARE(loaded.nextObjectId, scene.nextObjectId);
    }
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
    const Scene loaded = parseProject(projectJson(scene), QStringLiteral("numbers.gyre"));
    const std::vector<Keyframe>& keys = loaded.objects.front().track.keys;
    QCOMPARE(keys.size(), object.track.keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i) {
        QCOMPARE(bitsOf(keys[i].time), bitsOf(object.track.keys[i].time));
        // The sign of zero is not kept: Qt writes -0 as 0.
        const double expected = object.track.keys[i].pose.position.x() + 0.0;
        QCOMPARE(bitsOf(keys[i].pose.position.x() + 0.0), bitsOf(expected));
        QCOMPARE(bitsOf(keys[i].pose.position.z()), bitsOf(1.0 / 3.0));
    }
}

void TstProjectFile::sharedMeshesStayShared()
{
    const Scene scene = test::RandomEdits(5).scene(12);
    const Scene loaded = parseProject(projectJson(scene), QStringLiteral("meshes.gyre"));
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
    const QJsonArray meshes = QJsonDocument::fromJson(projectJson(scene)).object()["meshes"].toArray();
    QCOMPARE(static_cast<std::size_t>(meshes.size()), distinct.size());
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

    const QByteArray saved = projectJson(old);
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
    // Saved again, it is version 2 and reads back the same.
    const QJsonObject saved = QJsonDocument::fromJson(projectJson(scene)).object();
    QCOMPARE(saved["version"].toInt(), 2);
    QVERIFY(saved["objects"][0].toObject().contains("sketch"));
    QCOMPARE(projectJson(parseProject(projectJson(scene), path)), projectJson(scene));
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
    row("newer version", projectWith({"version"}, 3),
        "version: the file has version 3, newer than this build of Gyre reads (2 and older); open it with a newer Gyre");
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
        "objects[0].interpolation: unknown value \"cubic\"; expected one of slerp, nlerp, squad, hermite, euler, screw");
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
    const QByteArray valid = projectJson(test::RandomEdits(9).scene(3));
    std::mt19937 engine(11);
    const auto at = [&](qsizetype size) { return std::uniform_int_distribution<qsizetype>(0, size - 1)(engine); };
    int refused = 0;
    int read = 0;
    for (int trial = 0; trial < 600; ++trial) {
        QByteArray damaged = valid;
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
                 path + ": not saved, because the file would not read back: objects[1].keyframes[0].position[1]: nan "
                        "is not a finite number");
    }
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), QByteArray("precious\n"));
}

QTEST_GUILESS_MAIN(TstProjectFile)
#include "tst_project_file.moc"
