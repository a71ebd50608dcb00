#include "model/project_file.h"

#include "model/input_error.h"
#include "model/json_field.h"
#include "model/output_target.h"
#include "model/sketch_fit_problem.h"
#include "model/value_checks.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStringList>
#include <QtEndian>

#include <algorithm>
#include <limits>
#include <map>
#include <memory>
#include <string>

namespace gyre::model {

namespace {

// JSON numbers are doubles: ids go up to 2^53, the last integer they all hold exactly.
constexpr qint64 kMaxId = qint64{1} << 53;
// Files are read in pieces of this size, so that a device with no known size cannot run away.
constexpr qint64 kReadChunkBytes = qint64{1} << 20;

// ---- writing --------------------------------------------------------------------------------------

QJsonArray numbersJson(std::initializer_list<double> values)
{
    QJsonArray array;
    for (double value : values)
        array.append(value);
    return array;
}

QJsonArray json(const Eigen::Quaterniond& q) { return numbersJson({q.w(), q.x(), q.y(), q.z()}); }
QJsonArray json(const Eigen::Vector3d& v) { return numbersJson({v.x(), v.y(), v.z()}); }
QJsonArray json(const Eigen::Vector2d& v) { return numbersJson({v.x(), v.y()}); }

template <class Item, class ToJson>
QJsonArray arrayJson(const std::vector<Item>& items, ToJson toJson)
{
    QJsonArray array;
    for (const Item& item : items)
        array.append(toJson(item));
    return array;
}

// Little-endian float32 or uint32 values, base64-encoded.
template <class Value>
QString base64Json(const Value* values, std::size_t count)
{
    QByteArray bytes(static_cast<qsizetype>(count * sizeof(Value)), Qt::Uninitialized);
    if (count > 0) // Qt copies with memcpy, which must not see the null pointer of an empty array
        qToLittleEndian<Value>(values, static_cast<qsizetype>(count), bytes.data());
    return QString::fromLatin1(bytes.toBase64());
}

QString base64Json(const std::vector<Eigen::Vector3f>& vectors)
{
    return base64Json(vectors.empty() ? nullptr : vectors.front().data(), vectors.size() * 3);
}

QJsonObject meshJson(const Mesh& mesh)
{
    return {{"positions", base64Json(mesh.positions)},
            {"normals", base64Json(mesh.normals)},
            {"indices", base64Json(mesh.indices.data(), mesh.indices.size())}};
}

QJsonObject keyframeJson(const Keyframe& key)
{
    return {{"time", key.time},
            {"orientation", json(key.pose.orientation)},
            {"position", json(key.pose.position)},
            {"constrained", key.constrained}};
}

QJsonObject subdivisionJson(const SubdivisionSettings& settings)
{
    return {{"scheme", QString::fromLatin1(subdivisionSchemeName(settings.scheme))},
            {"levels", settings.levels},
            {"cyclic", settings.cyclic},
            {"decoupled", settings.decoupled}};
}

QJsonObject strokeJson(const DirectionStroke& stroke)
{
    return {{"points", arrayJson(stroke.points, [](const Eigen::Vector3d& point) { return json(point); })},
            {"times", arrayJson(stroke.times, [](double time) { return QJsonValue(time); })}};
}

QJsonValue windowJson(const std::optional<std::pair<double, double>>& window)
{
    return window ? QJsonValue(numbersJson({window->first, window->second})) : QJsonValue(QJsonValue::Null);
}

QJsonObject sketchJson(const SketchState& sketch)
{
    return {
        {"directionStrokes", arrayJson(sketch.directionStrokes, strokeJson)},
        {"magnitude", arrayJson(sketch.magnitude,
                                [](const MagnitudePoint& point) {
                                    return QJsonObject{{"time", point.time}, {"magnitude", point.magnitude}};
                                })},
        {"pattern", arrayJson(sketch.pattern, [](const Eigen::Vector2d& point) { return json(point); })},
        {"patternRepeat", sketch.patternRepeat},
        {"window", windowJson(sketch.window)},
        {"alpha", sketch.alpha},
        {"beta", sketch.beta},
        {"relativeDelta", sketch.delta},
        {"fittedCurve", arrayJson(sketch.fittedCurve,
                                  [](const HermiteControlPoint& point) {
                                      return QJsonObject{{"time", point.time},
                                                         {"value", json(point.value)},
                                                         {"derivative", json(point.derivative)}};
                                  })},
        {"keysBeforeFit", arrayJson(sketch.keysBeforeFit, keyframeJson)},
    };
}

QJsonValue idJson(ObjectId id) { return id == kNoObject ? QJsonValue() : QJsonValue(static_cast<qint64>(id)); }

QJsonObject objectJson(const SceneObject& object, const std::map<const Mesh*, qsizetype>& meshIndex)
{
    return {{"id", idJson(object.id)},
            {"name", object.name},
            {"parent", idJson(object.parent)},
            {"mesh", object.mesh ? QJsonValue(meshIndex.at(object.mesh.get())) : QJsonValue()},
            {"interpolation", QString::fromLatin1(interpolationMethodName(object.track.interpolation))},
            {"subdivision", subdivisionJson(object.track.subdivision)},
            {"keyframes", arrayJson(object.track.keys.vector(), keyframeJson)},
            {"sketch", sketchJson(object.track.sketch)}};
}

QJsonObject projectObject(const Scene& scene)
{
    // Each mesh once, in the order objects first use it.
    std::map<const Mesh*, qsizetype> meshIndex;
    QJsonArray meshes;
    for (const SceneObject& object : scene.objects)
        if (object.mesh && meshIndex.emplace(object.mesh.get(), meshes.size()).second)
            meshes.append(meshJson(*object.mesh));
    return {{"format", QString::fromLatin1(kProjectFormat)},
            {"version", kProjectVersion},
            {"fps", scene.fps},
            {"startTime", scene.startTime},
            {"endTime", scene.endTime},
            {"currentTime", scene.currentTime},
            {"meshes", meshes},
            {"objects", arrayJson(scene.objects, [&meshIndex](const SceneObject& object) {
                 return objectJson(object, meshIndex);
             })}};
}

// ---- reading --------------------------------------------------------------------------------------

template <class Enum, std::size_t N>
Enum named(const JsonField& field, const NameTable<Enum, N>& names)
{
    const QString name = field.string();
    if (const std::optional<Enum> value = valueNamed(names, name.toStdString()))
        return *value;
    QStringList known;
    for (const auto& entry : names)
        known.append(QString::fromLatin1(entry.second));
    field.fail(FileError::tr("unknown value \"%1\"; expected one of %2").arg(name, known.join(QStringLiteral(", "))));
}

// Reads each element, checking that the times `timeOf` gives strictly increase; `timeKey` names the
// member that holds the time, or is null where the elements are bare times.
template <class Item, class Read, class TimeOf>
std::vector<Item> timedItems(const JsonField& field, const char* timeKey, Read read, TimeOf timeOf)
{
    std::vector<Item> items;
    for (const JsonField& element : field.elements()) {
        Item item = read(element);
        (timeKey ? element.member(timeKey) : element).checked([&] {
            return items.empty() ? timeValue(timeOf(item)) : timeAfter(timeOf(item), timeOf(items.back()));
        });
        items.push_back(std::move(item));
    }
    return items;
}

Eigen::Quaterniond unitQuaternionIn(const JsonField& field)
{
    const Eigen::Vector4d wxyz = field.vector4();
    return field.checked([&] { return unitQuaternion(Eigen::Quaterniond(wxyz[0], wxyz[1], wxyz[2], wxyz[3])); });
}

Eigen::Quaterniond quaternionIn(const JsonField& field)
{
    const Eigen::Vector4d wxyz = field.vector4();
    return {wxyz[0], wxyz[1], wxyz[2], wxyz[3]};
}

template <class Value>
std::vector<Value> littleEndianValues(const JsonField& field, std::size_t valuesPerItem)
{
    const QByteArray bytes = field.base64();
    const auto itemBytes = static_cast<qsizetype>(valuesPerItem * sizeof(Value));
    if (bytes.size() % itemBytes != 0)
        field.fail(FileError::tr("%1 bytes are not a whole number of %2-byte items").arg(bytes.size()).arg(itemBytes));
    std::vector<Value> values(static_cast<std::size_t>(bytes.size()) / sizeof(Value));
    if (!values.empty()) // as in base64Json
        qFromLittleEndian<Value>(bytes.constData(), static_cast<qsizetype>(values.size()), values.data());
    return values;
}

std::vector<Eigen::Vector3f> vectorsIn(const JsonField& field)
{
    const std::vector<float> values = littleEndianValues<float>(field, 3);
    std::vector<Eigen::Vector3f> vectors(values.size() / 3);
    for (std::size_t i = 0; i < vectors.size(); ++i)
        vectors[i] = {values[3 * i], values[3 * i + 1], values[3 * i + 2]};
    return vectors;
}

std::shared_ptr<const Mesh> meshIn(const JsonField& field)
{
    auto mesh = std::make_shared<Mesh>();
    mesh->positions = vectorsIn(field.member("positions"));
    mesh->normals = vectorsIn(field.member("normals"));
    mesh->indices = littleEndianValues<std::uint32_t>(field.member("indices"), 1);
    field.checked([&] { checkMesh(*mesh); });
    return mesh;
}

Keyframe keyframeIn(const JsonField& field)
{
    Keyframe key;
    key.time = field.member("time").number();
    key.pose.orientation = unitQuaternionIn(field.member("orientation"));
    const JsonField position = field.member("position");
    key.pose.position = position.checked([&] { return positionValue(position.vector3()); });
    key.constrained = field.member("constrained").boolean();
    return key;
}

SubdivisionSettings subdivisionIn(const JsonField& field)
{
    SubdivisionSettings settings;
    settings.scheme = named(field.member("scheme"), kSubdivisionSchemeNames);
    settings.levels = static_cast<int>(field.member("levels").integer(0, kMaxSubdivisionLevels));
    settings.cyclic = field.member("cyclic").boolean();
    settings.decoupled = field.member("decoupled").boolean();
    return settings;
}

DirectionStroke strokeIn(const JsonField& field)
{
    DirectionStroke stroke;
    for (const JsonField& point : field.member("points").elements()) {
        const Eigen::Vector3d direction = point.vector3();
        stroke.points.push_back(point.checked([&] { return unitVector(direction); }));
    }
    const JsonField times = field.member("times");
    stroke.times = timedItems<double>(times, nullptr, [](const JsonField& time) { return time.number(); },
                                      [](double time) { return time; });
    if (stroke.points.empty())
        field.member("points").fail(FileError::tr("a stroke needs at least one point"));
    if (!stroke.times.empty() && stroke.times.size() != stroke.points.size())
        times.fail(FileError::tr("%1 times for %2 points; give none or one per point")
                       .arg(stroke.times.size())
                       .arg(stroke.points.size()));
    return stroke;
}

MagnitudePoint magnitudePointIn(const JsonField& field)
{
    const JsonField magnitude = field.member("magnitude");
    return {field.member("time").number(), magnitude.checked([&] { return nonNegativeNumber(magnitude.number()); })};
}

HermiteControlPoint controlPointIn(const JsonField& field)
{
    const JsonField value = field.member("value");
    const JsonField derivative = field.member("derivative");
    return {field.member("time").number(), value.checked([&] { return controlValue(quaternionIn(value)); }),
            derivative.checked([&] { return controlDerivative(quaternionIn(derivative)); })};
}

std::optional<std::pair<double, double>> windowIn(const JsonField& field)
{
    if (field.isNull())
        return std::nullopt;
    const Eigen::Vector2d span = field.vector2();
    field.checked([&] { timeAfter(span[1], timeValue(span[0])); });
    return std::pair{span[0], span[1]};
}

double numberIn(const JsonField& field, double (*check)(double))
{
    const double value = field.number();
    return field.checked([&] { return check(value); });
}

SketchState sketchIn(const JsonField& field)
{
    SketchState sketch;
    for (const JsonField& stroke : field.member("directionStrokes").elements())
        sketch.directionStrokes.push_back(strokeIn(stroke));
    sketch.magnitude = timedItems<MagnitudePoint>(field.member("magnitude"), "time", magnitudePointIn,
                                                  [](const MagnitudePoint& point) { return point.time; });
    for (const JsonField& point : field.member("pattern").elements())
        sketch.pattern.push_back(point.vector2());
    sketch.patternRepeat = static_cast<int>(field.member("patternRepeat").integer(0, std::numeric_limits<int>::max()));
    sketch.window = windowIn(field.member("window"));
    sketch.alpha = numberIn(field.member("alpha"), nonNegativeNumber);
    sketch.beta = numberIn(field.member("beta"), nonNegativeNumber);
    // Files written before δ became relative hold `delta` in rad²/s; sceneObjectIn converts it.
    sketch.delta = numberIn(field.member(field.has("relativeDelta") ? "relativeDelta" : "delta"), positiveNumber);
    sketch.fittedCurve = timedItems<HermiteControlPoint>(field.member("fittedCurve"), "time", controlPointIn,
                                                         [](const HermiteControlPoint& point) { return point.time; });
    // Files written before Gyre kept the keys a fit moved have no keysBeforeFit: nothing to restore.
    if (field.has("keysBeforeFit")) {
        const JsonField before = field.member("keysBeforeFit");
        sketch.keysBeforeFit = timedItems<Keyframe>(before, "time", keyframeIn, [](const Keyframe& key) { return key.time; });
        if (sketch.fittedCurve.empty() && !sketch.keysBeforeFit.empty())
            before.fail(FileError::tr("keys to restore without an applied fit"));
    }
    return sketch;
}

ObjectId optionalId(const JsonField& field)
{
    return field.isNull() ? kNoObject : static_cast<ObjectId>(field.integer(1, kMaxId));
}

SceneObject sceneObjectIn(const JsonField& field, const std::vector<std::shared_ptr<const Mesh>>& meshes, int version)
{
    SceneObject object;
    object.id = static_cast<ObjectId>(field.member("id").integer(1, kMaxId));
    object.name = field.member("name").string();
    object.parent = optionalId(field.member("parent"));
    if (const JsonField mesh = field.member("mesh"); !mesh.isNull()) {
        if (meshes.empty())
            mesh.fail(FileError::tr("the file has no meshes"));
        object.mesh = meshes[static_cast<std::size_t>(mesh.integer(0, static_cast<qint64>(meshes.size()) - 1))];
    }
    object.track.interpolation = named(field.member("interpolation"), kInterpolationMethodNames);
    object.track.subdivision = subdivisionIn(field.member("subdivision"));
    object.track.keys = timedItems<Keyframe>(field.member("keyframes"), "time", keyframeIn,
                                             [](const Keyframe& key) { return key.time; });
    field.member("subdivision").member("levels").checked([&] {
        checkPoseBudget(object.track.keys.size(), object.track.interpolation, object.track.subdivision);
    });
    // Version 1 has no sketch-editing state: it reads as the empty sketch.
    if (version >= 2)
        object.track.sketch = sketchIn(field.member("sketch"));
    // An absolute δ becomes the relative δ that keeps the fit's threshold for this track where it was.
    if (version >= 2 && !field.member("sketch").has("relativeDelta"))
        object.track.sketch.delta = relativeDelta(object.track, object.track.sketch.delta);
    return object;
}

// Ids are unique, parents exist, form no cycle, and come before their children.
void checkHierarchy(const std::vector<JsonField>& fields, const std::vector<SceneObject>& objects)
{
    std::map<ObjectId, std::size_t> indexOf;
    for (std::size_t i = 0; i < objects.size(); ++i)
        if (const auto [at, added] = indexOf.emplace(objects[i].id, i); !added)
            fields[i].member("id").fail(FileError::tr("%1 is also the id of objects[%2]").arg(objects[i].id).arg(at->second));
    for (std::size_t i = 0; i < objects.size(); ++i)
        if (objects[i].parent != kNoObject && !indexOf.contains(objects[i].parent))
            fields[i].member("parent").fail(FileError::tr("no object has id %1").arg(objects[i].parent));
    // Follow each chain of parents until it reaches a root or an object known to lead to one; meeting
    // an object of the chain being followed again is a cycle. Each object is followed once.
    enum class Mark { Unvisited, OnChain, LeadsToRoot };
    std::vector<Mark> marks(objects.size(), Mark::Unvisited);
    for (std::size_t start = 0; start < objects.size(); ++start) {
        std::vector<std::size_t> chain;
        for (std::size_t i = start; marks[i] != Mark::LeadsToRoot;) {
            if (marks[i] == Mark::OnChain)
                fields[i].member("parent").fail(FileError::tr("object %1 is its own ancestor").arg(objects[i].id));
            marks[i] = Mark::OnChain;
            chain.push_back(i);
            if (objects[i].parent == kNoObject)
                break;
            i = indexOf.at(objects[i].parent);
        }
        for (std::size_t i : chain)
            marks[i] = Mark::LeadsToRoot;
    }
    for (std::size_t i = 0; i < objects.size(); ++i)
        if (objects[i].parent != kNoObject && indexOf.at(objects[i].parent) > i)
            fields[i].member("parent").fail(
                FileError::tr("object %1 comes after it in the file; parents come before their children")
                    .arg(objects[i].parent));
}

int versionIn(const JsonField& root)
{
    const JsonField format = root.member("format");
    if (format.string() != QLatin1String(kProjectFormat))
        format.fail(FileError::tr("expected \"%1\", found \"%2\"; this is not a Gyre project")
                        .arg(QLatin1String(kProjectFormat), format.string()));
    const JsonField version = root.member("version");
    const qint64 number = version.integer(1, std::numeric_limits<int>::max());
    if (number > kProjectVersion)
        version.fail(FileError::tr("the file has version %1, newer than this build of Gyre reads (%2 and older); "
                                   "open it with a newer Gyre")
                         .arg(number)
                         .arg(kProjectVersion));
    return static_cast<int>(number);
}

Scene sceneIn(const JsonField& root)
{
    const int version = versionIn(root);
    Scene scene;
    scene.fps = root.member("fps").number();
    scene.startTime = root.member("startTime").number();
    scene.endTime = root.member("endTime").number();
    root.member("fps").checked([&] { return frameRate(scene.fps); });
    root.member("endTime").checked([&] { checkTimeRange(scene.fps, scene.startTime, scene.endTime); });
    scene.currentTime = numberIn(root.member("currentTime"), timeValue);
    std::vector<std::shared_ptr<const Mesh>> meshes;
    for (const JsonField& mesh : root.member("meshes").elements())
        meshes.push_back(meshIn(mesh));
    const std::vector<JsonField> objects = root.member("objects").elements();
    for (const JsonField& object : objects)
        scene.objects.push_back(sceneObjectIn(object, meshes, version));
    checkHierarchy(objects, scene.objects);
    for (const SceneObject& object : scene.objects)
        scene.nextObjectId = std::max(scene.nextObjectId, object.id + 1);
    return scene;
}

QByteArray contentsOf(const QString& path)
{
    if (QFileInfo(path).isDir())
        throw InputError(path, FileError::tr("is a directory, not a file").toStdString());
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw InputError(path, FileError::tr("cannot open: %1").arg(file.errorString()).toStdString());
    const InputError tooLarge(path,
                              FileError::tr("is larger than 1 GiB, the most a project file may hold").toStdString());
    if (file.size() > kMaxProjectBytes)
        throw tooLarge;
    QByteArray contents;
    while (true) {
        const QByteArray chunk = file.read(kReadChunkBytes);
        if (chunk.isEmpty())
            break;
        contents += chunk;
        if (contents.size() > kMaxProjectBytes) // a device whose size was not known beforehand
            throw tooLarge;
    }
    if (file.error() != QFileDevice::NoError)
        throw InputError(path, FileError::tr("cannot read: %1").arg(file.errorString()).toStdString());
    return contents;
}

} // namespace

QByteArray projectJson(const Scene& scene) { return QJsonDocument(projectObject(scene)).toJson(); }

Scene parseProject(const QByteArray& json, const QString& path)
{
    if (json.trimmed().isEmpty())
        throw InputError(path, FileError::tr("is empty; a project file holds a JSON object").toStdString());
    QJsonParseError error;
    // Qt refuses nesting deeper than 1024 (DeepNesting) rather than recursing further.
    const QJsonDocument document = QJsonDocument::fromJson(json, &error);
    if (error.error != QJsonParseError::NoError)
        throw InputError(path, FileError::tr("not valid JSON: %1 at byte %2")
                                   .arg(error.errorString())
                                   .arg(error.offset)
                                   .toStdString());
    try {
        return sceneIn(JsonField(document.isObject() ? QJsonValue(document.object()) : QJsonValue(document.array()),
                                 QString()));
    } catch (const FieldError& problem) {
        throw InputError(path, problem.what());
    }
}

Scene readProject(const QString& path) { return parseProject(contentsOf(path), path); }

void writeProject(const QString& path, const Scene& scene)
{
    const QJsonObject project = projectObject(scene);
    try {
        sceneIn(JsonField(project, QString()));
    } catch (const FieldError& problem) {
        throw OutputError(path, FileError::tr("not saved, because the file would not read back: %1")
                                    .arg(QString::fromUtf8(problem.what()))
                                    .toStdString());
    }
    saveFileContents(path, QJsonDocument(project).toJson());
}

} // namespace gyre::model
