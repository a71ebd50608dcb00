#include "io/scene_wire.h"

#include "io/scene_wire_stream.h"

#include "model/gravity.h"
#include "model/object_mass.h"
#include "model/skinning.h"
#include "model/value_checks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

namespace gyre::io::wire {

namespace {

enum class Kind : quint8 { ImportRequest = 1, ExportRequest = 2, SceneImport = 3, ExportReport = 4, Failure = 5 };

// The numbers of one keyframe: time, orientation w x y z, position x y z.
constexpr std::size_t kKeyNumbers = 8;
// Of a fitted curve's control point: time, value w x y z, derivative w x y z.
constexpr std::size_t kControlPointNumbers = 9;

// ---- writing --------------------------------------------------------------------------------------

void header(Writer& out, Kind kind)
{
    out.put(kMagic);
    out.put(kVersion);
    out.enumeration(kind);
}

template <int Rows>
void appendAll(std::vector<double>& numbers, const Eigen::Matrix<double, Rows, 1>& v)
{
    numbers.insert(numbers.end(), v.data(), v.data() + Rows);
}

void appendQuaternion(std::vector<double>& numbers, const Eigen::Quaterniond& q)
{
    numbers.insert(numbers.end(), {q.w(), q.x(), q.y(), q.z()});
}

void writeVectors(Writer& out, const std::vector<Eigen::Vector3f>& vectors)
{
    out.block(vectors.empty() ? nullptr : vectors.front().data(), vectors.size() * 3);
}

// A skin: its joints' ids, their inverse binds (16 numbers each, column-major), then four joint
// indices and four weights per position; all four blocks empty for a rigid mesh.
void writeSkin(Writer& out, const model::Skin& skin)
{
    out.block(std::vector<quint64>(skin.joints.begin(), skin.joints.end()));
    out.block(skin.inverseBinds.empty() ? nullptr : skin.inverseBinds.front().data(), skin.inverseBinds.size() * 16);
    out.block(skin.vertexJoints.empty() ? nullptr : skin.vertexJoints.front().data(), skin.vertexJoints.size() * 4);
    out.block(skin.vertexWeights.empty() ? nullptr : skin.vertexWeights.front().data(), skin.vertexWeights.size() * 4);
}

void writeMesh(Writer& out, const model::Mesh& mesh)
{
    writeVectors(out, mesh.positions);
    writeVectors(out, mesh.normals);
    out.block(mesh.indices);
    writeSkin(out, mesh.skin);
}

void writeSketch(Writer& out, const model::SketchState& sketch)
{
    out.count(sketch.directionStrokes.size());
    for (const model::DirectionStroke& stroke : sketch.directionStrokes) {
        std::vector<double> points;
        for (const Eigen::Vector3d& point : stroke.points)
            appendAll(points, point);
        out.block(points);
        out.block(stroke.times);
    }
    std::vector<double> magnitude;
    for (const model::MagnitudePoint& point : sketch.magnitude)
        magnitude.insert(magnitude.end(), {point.time, point.magnitude});
    out.block(magnitude);
    std::vector<double> pattern;
    for (const Eigen::Vector2d& point : sketch.pattern)
        appendAll(pattern, point);
    out.block(pattern);
    out.put<qint32>(sketch.patternRepeat);
    out.put<quint8>(sketch.window.has_value());
    out.put(sketch.window ? sketch.window->first : 0.0);
    out.put(sketch.window ? sketch.window->second : 0.0);
    out.put(sketch.alpha);
    out.put(sketch.beta);
    out.put(sketch.delta);
    std::vector<double> curve;
    for (const HermiteControlPoint& point : sketch.fittedCurve) {
        curve.push_back(point.time);
        appendQuaternion(curve, point.value);
        appendQuaternion(curve, point.derivative);
    }
    out.block(curve);
}

void writeTrack(Writer& out, const model::MotionTrack& track)
{
    out.string(QString::fromLatin1(interpolationMethodName(track.interpolation)));
    out.string(QString::fromLatin1(subdivisionSchemeName(track.subdivision.scheme)));
    out.put<qint32>(track.subdivision.levels);
    out.put<quint8>(track.subdivision.cyclic);
    out.put<quint8>(track.subdivision.decoupled);
    std::vector<double> numbers;
    numbers.reserve(track.keys.size() * kKeyNumbers);
    std::vector<quint8> constrained;
    constrained.reserve(track.keys.size());
    std::vector<qint32> flights;
    flights.reserve(track.keys.size());
    for (const model::Keyframe& key : track.keys) {
        numbers.push_back(key.time);
        appendQuaternion(numbers, key.pose.orientation);
        appendAll(numbers, key.pose.position);
        constrained.push_back(key.constrained);
        flights.push_back(key.flightSolution);
    }
    out.block(numbers);
    out.block(constrained);
    out.block(flights);
    // The rotation mode, then the keys' stored angles, three each, in Euler mode alone.
    out.put<quint8>(track.rotationMode.isEuler());
    out.string(QString::fromStdString(track.rotationMode.convention.order()));
    out.put<quint8>(track.rotationMode.convention.frame == AngleFrame::Intrinsic);
    std::vector<double> angles;
    for (const model::Keyframe& key : track.keys)
        if (key.eulerAngles)
            appendAll(angles, *key.eulerAngles);
    out.block(angles);
    writeSketch(out, track.sketch);
}

// A flag, then the mass, the centre and the six inertia components (zeros when the mass comes from the mesh).
void writeMassOverride(Writer& out, const std::optional<MassProperties>& typed)
{
    const MassProperties properties = typed.value_or(MassProperties{});
    std::vector<double> numbers{properties.mass};
    appendAll(numbers, properties.centre);
    const InertiaComponents inertia = inertiaComponents(properties.inertia);
    numbers.insert(numbers.end(), inertia.begin(), inertia.end());
    out.put<quint8>(typed.has_value());
    out.block(numbers);
}

void writeScene(Writer& out, const model::Scene& scene)
{
    out.put(scene.fps);
    out.put(scene.startTime);
    out.put(scene.endTime);
    out.put(scene.currentTime);
    out.put(scene.gravity.acceleration);
    out.put(static_cast<quint8>(scene.gravity.up));
    // Each mesh once, however many objects share it; objects name it by 1-based index, 0 for none.
    std::map<const model::Mesh*, quint64> meshIndex;
    std::vector<const model::Mesh*> meshes;
    for (const model::SceneObject& object : scene.objects)
        if (object.mesh && meshIndex.emplace(object.mesh.get(), meshes.size() + 1).second)
            meshes.push_back(object.mesh.get());
    out.count(meshes.size());
    for (const model::Mesh* mesh : meshes)
        writeMesh(out, *mesh);
    out.count(scene.objects.size());
    for (const model::SceneObject& object : scene.objects) {
        out.put<quint64>(object.id);
        out.string(object.name);
        out.put<quint64>(object.parent);
        out.put<quint64>(object.mesh ? meshIndex.at(object.mesh.get()) : 0);
        writeTrack(out, object.track);
        writeMassOverride(out, object.massOverride);
        out.put<quint8>(object.empty);
    }
}

void writeStrings(Writer& out, const QStringList& strings)
{
    out.count(static_cast<std::size_t>(strings.size()));
    for (const QString& text : strings)
        out.string(text);
}

// An optional value: a flag, then the value (or a zero of its type, so that every message of a kind
// has the same layout).
template <class Value>
void writeOptional(Writer& out, const std::optional<Value>& value)
{
    out.put<quint8>(value.has_value());
    if constexpr (std::is_enum_v<Value>)
        out.enumeration(value.value_or(Value{}));
    else
        out.put(value.value_or(Value{}));
}

void writeImportOptions(Writer& out, const ImportOptions& options)
{
    out.enumeration(options.takeSelection);
    out.block(std::vector<quint64>(options.takes.begin(), options.takes.end()));
    writeOptional(out, options.fps);
    writeOptional(out, options.metresPerUnit);
    writeOptional(out, options.up);
    out.enumeration(options.timeOrigin);
}

void writeSettings(Writer& out, const ImportSettings& settings)
{
    out.put(settings.fps);
    out.put(settings.metresPerUnit);
    out.enumeration(settings.up);
}

void writeSceneImport(Writer& out, const SceneImport& imported)
{
    writeScene(out, imported.scene);
    out.count(imported.animations.size());
    for (const AnimationSummary& animation : imported.animations) {
        out.string(animation.name);
        out.put(animation.durationSeconds);
        writeStrings(out, animation.nodes);
    }
    out.block(std::vector<quint64>(imported.takes.begin(), imported.takes.end()));
    out.enumeration(imported.takeRule);
    writeSettings(out, imported.file.values);
    out.string(imported.file.fpsSource);
    out.string(imported.file.unitSource);
    out.string(imported.file.upSource);
    writeSettings(out, imported.applied);
    out.put(imported.timeShift);
    writeStrings(out, imported.warnings);
}

// ---- reading --------------------------------------------------------------------------------------

Kind headerIn(Reader& in)
{
    if (in.get<quint32>() != kMagic)
        throw WireError("not a gyre-scene-worker message");
    if (const auto version = in.get<quint16>(); version != kVersion)
        throw WireError("wire version " + std::to_string(version) + ", expected " + std::to_string(kVersion));
    const auto kind = in.get<quint8>();
    if (kind < 1 || kind > 5)
        throw WireError("unknown message kind " + std::to_string(kind));
    return static_cast<Kind>(kind);
}

template <class Enum, std::size_t N>
Enum named(Reader& in, const NameTable<Enum, N>& names, const char* what)
{
    const QString name = in.string(what);
    if (const std::optional<Enum> value = valueNamed(names, name.toStdString()))
        return *value;
    throw WireError(std::string(what) + ": unknown name '" + name.toStdString() + "'");
}

// A value check of value_checks.h, its std::invalid_argument said about `what`.
template <class Check>
auto checked(const std::string& what, Check check) -> decltype(check())
{
    try {
        return check();
    } catch (const std::invalid_argument& problem) {
        throw WireError(what + ": " + problem.what());
    }
}

// `numbers` copied into `items` of `N` numbers each (the block was read in whole items).
template <class Item, std::size_t N, class Number>
std::vector<Item> itemsOf(const std::vector<Number>& numbers)
{
    static_assert(sizeof(Item) == N * sizeof(Number));
    std::vector<Item> items(numbers.size() / N);
    if (!numbers.empty()) // memcpy may not be given the null data() of an empty vector
        std::memcpy(static_cast<void*>(items.data()), numbers.data(), numbers.size() * sizeof(Number));
    return items;
}

model::Skin skinIn(Reader& in)
{
    model::Skin skin;
    const std::vector<quint64> joints = in.block<quint64>("skin joints");
    skin.joints.assign(joints.begin(), joints.end());
    skin.inverseBinds = itemsOf<Eigen::Matrix4f, 16>(in.block<float>("skin inverse binds", 16));
    skin.vertexJoints = itemsOf<std::array<std::uint16_t, 4>, 4>(in.block<quint16>("skin vertex joints", 4));
    skin.vertexWeights = itemsOf<Eigen::Vector4f, 4>(in.block<float>("skin vertex weights", 4));
    return skin;
}

std::shared_ptr<const model::Mesh> meshIn(Reader& in)
{
    auto mesh = std::make_shared<model::Mesh>();
    mesh->positions = itemsOf<Eigen::Vector3f, 3>(in.block<float>("mesh positions", 3));
    mesh->normals = itemsOf<Eigen::Vector3f, 3>(in.block<float>("mesh normals", 3));
    mesh->indices = in.block<std::uint32_t>("mesh indices");
    mesh->skin = skinIn(in);
    checked("mesh", [&] { model::checkMesh(*mesh); });
    return mesh;
}

Eigen::Quaterniond quaternionAt(const double* numbers) { return {numbers[0], numbers[1], numbers[2], numbers[3]}; }

model::SketchState sketchIn(Reader& in)
{
    model::SketchState sketch;
    // Each stroke is at least its two counts.
    sketch.directionStrokes.resize(in.count(16, "direction strokes"));
    for (model::DirectionStroke& stroke : sketch.directionStrokes) {
        const std::vector<double> points = in.block<double>("stroke points", 3);
        for (std::size_t i = 0; i < points.size(); i += 3)
            stroke.points.emplace_back(points[i], points[i + 1], points[i + 2]);
        stroke.times = in.block<double>("stroke times");
    }
    const std::vector<double> magnitude = in.block<double>("magnitude curve", 2);
    for (std::size_t i = 0; i < magnitude.size(); i += 2)
        sketch.magnitude.push_back({magnitude[i], magnitude[i + 1]});
    const std::vector<double> pattern = in.block<double>("pattern", 2);
    for (std::size_t i = 0; i < pattern.size(); i += 2)
        sketch.pattern.emplace_back(pattern[i], pattern[i + 1]);
    sketch.patternRepeat = in.get<qint32>();
    const bool hasWindow = in.flag();
    const auto windowStart = in.get<double>();
    const auto windowEnd = in.get<double>();
    if (hasWindow)
        sketch.window = std::pair{windowStart, windowEnd};
    sketch.alpha = in.get<double>();
    sketch.beta = in.get<double>();
    sketch.delta = in.get<double>();
    const std::vector<double> curve = in.block<double>("fitted curve", kControlPointNumbers);
    for (std::size_t i = 0; i < curve.size(); i += kControlPointNumbers)
        sketch.fittedCurve.push_back({curve[i], quaternionAt(&curve[i + 1]), quaternionAt(&curve[i + 5])});
    return sketch;
}

model::MotionTrack trackIn(Reader& in, const std::string& what)
{
    model::MotionTrack track;
    track.interpolation = named(in, kInterpolationMethodNames, "interpolation");
    track.subdivision.scheme = named(in, kSubdivisionSchemeNames, "subdivision scheme");
    track.subdivision.levels = in.get<qint32>();
    track.subdivision.cyclic = in.flag();
    track.subdivision.decoupled = in.flag();
    const std::vector<double> numbers = in.block<double>("keyframes", kKeyNumbers);
    const std::vector<quint8> constrained = in.block<quint8>("keyframe flags");
    const std::vector<qint32> flights = in.block<qint32>("keyframe flights");
    if (constrained.size() * kKeyNumbers != numbers.size() || flights.size() != constrained.size())
        throw WireError(what + ": " + std::to_string(constrained.size()) + " flags and " + std::to_string(flights.size()) +
                        " flight choices for " + std::to_string(numbers.size() / kKeyNumbers) + " keyframes");
    track.keys.resize(constrained.size());
    for (std::size_t k = 0; k < track.keys.size(); ++k) {
        const double* key = &numbers[k * kKeyNumbers];
        if (constrained[k] > 1)
            throw WireError(what + ": keyframe " + std::to_string(k) + " has a flag that is neither 0 nor 1");
        track.keys[k] = {key[0], Pose{quaternionAt(key + 1), {key[5], key[6], key[7]}}, constrained[k] == 1,
                         std::max(flights[k], -1)};
    }
    track.rotationMode.kind = in.flag() ? model::RotationMode::Kind::Euler : model::RotationMode::Kind::Quaternion;
    const std::string order = in.string("Euler order").toStdString();
    const AngleFrame frame = in.flag() ? AngleFrame::Intrinsic : AngleFrame::Extrinsic;
    const std::optional<EulerConvention> convention = EulerConvention::parse(order, frame);
    if (!convention)
        throw WireError(what + ": '" + order + "' is not an Euler order");
    track.rotationMode.convention = *convention;
    const std::vector<double> angles = in.block<double>("Euler angles", 3);
    if (angles.size() != (track.rotationMode.isEuler() ? 3 * track.keys.size() : 0))
        throw WireError(what + ": " + std::to_string(angles.size() / 3) + " angle triples for " +
                        std::to_string(track.keys.size()) + " keyframes");
    for (std::size_t k = 0; k < angles.size() / 3; ++k) {
        track.keys[k].eulerAngles = Eigen::Vector3d(angles[3 * k], angles[3 * k + 1], angles[3 * k + 2]);
        if (!track.keys[k].eulerAngles->allFinite())
            throw WireError(what + ": keyframe " + std::to_string(k) + " has angles that are not finite");
    }
    track.sketch = sketchIn(in);
    checked(what, [&] { model::checkTrack(track); });
    return track;
}

std::optional<MassProperties> massOverrideIn(Reader& in, const std::string& what)
{
    const bool typed = in.flag();
    const std::vector<double> numbers = in.block<double>("mass properties");
    if (numbers.size() != 10)
        throw WireError(what + ": " + std::to_string(numbers.size()) + " mass property numbers, not 10");
    if (!typed)
        return std::nullopt;
    MassProperties properties;
    properties.mass = numbers[0];
    properties.centre = Eigen::Vector3d(numbers[1], numbers[2], numbers[3]);
    InertiaComponents inertia;
    std::copy(numbers.begin() + 4, numbers.end(), inertia.begin());
    properties.inertia = inertiaTensor(inertia);
    checked(what + " mass properties", [&] { model::checkMassProperties(properties); });
    return properties;
}

model::Scene sceneIn(Reader& in)
{
    model::Scene scene;
    scene.fps = in.get<double>();
    scene.startTime = in.get<double>();
    scene.endTime = in.get<double>();
    scene.currentTime = in.get<double>();
    scene.gravity.acceleration = in.get<double>();
    const auto up = in.get<quint8>();
    if (up > static_cast<quint8>(model::UpDirection::MinusZ))
        throw WireError("scene: up direction " + std::to_string(up) + " is none of the six axes");
    scene.gravity.up = static_cast<model::UpDirection>(up);
    checked("scene", [&] {
        model::checkGravity(scene.gravity);
        model::frameRate(scene.fps);
        model::finiteNumber(scene.currentTime);
        if (!(model::finiteNumber(scene.endTime) >= model::finiteNumber(scene.startTime)))
            throw std::invalid_argument("the end time comes before the start time");
    });
    // A mesh is at least its seven counts.
    std::vector<std::shared_ptr<const model::Mesh>> meshes(in.count(56, "meshes"));
    for (auto& mesh : meshes)
        mesh = meshIn(in);
    // Ids are unique and nonzero; a parent is an object that came before.
    std::map<model::ObjectId, std::size_t> seen;
    // An object is at least its ids, name, track names, settings, counts and sketch numbers.
    scene.objects.resize(in.count(128, "objects"));
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        model::SceneObject& object = scene.objects[i];
        const std::string what = "object " + std::to_string(i);
        object.id = in.get<quint64>();
        object.name = in.string("object name");
        object.parent = in.get<quint64>();
        const auto mesh = in.get<quint64>();
        if (object.id == model::kNoObject || !seen.emplace(object.id, i).second)
            throw WireError(what + ": the id " + std::to_string(object.id) + " is zero or taken");
        if (object.parent != model::kNoObject && (object.parent == object.id || !seen.contains(object.parent)))
            throw WireError(what + ": its parent " + std::to_string(object.parent) + " is not an object before it");
        if (mesh > meshes.size())
            throw WireError(what + ": there is no mesh " + std::to_string(mesh));
        if (mesh > 0)
            object.mesh = meshes[mesh - 1];
        object.track = trackIn(in, what);
        object.massOverride = massOverrideIn(in, what);
        object.empty = in.flag();
        if (object.empty && object.mesh)
            throw WireError(what + ": an empty has a mesh");
        scene.nextObjectId = std::max(scene.nextObjectId, object.id + 1);
    }
    // A skin's joints are objects of the scene, anywhere in it.
    for (const auto& mesh : meshes)
        checked("mesh skin", [&] {
            model::skinWithJoints(mesh->skin, [&](model::ObjectId joint) { return seen.contains(joint) ? joint : model::kNoObject; });
        });
    return scene;
}

QStringList stringsIn(Reader& in, const char* what)
{
    QStringList strings;
    const std::size_t n = in.count(8, what);
    for (std::size_t i = 0; i < n; ++i)
        strings << in.string(what);
    return strings;
}

UpAxis upAxisOf(quint8 up)
{
    if (up != static_cast<quint8>(UpAxis::Y) && up != static_cast<quint8>(UpAxis::Z))
        throw WireError("unknown up axis " + std::to_string(up));
    return static_cast<UpAxis>(up);
}

// A frame rate in (0, kMaxFps] and a unit that is a positive length, as importScene accepts them.
double checkedFrameRate(double fps, const char* what)
{
    return checked(what, [&] { return model::frameRate(fps); });
}

double checkedUnit(double metres, const char* what)
{
    if (!(std::isfinite(metres) && metres > 0.0))
        throw WireError(std::string(what) + ": " + std::to_string(metres) + " m is not a positive length");
    return metres;
}

// An optional value as writeOptional wrote it, checked by `check` when it is there; when it is not,
// its place must hold a zero.
template <class Value, class Check>
std::optional<Value> optionalIn(Reader& in, const char* what, Check check)
{
    const bool present = in.flag();
    using Stored = std::conditional_t<std::is_enum_v<Value>, quint8, Value>;
    const auto value = in.get<Stored>();
    if (present)
        return check(value);
    if (value != Stored{})
        throw WireError(std::string(what) + ": a value where none was given");
    return std::nullopt;
}

ImportOptions importOptionsIn(Reader& in)
{
    ImportOptions options;
    const auto selection = in.get<quint8>();
    if (selection < static_cast<quint8>(TakeSelection::Automatic) || selection > static_cast<quint8>(TakeSelection::Listed))
        throw WireError("unknown take selection " + std::to_string(selection));
    options.takeSelection = static_cast<TakeSelection>(selection);
    const std::vector<quint64> takes = in.block<quint64>("takes");
    if (options.takeSelection != TakeSelection::Listed && !takes.empty())
        throw WireError("takes: listed without being chosen");
    options.takes.assign(takes.begin(), takes.end());
    options.fps = optionalIn<double>(in, "frame rate option",
                                     [](double fps) { return checkedFrameRate(fps, "frame rate option"); });
    options.metresPerUnit = optionalIn<double>(in, "unit option",
                                               [](double metres) { return checkedUnit(metres, "unit option"); });
    options.up = optionalIn<UpAxis>(in, "up axis option", upAxisOf);
    const auto origin = in.get<quint8>();
    if (origin != static_cast<quint8>(TimeOrigin::FirstKey) && origin != static_cast<quint8>(TimeOrigin::File))
        throw WireError("unknown time origin " + std::to_string(origin));
    options.timeOrigin = static_cast<TimeOrigin>(origin);
    return options;
}

ImportSettings settingsIn(Reader& in, const char* what)
{
    ImportSettings settings;
    settings.fps = checkedFrameRate(in.get<double>(), what);
    settings.metresPerUnit = checkedUnit(in.get<double>(), what);
    settings.up = upAxisOf(in.get<quint8>());
    return settings;
}

SceneImport sceneImportIn(Reader& in)
{
    SceneImport imported;
    imported.scene = sceneIn(in);
    // An animation is at least its name's count, its duration and its node count.
    imported.animations.resize(in.count(24, "animations"));
    for (AnimationSummary& animation : imported.animations) {
        animation.name = in.string("animation name");
        animation.durationSeconds = in.get<double>();
        animation.nodes = stringsIn(in, "animation nodes");
    }
    for (const quint64 take : in.block<quint64>("takes")) {
        if (take >= imported.animations.size())
            throw WireError("takes: there is no animation " + std::to_string(take));
        imported.takes.push_back(static_cast<std::size_t>(take));
    }
    const auto rule = in.get<quint8>();
    if (rule < static_cast<quint8>(TakeRule::NoAnimation) || rule > static_cast<quint8>(TakeRule::Chosen))
        throw WireError("unknown take rule " + std::to_string(rule));
    imported.takeRule = static_cast<TakeRule>(rule);
    imported.file.values = settingsIn(in, "the file's settings");
    imported.file.fpsSource = in.string("frame rate source");
    imported.file.unitSource = in.string("unit source");
    imported.file.upSource = in.string("up axis source");
    imported.applied = settingsIn(in, "the applied settings");
    if (imported.applied.fps != imported.scene.fps)
        throw WireError("the applied frame rate is not the scene's");
    imported.timeShift = checked("time shift", [&] { return model::finiteNumber(in.get<double>()); });
    imported.warnings = stringsIn(in, "warnings");
    return imported;
}

QString pathIn(Reader& in)
{
    QString path = in.string("path");
    if (path.isEmpty())
        throw WireError("the path is empty");
    return path;
}

} // namespace

QByteArray encodeRequest(const Request& request)
{
    Writer out;
    if (const auto* import = std::get_if<ImportRequest>(&request)) {
        header(out, Kind::ImportRequest);
        out.string(import->path);
        out.string(import->locale);
        writeImportOptions(out, import->options);
    } else {
        const auto& exportRequest = std::get<ExportRequest>(request);
        header(out, Kind::ExportRequest);
        out.string(exportRequest.path);
        out.string(exportRequest.locale);
        out.string(QString::fromLatin1(nameOf(kSceneFormatNames, exportRequest.format)));
        out.put(exportRequest.fps);
        writeScene(out, exportRequest.scene);
    }
    return out.take();
}

Request decodeRequest(const QByteArray& bytes)
{
    Reader in(bytes);
    Request request;
    switch (headerIn(in)) {
    case Kind::ImportRequest: {
        ImportRequest import{pathIn(in), in.string("locale"), {}};
        import.options = importOptionsIn(in);
        request = std::move(import);
        break;
    }
    case Kind::ExportRequest: {
        ExportRequest exportRequest;
        exportRequest.path = pathIn(in);
        exportRequest.locale = in.string("locale");
        exportRequest.format = named(in, kSceneFormatNames, "format");
        exportRequest.fps = in.get<double>();
        exportRequest.scene = sceneIn(in);
        request = std::move(exportRequest);
        break;
    }
    default:
        throw WireError("a reply where a request was expected");
    }
    in.requireEnd();
    return request;
}

QByteArray encodeReply(const Reply& reply)
{
    Writer out;
    if (const auto* imported = std::get_if<SceneImport>(&reply)) {
        header(out, Kind::SceneImport);
        writeSceneImport(out, *imported);
    } else if (const auto* report = std::get_if<ExportReport>(&reply)) {
        header(out, Kind::ExportReport);
        writeStrings(out, report->files);
        writeStrings(out, report->warnings);
    } else {
        const auto& failure = std::get<Failure>(reply);
        header(out, Kind::Failure);
        out.enumeration(failure.kind);
        out.string(failure.message);
    }
    return out.take();
}

Reply decodeReply(const QByteArray& bytes)
{
    Reader in(bytes);
    Reply reply;
    switch (headerIn(in)) {
    case Kind::SceneImport:
        reply = sceneImportIn(in);
        break;
    case Kind::ExportReport: {
        ExportReport report;
        report.files = stringsIn(in, "files");
        report.warnings = stringsIn(in, "warnings");
        reply = std::move(report);
        break;
    }
    case Kind::Failure: {
        Failure failure;
        const auto kind = in.get<quint8>();
        if (kind != 1 && kind != 2)
            throw WireError("unknown failure kind " + std::to_string(kind));
        failure.kind = static_cast<Failure::Kind>(kind);
        failure.message = in.string("message");
        reply = std::move(failure);
        break;
    }
    default:
        throw WireError("a request where a reply was expected");
    }
    in.requireEnd();
    return reply;
}

} // namespace gyre::io::wire
