#include "model/project_file.h"

#include "model/flight_choices.h"
#include "model/input_error.h"
#include "model/json_field.h"
#include "model/object_mass.h"
#include "model/output_target.h"
#include "model/gravity.h"
#include "model/project_blocks.h"
#include "model/project_json.h"
#include "model/rotation_mode.h"
#include "model/sketch_fit_problem.h"
#include "model/value_checks.h"

#include <QFile>
#include <QBuffer>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStringList>
#include <QtEndian>

#include <algorithm>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>

namespace gyre::model {

namespace {

// JSON numbers are doubles: ids go up to 2^53, the last integer they all hold exactly.
constexpr qint64 kMaxId = qint64{1} << 53;
// Files are read in pieces of this size, so that a device with no known size cannot run away.
constexpr qint64 kReadChunkBytes = qint64{1} << 20;
// A version 3 file starts with the format's name, its version (uint32) and the length of its JSON
// header (uint64), little-endian.
constexpr qint64 kMagicBytes = sizeof kProjectFormat - 1;
constexpr qint64 kPreambleBytes = kMagicBytes + 4 + 8;
// The largest JSON header a version 3 file may have: names and sketches, never keys or meshes.
constexpr qint64 kMaxHeaderBytes = qint64{16} << 20;

// ---- writing --------------------------------------------------------------------------------------

} // namespace

QJsonObject keyframeJson(const Keyframe& key)
{
    const Eigen::Quaterniond& q = key.pose.orientation;
    QJsonObject json{{"time", key.time},
                     {"orientation", numbersJson({q.w(), q.x(), q.y(), q.z()})},
                     {"position", vectorJson(key.pose.position)},
                     {"constrained", key.constrained}};
    if (key.eulerAngles)
        json.insert("eulerAngles", vectorJson(*key.eulerAngles));
    return json;
}

namespace {

QJsonObject keyLayoutJson(const KeyLayout& layout)
{
    QJsonObject json{{"count", static_cast<qint64>(layout.count)},
                     {"times", static_cast<qint64>(layout.times)},
                     {"position", layout.position ? QJsonValue(vectorJson(*layout.position)) : QJsonValue()},
                     {"constrained", layout.constrained ? QJsonValue(*layout.constrained) : QJsonValue()}};
    if (layout.eulerAngles)
        json.insert("eulerAngles", true);
    return json;
}

QJsonValue idJson(ObjectId id) { return id == kNoObject ? QJsonValue() : QJsonValue(static_cast<qint64>(id)); }

// Whether two lists of keys have the same times, to the bit.
bool sameTimes(const std::vector<Keyframe>& a, const std::vector<Keyframe>& b)
{
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const Keyframe& x, const Keyframe& y) {
        return std::memcmp(&x.time, &y.time, sizeof x.time) == 0;
    });
}

// FNV-1a over the bits of the times.
std::uint64_t timesHash(const std::vector<Keyframe>& keys)
{
    std::uint64_t hash = 14695981039346656037ULL ^ keys.size();
    for (const Keyframe& key : keys) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &key.time, sizeof bits);
        hash = (hash ^ bits) * 1099511628211ULL;
    }
    return hash;
}

// A version 3 file of a scene, which must outlive it: the JSON header, and the blocks that follow
// it, made one at a time when written. The blocks are the meshes, each once however many objects
// share it; the distinct lists of key times, each once however many tracks share it (the joints of a
// capture all do); then each object's keyframes and keys before its fit.
class ProjectLayout {
public:
    explicit ProjectLayout(const Scene& scene);

    QJsonObject header;
    std::vector<std::function<QByteArray()>> blocks;

private:
    // The layout of `keys`, their block queued.
    QJsonObject keysJson(const std::vector<Keyframe>& keys);
    // How many control points `points` holds, their block queued.
    QJsonObject controlPointsJson(const std::vector<HermiteControlPoint>& points);
    // The index of the time list `keys` use, added if it is new.
    std::size_t timeListOf(const std::vector<Keyframe>& keys);

    std::vector<const std::vector<Keyframe>*> timeLists_;
    std::unordered_multimap<std::uint64_t, std::size_t> timeListsByHash_;
    std::vector<std::function<QByteArray()>> keyBlocks_;
};

ProjectLayout::ProjectLayout(const Scene& scene)
{
    std::map<const Mesh*, qsizetype> meshIndex;
    QJsonArray meshes;
    for (const SceneObject& object : scene.objects)
        if (object.mesh && meshIndex.emplace(object.mesh.get(), meshes.size()).second) {
            const Mesh& mesh = *object.mesh;
            QJsonObject counts{{"positions", static_cast<qint64>(mesh.positions.size())},
                               {"normals", static_cast<qint64>(mesh.normals.size())},
                               {"indices", static_cast<qint64>(mesh.indices.size())}};
            if (!mesh.skin.empty()) {
                QJsonArray joints;
                for (const ObjectId joint : mesh.skin.joints)
                    joints.append(idJson(joint));
                counts.insert("skin", QJsonObject{{"joints", joints}});
            }
            meshes.append(counts);
            blocks.push_back([&mesh] { return meshBlock(mesh); });
        }
    QJsonArray objects;
    for (const SceneObject& object : scene.objects) {
        // In the order sceneObjectIn reads their blocks.
        const QJsonObject keyframes = keysJson(object.track.keys);
        const QJsonObject fittedCurve = controlPointsJson(object.track.sketch.fittedCurve);
        const QJsonObject keysBeforeFit = keysJson(object.track.sketch.keysBeforeFit);
        QJsonObject entry{
            {"id", idJson(object.id)},
            {"name", object.name},
            {"parent", idJson(object.parent)},
            {"visible", object.visible},
            {"mesh", object.mesh ? QJsonValue(meshIndex.at(object.mesh.get())) : QJsonValue()},
            {"interpolation", QString::fromLatin1(interpolationMethodName(object.track.interpolation))},
            {"subdivision", subdivisionJson(object.track.subdivision)},
            {"flightSolutions", arrayJson(flightSolutions(object.track.keys), [](int choice) { return QJsonValue(choice); })},
            {"keyframes", keyframes},
            {"sketch", sketchJson(object.track.sketch, fittedCurve, keysBeforeFit)}};
        if (object.massOverride)
            entry.insert("massProperties", massPropertiesJson(*object.massOverride));
        // Absent: quaternion mode in the default convention, as files from before rotation modes read.
        if (object.track.rotationMode != RotationMode{})
            entry.insert("rotationMode", rotationModeJson(object.track.rotationMode));
        if (object.empty)
            entry.insert("empty", true);
        objects.append(entry);
    }
    QJsonArray times;
    for (const std::vector<Keyframe>* keys : timeLists_) {
        times.append(static_cast<qint64>(keys->size()));
        blocks.push_back([keys] { return timeBlock(*keys); });
    }
    blocks.insert(blocks.end(), keyBlocks_.begin(), keyBlocks_.end());
    header = {{"fps", scene.fps},
              {"startTime", scene.startTime},
              {"endTime", scene.endTime},
              {"currentTime", scene.currentTime},
              {"meshes", meshes},
              {"times", times},
              {"objects", objects}};
    if (scene.gravity != Gravity{})
        header.insert("gravity", gravityJson(scene.gravity));
}

QJsonObject ProjectLayout::keysJson(const std::vector<Keyframe>& keys)
{
    const KeyLayout layout = keyLayoutOf(keys, timeListOf(keys));
    keyBlocks_.push_back([&keys, layout] { return keyBlock(keys, layout); });
    return keyLayoutJson(layout);
}

QJsonObject ProjectLayout::controlPointsJson(const std::vector<HermiteControlPoint>& points)
{
    keyBlocks_.push_back([&points] { return controlPointBlock(points); });
    return {{"count", static_cast<qint64>(points.size())}};
}

std::size_t ProjectLayout::timeListOf(const std::vector<Keyframe>& keys)
{
    const std::uint64_t hash = timesHash(keys);
    const auto [first, last] = timeListsByHash_.equal_range(hash);
    for (auto entry = first; entry != last; ++entry)
        if (sameTimes(*timeLists_[entry->second], keys))
            return entry->second;
    timeLists_.push_back(&keys);
    timeListsByHash_.emplace(hash, timeLists_.size() - 1);
    return timeLists_.size() - 1;
}

// The bytes before the blocks: the preamble, then the header.
QByteArray headerBytes(const QJsonObject& header)
{
    const QByteArray json = QJsonDocument(header).toJson();
    QByteArray bytes(kProjectFormat, kMagicBytes);
    char numbers[12];
    qToLittleEndian<quint32>(kProjectVersion, numbers);
    qToLittleEndian<quint64>(static_cast<quint64>(json.size()), numbers + 4);
    bytes.append(numbers, sizeof numbers);
    return bytes + json;
}

// ---- reading --------------------------------------------------------------------------------------

std::string tooLargeMessage()
{
    return gyre::FileError::tr("is larger than 1 GiB, the most a project file may hold").toStdString();
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
    if (!values.empty()) // Qt copies with memcpy, which must not see the null pointer of an empty array
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

// What reading a version 3 file keeps between its parts: where its blocks come from, the time lists
// read so far, and how many keys and times the budget has left. Versions 1 and 2 have no blocks.
// A check before saving keeps no keys: each track's, and its fitted curve, are dropped once they passed.
struct BlockReading {
    BlockReading(BlockSource& source, bool keep) : blocks(source), keepsKeys(keep) {}

    BlockSource& blocks;
    bool keepsKeys;
    std::vector<std::vector<double>> timeLists;
    std::size_t keysLeft = kMaxProjectKeys;
    std::size_t timesLeft = kMaxProjectKeys;
};

// A count that the budget, of which `left` remain, holds; taken from it. `pastBudget` says what is
// wrong with a larger one, given the count (%1) and the whole budget (%2).
std::size_t budgetedCount(const JsonField& field, std::size_t& left, const QString& pastBudget)
{
    const qint64 count = field.integer(0, kMaxId);
    if (static_cast<std::size_t>(count) > left)
        field.fail(pastBudget.arg(count).arg(kMaxProjectKeys));
    left -= static_cast<std::size_t>(count);
    return static_cast<std::size_t>(count);
}

std::shared_ptr<const Mesh> meshIn(const JsonField& field, BlockReading* binary)
{
    if (binary) {
        const auto count = [&](const char* key) {
            return static_cast<std::size_t>(field.member(key).integer(0, kMaxProjectBytes));
        };
        MeshCounts counts{count("positions"), count("normals"), count("indices"), {}};
        if (field.has("skin")) {
            const JsonField joints = field.member("skin").member("joints");
            for (const JsonField& joint : joints.elements())
                counts.skinJoints.push_back(static_cast<ObjectId>(joint.integer(1, kMaxId)));
            if (counts.skinJoints.empty() || counts.skinJoints.size() > kMaxSkinJoints)
                joints.fail(FileError::tr("a skin has 1 to %1 joints").arg(kMaxSkinJoints));
        }
        return meshFromBlock(binary->blocks.next(counts.blockBytes(), field), counts, field);
    }
    auto mesh = std::make_shared<Mesh>();
    mesh->positions = vectorsIn(field.member("positions"));
    mesh->normals = vectorsIn(field.member("normals"));
    mesh->indices = littleEndianValues<std::uint32_t>(field.member("indices"), 1);
    field.checked([&] { checkMesh(*mesh); });
    return mesh;
}

} // namespace

Keyframe keyframeFromJson(const JsonField& field)
{
    Keyframe key;
    key.time = field.member("time").number();
    key.pose.orientation = unitQuaternionIn(field.member("orientation"));
    const JsonField position = field.member("position");
    key.pose.position = position.checked([&] { return positionValue(position.vector3()); });
    key.constrained = field.member("constrained").boolean();
    if (field.has("eulerAngles")) {
        const JsonField angles = field.member("eulerAngles");
        key.eulerAngles = angles.vector3();
        if (!key.eulerAngles->allFinite())
            angles.fail(FileError::tr("the angles are not finite"));
    }
    return key;
}

namespace {

// A list of keys: in versions 1 and 2 an array of keyframes, in version 3 the layout of its block.
std::vector<Keyframe> keysIn(const JsonField& field, BlockReading* binary)
{
    if (!binary)
        return timedItems<Keyframe>(field, "time", keyframeFromJson, [](const Keyframe& key) { return key.time; });
    KeyLayout layout;
    layout.count = budgetedCount(field.member("count"), binary->keysLeft,
                                 FileError::tr("these %1 keys bring the file past the %2 keys a project may hold"));
    const JsonField times = field.member("times");
    if (binary->timeLists.empty())
        times.fail(FileError::tr("the file has no time lists"));
    layout.times = static_cast<std::size_t>(times.integer(0, static_cast<qint64>(binary->timeLists.size()) - 1));
    const std::vector<double>& timeList = binary->timeLists[layout.times];
    if (timeList.size() != layout.count)
        times.fail(FileError::tr("time list %1 holds %2 times for %3 keys").arg(layout.times).arg(timeList.size()).arg(layout.count));
    if (const JsonField position = field.member("position"); !position.isNull())
        layout.position = position.checked([&] { return positionValue(position.vector3()); });
    if (const JsonField constrained = field.member("constrained"); !constrained.isNull())
        layout.constrained = constrained.boolean();
    layout.eulerAngles = field.has("eulerAngles") && field.member("eulerAngles").boolean();
    return keysFromBlock(binary->blocks.next(layout.blockBytes(), field), layout, timeList, field);
}

SubdivisionSettings subdivisionIn(const JsonField& field)
{
    SubdivisionSettings settings;
    settings.scheme = namedValue(field.member("scheme"), kSubdivisionSchemeNames);
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

// An applied fit's control points: in versions 1 and 2 an array, in version 3 the count of its block.
std::vector<HermiteControlPoint> controlPointsIn(const JsonField& field, BlockReading* binary)
{
    if (!binary)
        return timedItems<HermiteControlPoint>(field, "time", controlPointIn,
                                               [](const HermiteControlPoint& point) { return point.time; });
    const std::size_t count = budgetedCount(field.member("count"), binary->keysLeft,
                                            FileError::tr("these %1 control points bring the file past the %2 keys a project may hold"));
    return controlPointsFromBlock(binary->blocks.next(static_cast<qint64>(count) * kControlPointBytes, field), field);
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

SketchState sketchIn(const JsonField& field, BlockReading* binary)
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
    sketch.fittedCurve = controlPointsIn(field.member("fittedCurve"), binary);
    // Files written before Gyre kept the keys a fit moved have no keysBeforeFit: nothing to restore.
    if (binary || field.has("keysBeforeFit")) {
        const JsonField before = field.member("keysBeforeFit");
        sketch.keysBeforeFit = keysIn(before, binary);
        if (sketch.fittedCurve.empty() && !sketch.keysBeforeFit.empty())
            before.fail(FileError::tr("keys to restore without an applied fit"));
    }
    return sketch;
}

// An Euler-mode track interpolates angles and every key has angles that give its orientation; a quaternion one
// stores no angles.
void checkRotationMode(const JsonField& field, const MotionTrack& track)
{
    const RotationMode& mode = track.rotationMode;
    if (mode.isEuler() && !interpolatesAngles(track.interpolation))
        field.member("interpolation").fail(FileError::tr("an object in Euler rotation mode interpolates euler or euler-cubic"));
    const JsonField keys = field.member("keyframes");
    for (std::size_t k = 0; k < track.keys.size(); ++k) {
        const Keyframe& key = track.keys[k];
        const JsonField at(QJsonValue(), keys.path() + QLatin1Char('[') + QString::number(k) + QStringLiteral("].eulerAngles"));
        if (key.eulerAngles.has_value() != mode.isEuler())
            at.fail(mode.isEuler() ? FileError::tr("an object in Euler rotation mode needs the angles of every key")
                                   : FileError::tr("angles on an object in quaternion rotation mode"));
        if (key.eulerAngles && !anglesGiveOrientation(*key.eulerAngles, key.pose.orientation, mode.convention))
            at.fail(FileError::tr("the angles do not give the key's orientation"));
    }
}

ObjectId optionalId(const JsonField& field)
{
    return field.isNull() ? kNoObject : static_cast<ObjectId>(field.integer(1, kMaxId));
}

SceneObject sceneObjectIn(const JsonField& field, const std::vector<std::shared_ptr<const Mesh>>& meshes, int version,
                          BlockReading* binary)
{
    SceneObject object;
    object.id = static_cast<ObjectId>(field.member("id").integer(1, kMaxId));
    object.name = field.member("name").string();
    object.parent = optionalId(field.member("parent"));
    // Files written before objects could be hidden show every object.
    object.visible = !field.has("visible") || field.member("visible").boolean();
    object.empty = field.has("empty") && field.member("empty").boolean();
    if (field.has("massProperties"))
        object.massOverride = massPropertiesIn(field.member("massProperties"));
    if (const JsonField mesh = field.member("mesh"); !mesh.isNull()) {
        if (meshes.empty())
            mesh.fail(FileError::tr("the file has no meshes"));
        object.mesh = meshes[static_cast<std::size_t>(mesh.integer(0, static_cast<qint64>(meshes.size()) - 1))];
    }
    object.track.interpolation = namedValue(field.member("interpolation"), kInterpolationMethodNames);
    object.track.subdivision = subdivisionIn(field.member("subdivision"));
    object.track.keys = keysIn(field.member("keyframes"), binary);
    // Files written before ballistic interpolation take every span's default flight.
    if (field.has("flightSolutions"))
        setFlightSolutions(object.track.keys.edit(), field.member("flightSolutions"));
    if (field.has("rotationMode"))
        object.track.rotationMode = rotationModeIn(field.member("rotationMode"));
    checkRotationMode(field, object.track);
    field.member("subdivision").member("levels").checked([&] {
        checkPoseBudget(object.track.keys.size(), object.track.interpolation, object.track.subdivision);
    });
    // Version 1 has no sketch-editing state: it reads as the empty sketch.
    if (version >= 2)
        object.track.sketch = sketchIn(field.member("sketch"), binary);
    // An absolute δ becomes the relative δ that keeps the fit's threshold for this track where it was.
    if (version >= 2 && !field.member("sketch").has("relativeDelta"))
        object.track.sketch.delta = relativeDelta(object.track, object.track.sketch.delta);
    if (binary && !binary->keepsKeys) {
        object.track.keys.clear();
        object.track.sketch.fittedCurve.clear();
        object.track.sketch.keysBeforeFit.clear();
    }
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

// The first version written in binary.
constexpr int kFirstBinaryVersion = 3;

// Refuses a version newer than this build reads.
void checkVersion(const JsonField& version, qint64 number)
{
    if (number > kProjectVersion)
        version.fail(FileError::tr("the file has version %1, newer than this build of Gyre reads (%2 and older); "
                                   "open it with a newer Gyre")
                         .arg(number)
                         .arg(kProjectVersion));
}

int versionIn(const JsonField& root)
{
    const JsonField format = root.member("format");
    if (format.string() != QLatin1String(kProjectFormat))
        format.fail(FileError::tr("expected \"%1\", found \"%2\"; this is not a Gyre project")
                        .arg(QLatin1String(kProjectFormat), format.string()));
    const JsonField version = root.member("version");
    const qint64 number = version.integer(1, std::numeric_limits<int>::max());
    checkVersion(version, number);
    if (number >= kFirstBinaryVersion)
        version.fail(FileError::tr("a version %1 file starts with \"%2\" and its version in binary, not with JSON text")
                         .arg(number)
                         .arg(QLatin1String(kProjectFormat)));
    return static_cast<int>(number);
}

// The scene of a project's JSON: the whole file in versions 1 and 2; in version 3 its header, with
// `binary` giving the blocks that follow it.
Scene sceneIn(const JsonField& root, int version, BlockReading* binary)
{
    Scene scene;
    scene.fps = root.member("fps").number();
    scene.startTime = root.member("startTime").number();
    scene.endTime = root.member("endTime").number();
    root.member("fps").checked([&] { return frameRate(scene.fps); });
    root.member("endTime").checked([&] { checkTimeRange(scene.fps, scene.startTime, scene.endTime); });
    scene.currentTime = numberIn(root.member("currentTime"), timeValue);
    if (root.has("gravity"))
        scene.gravity = gravityIn(root.member("gravity"));
    std::vector<std::shared_ptr<const Mesh>> meshes;
    const std::vector<JsonField> meshFields = root.member("meshes").elements();
    for (const JsonField& mesh : meshFields)
        meshes.push_back(meshIn(mesh, binary));
    if (binary)
        for (const JsonField& list : root.member("times").elements()) {
            const std::size_t count = budgetedCount(list, binary->timesLeft,
                                                   FileError::tr("these %1 times bring the file past the %2 times a project may hold"));
            binary->timeLists.push_back(
                timesFromBlock(binary->blocks.next(static_cast<qint64>(count * sizeof(double)), list), list));
        }
    const std::vector<JsonField> objects = root.member("objects").elements();
    for (const JsonField& object : objects)
        scene.objects.push_back(sceneObjectIn(object, meshes, version, binary));
    checkHierarchy(objects, scene.objects);
    for (const SceneObject& object : scene.objects)
        scene.nextObjectId = std::max(scene.nextObjectId, object.id + 1);
    for (std::size_t i = 0; i < meshes.size(); ++i)
        for (const ObjectId joint : meshes[i]->skin.joints)
            if (std::none_of(scene.objects.begin(), scene.objects.end(), [&](const SceneObject& object) { return object.id == joint; }))
                meshFields[i].member("skin").member("joints").fail(FileError::tr("no object has id %1").arg(joint));
    return scene;
}

// The rest of a version 1 or 2 project, JSON text, refused past kMaxProjectBytes.
QByteArray restOf(QIODevice& device, const QString& path)
{
    QByteArray contents;
    while (true) {
        const QByteArray chunk = device.read(kReadChunkBytes);
        if (chunk.isEmpty())
            break;
        contents += chunk;
        if (contents.size() > kMaxProjectBytes) // a device whose size was not known beforehand
            throw InputError(path, tooLargeMessage());
    }
    if (const auto* file = qobject_cast<const QFileDevice*>(&device); file && file->error() != QFileDevice::NoError)
        throw InputError(path, FileError::tr("cannot read: %1").arg(file->errorString()).toStdString());
    return contents;
}

QString notValidJson(const QJsonParseError& error)
{
    return FileError::tr("not valid JSON: %1 at byte %2").arg(error.errorString()).arg(error.offset);
}

// A version 1 or 2 project.
Scene jsonProjectIn(const QByteArray& json, const QString& path)
{
    if (json.trimmed().isEmpty())
        throw InputError(path, FileError::tr("is empty; a project file holds a JSON object").toStdString());
    QJsonParseError error;
    // Qt refuses nesting deeper than 1024 (DeepNesting) rather than recursing further.
    const QJsonDocument document = QJsonDocument::fromJson(json, &error);
    if (error.error != QJsonParseError::NoError)
        throw InputError(path, notValidJson(error).toStdString());
    try {
        const JsonField root(document.isObject() ? QJsonValue(document.object()) : QJsonValue(document.array()),
                             QString());
        return sceneIn(root, versionIn(root), nullptr);
    } catch (const FieldError& problem) {
        throw InputError(path, problem.what());
    }
}

// A version 3 project from its first byte, of which `bytesLeft` are left; throws FieldError.
Scene binaryProjectIn(QIODevice& device, qint64 bytesLeft)
{
    const QByteArray preamble = device.read(kPreambleBytes);
    if (preamble.size() < kPreambleBytes)
        JsonField(QJsonValue(), QString()).fail(FileError::tr("the file ends inside its first %1 bytes").arg(kPreambleBytes));
    const JsonField version(QJsonValue(), QStringLiteral("version"));
    const auto number = qFromLittleEndian<quint32>(preamble.constData() + kMagicBytes);
    checkVersion(version, number);
    if (number < kFirstBinaryVersion)
        version.fail(FileError::tr("a version %1 file is JSON text, not binary").arg(number));
    const JsonField header(QJsonValue(), QStringLiteral("header"));
    const auto headerBytes = qFromLittleEndian<quint64>(preamble.constData() + kMagicBytes + 4);
    if (headerBytes > static_cast<quint64>(kMaxHeaderBytes))
        header.fail(FileError::tr("%1 bytes; a header may hold at most %2").arg(headerBytes).arg(kMaxHeaderBytes));
    DeviceBlocks blocks(device, bytesLeft - kPreambleBytes);
    QJsonParseError error;
    const QJsonDocument document =
        QJsonDocument::fromJson(blocks.next(static_cast<qint64>(headerBytes), header), &error);
    if (error.error != QJsonParseError::NoError)
        header.fail(notValidJson(error));
    BlockReading reading(blocks, true);
    Scene scene = sceneIn(JsonField(document.isObject() ? QJsonValue(document.object()) : QJsonValue(document.array()),
                                    QString()),
                          static_cast<int>(number), &reading);
    blocks.requireEnd();
    return scene;
}

// The project `device` holds from its position on: version 3 if it starts with the format's name,
// else JSON text.
Scene projectIn(QIODevice& device, const QString& path)
{
    if (device.peek(kMagicBytes) == QByteArray(kProjectFormat, kMagicBytes)) {
        try {
            return binaryProjectIn(device, device.isSequential() ? kMaxProjectBytes : device.size() - device.pos());
        } catch (const FieldError& problem) {
            throw InputError(path, problem.what());
        }
    }
    return jsonProjectIn(restOf(device, path), path);
}

} // namespace

QByteArray projectBytes(const Scene& scene)
{
    const ProjectLayout layout(scene);
    QByteArray bytes = headerBytes(layout.header);
    for (const std::function<QByteArray()>& block : layout.blocks)
        bytes += block();
    return bytes;
}

Scene parseProject(const QByteArray& bytes, const QString& path)
{
    QBuffer buffer;
    buffer.setData(bytes);
    buffer.open(QIODevice::ReadOnly);
    return projectIn(buffer, path);
}

Scene readProject(const QString& path)
{
    if (QFileInfo(path).isDir())
        throw InputError(path, FileError::tr("is a directory, not a file").toStdString());
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw InputError(path, FileError::tr("cannot open: %1").arg(file.errorString()).toStdString());
    if (file.size() > kMaxProjectBytes)
        throw InputError(path, tooLargeMessage());
    return projectIn(file, path);
}

void writeProject(const QString& path, const Scene& scene)
{
    const ProjectLayout layout(scene);
    // Read back from the very blocks that would be written, one at a time, before any is.
    try {
        WrittenBlocks blocks(layout.blocks);
        BlockReading reading(blocks, false);
        sceneIn(JsonField(layout.header, QString()), kProjectVersion, &reading);
    } catch (const FieldError& problem) {
        throw OutputError(path, FileError::tr("not saved, because the file would not read back: %1")
                                    .arg(QString::fromUtf8(problem.what()))
                                    .toStdString());
    }
    // What the blocks do not hold (names, strokes) must fit the header a reader accepts.
    const QByteArray header = headerBytes(layout.header);
    if (header.size() - kPreambleBytes > kMaxHeaderBytes)
        throw OutputError(path, FileError::tr("not saved, because its header (the objects' names and settings, the "
                                              "sketches' strokes) would hold %1 bytes, more than the %2 a project may hold")
                                    .arg(header.size() - kPreambleBytes)
                                    .arg(kMaxHeaderBytes)
                                    .toStdString());
    OutputTarget target(path);
    target.open();
    target.write(header);
    for (const std::function<QByteArray()>& block : layout.blocks)
        target.write(block());
    target.commit();
}

} // namespace gyre::model
