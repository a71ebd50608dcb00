// glTF animation samplers as the file means them (io/gltf_animation.h): STEP stays a step, CUBICSPLINE
// keeps its tangents, checked against the specification's Hermite formula written here; and a hermite
// track written as a CUBICSPLINE sampler reads back as the same motion between the keys too, a fit over
// some of its keys included.

#include "core/core_test_support.h"
#include "io/gltf_animation.h"
#include "io/scene_export.h"
#include "io/scene_import.h"
#include "io/up_axis.h"
#include "model/track_evaluation.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QObject>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <map>
#include <cstring>
#include <vector>

using namespace gyre;
using namespace gyre::io;
using namespace gyre::test;

namespace {

struct SamplerSpec {
    const char* interpolation;
    const char* path; // "rotation" or "translation"
    std::vector<float> times;
    std::vector<float> output; // 4 (rotation) or 3 (translation) floats per element
};

// A .gltf of one node without a mesh, "spinner" or unnamed, moved by one animation of `samplers`, its
// buffer a data URI.
QByteArray gltfOf(const std::vector<SamplerSpec>& samplers, bool named = true)
{
    QByteArray buffer;
    QJsonArray views;
    QJsonArray accessors;
    const auto addAccessor = [&](const std::vector<float>& floats, const char* type, int components, bool bounds) {
        QJsonObject accessor{{"bufferView", static_cast<int>(views.size())},
                             {"componentType", 5126},
                             {"count", static_cast<int>(floats.size()) / components},
                             {"type", type}};
        if (bounds) {
            const auto [low, high] = std::minmax_element(floats.begin(), floats.end());
            accessor["min"] = QJsonArray{*low};
            accessor["max"] = QJsonArray{*high};
        }
        views.append(QJsonObject{{"buffer", 0},
                                 {"byteOffset", static_cast<int>(buffer.size())},
                                 {"byteLength", static_cast<int>(floats.size() * sizeof(float))}});
        buffer.append(reinterpret_cast<const char*>(floats.data()), static_cast<qsizetype>(floats.size() * sizeof(float)));
        accessors.append(accessor);
        return static_cast<int>(accessors.size()) - 1;
    };
    QJsonArray jsonSamplers;
    QJsonArray channels;
    for (const SamplerSpec& spec : samplers) {
        const bool rotation = std::strcmp(spec.path, "rotation") == 0;
        const int input = addAccessor(spec.times, "SCALAR", 1, true);
        const int output = addAccessor(spec.output, rotation ? "VEC4" : "VEC3", rotation ? 4 : 3, false);
        channels.append(QJsonObject{{"sampler", static_cast<int>(jsonSamplers.size())},
                                    {"target", QJsonObject{{"node", 0}, {"path", spec.path}}}});
        jsonSamplers.append(QJsonObject{{"input", input}, {"output", output}, {"interpolation", spec.interpolation}});
    }
    const QJsonObject gltf{
        {"asset", QJsonObject{{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", QJsonArray{QJsonObject{{"nodes", QJsonArray{0}}}}},
        {"nodes", QJsonArray{named ? QJsonObject{{"name", "spinner"}} : QJsonObject{}}},
        {"buffers", QJsonArray{QJsonObject{{"byteLength", static_cast<int>(buffer.size())},
                                           {"uri", QString::fromLatin1("data:application/octet-stream;base64," +
                                                                       buffer.toBase64())}}}},
        {"bufferViews", views},
        {"accessors", accessors},
        {"animations", QJsonArray{QJsonObject{{"name", "take"}, {"samplers", jsonSamplers}, {"channels", channels}}}},
    };
    return QJsonDocument(gltf).toJson();
}

void appendQuaternion(std::vector<float>& out, const Eigen::Quaterniond& q)
{
    out.insert(out.end(), {static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z()),
                           static_cast<float>(q.w())});
}

Eigen::Vector4d vec4(const float* xyzw) { return {xyzw[0], xyzw[1], xyzw[2], xyzw[3]}; }

// The glTF specification's CUBICSPLINE (Appendix C) of elements of N floats:
// p(s) = (2s³−3s²+1)vₖ + tₔ(s³−2s²+s)bₖ + (−2s³+3s²)vₖ₊₁ + tₔ(s³−s²)aₖ₊₁, output laid out as aₖ, vₖ, bₖ.
template <int N>
Eigen::Matrix<double, N, 1> specCubic(const std::vector<float>& inputs, const std::vector<float>& output, double t)
{
    const std::vector<double> times(inputs.begin(), inputs.end());
    std::size_t k = 0;
    while (k + 2 < times.size() && t >= times[k + 1])
        ++k;
    const auto element = [&](std::size_t key, int part) {
        return Eigen::Map<const Eigen::Matrix<float, N, 1>>(&output[(3 * key + static_cast<std::size_t>(part)) * N])
            .template cast<double>()
            .eval();
    };
    const double td = times[k + 1] - times[k];
    const double s = std::clamp((t - times[k]) / td, 0.0, 1.0);
    const double s2 = s * s;
    const double s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * element(k, 1) + td * (s3 - 2 * s2 + s) * element(k, 2) +
           (-2 * s3 + 3 * s2) * element(k + 1, 1) + td * (s3 - s2) * element(k + 1, 0);
}

// A rotation sampler's, normalised.
Eigen::Quaterniond specCubicSpline(const std::vector<float>& inputs, const std::vector<float>& output, double t)
{
    const Eigen::Vector4d p = specCubic<4>(inputs, output, t);
    return Eigen::Quaterniond(p[3], p[0], p[1], p[2]).normalized();
}

Eigen::Quaterniond aboutZ(double angle) { return Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ())); }

// The floats of accessor `index` of a .gltf (`gltf`) whose one buffer is `bin`, read as the specification
// lays them out: the accessor's view's bytes from its offset, tightly packed.
std::vector<float> accessorFloats(const QJsonObject& gltf, const QByteArray& bin, int index)
{
    const QJsonObject accessor = gltf["accessors"].toArray()[index].toObject();
    const QJsonObject view = gltf["bufferViews"].toArray()[accessor["bufferView"].toInt()].toObject();
    const QString type = accessor["type"].toString();
    const int components = type == QLatin1String("VEC4") ? 4 : type == QLatin1String("VEC3") ? 3 : 1;
    std::vector<float> floats(static_cast<std::size_t>(accessor["count"].toInt() * components));
    const int offset = view["byteOffset"].toInt() + accessor["byteOffset"].toInt();
    if (offset + static_cast<qsizetype>(floats.size() * sizeof(float)) > bin.size())
        qFatal("accessor %d lies past its buffer", index);
    std::memcpy(floats.data(), bin.constData() + offset, floats.size() * sizeof(float));
    return floats;
}

} // namespace

class TstGltfSamplers : public QObject {
    Q_OBJECT

private slots:
    void stepStaysAStep_data();
    void stepStaysAStep();
    void cubicSplineKeepsItsTangents();
    void cubicSplineWithACornerIsBakedAtTheFrames();
    void hermiteTrackIsWrittenAsCubicSpline();
    void aFitOverSomeKeysIsWrittenAsOneSplineWithCorners();
    void accessorPastItsBufferIsRefusedNamingTheField();
    void aTrackPastTheKeyBudgetIsRefusedBeforeItIsBuilt();

private:
    QString path(const QString& name) const { return directory_.filePath(name); }

    SceneImport importGltf(const std::vector<SamplerSpec>& samplers, const QString& name, bool named = true) const
    {
        QFile file(path(name));
        if (!file.open(QIODevice::WriteOnly) || file.write(gltfOf(samplers, named)) < 0)
            qFatal("cannot write %s", qPrintable(file.fileName()));
        file.close();
        ImportOptions options;
        options.fps = 24.0;
        options.up = UpAxis::Z; // the file's own axes, so the test compares the file's values
        options.timeOrigin = TimeOrigin::File;
        return importScene(file.fileName(), options);
    }

    QTemporaryDir directory_;
};

// Rotation keys 0°, 90°, 180° about z at 0, 1, 2 s and positions at 0, 1.5 s, both STEP: at every frame
// the value is the last key's, up to the frame before the next key; for a node without a name too,
// which Assimp calls "nodes[0]".
void TstGltfSamplers::stepStaysAStep_data()
{
    QTest::addColumn<bool>("named");
    QTest::newRow("named") << true;
    QTest::newRow("unnamed") << false;
}

void TstGltfSamplers::stepStaysAStep()
{
    QFETCH(bool, named);
    std::vector<float> rotations;
    for (const double angle : {0.0, kPi / 2, kPi})
        appendQuaternion(rotations, aboutZ(angle));
    const SceneImport imported = importGltf(
        {{"STEP", "rotation", {0.0f, 1.0f, 2.0f}, rotations}, {"STEP", "translation", {0.0f, 1.5f}, {0, 0, 0, 1, 2, 3}}},
        "step.gltf", named);
    QCOMPARE(imported.scene.objects.size(), std::size_t{1});
    const model::TrackMotion motion(imported.scene.objects[0].track);
    for (int frame = 0; frame <= 60; ++frame) {
        const double t = frame / 24.0;
        const double expectedAngle = t < 1.0 ? 0.0 : t < 2.0 ? kPi / 2 : kPi;
        const Eigen::Vector3d expectedPosition = t < 1.5 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(1, 2, 3);
        const Pose pose = motion.at(t);
        GYRE_CHECK(distanceUpToSign(pose.orientation, aboutZ(expectedAngle)) < 1e-6,
                   QStringLiteral("frame %1: %2, not the step's %3")
                       .arg(frame)
                       .arg(str(pose.orientation), str(expectedAngle)));
        GYRE_CHECK((pose.position - expectedPosition).norm() < 1e-6,
                   QStringLiteral("frame %1: position %2").arg(frame).arg(str(pose.position)));
    }
}

// Three keys with tangents that agree at the inner key: a hermite track whose fit is the file's spline,
// equal to the specification's formula at every time, between the keys too.
void TstGltfSamplers::cubicSplineKeepsItsTangents()
{
    const std::vector<float> times{0.0f, 1.0f, 2.5f};
    std::vector<float> output;
    const Eigen::Quaterniond values[] = {aboutZ(0.0), Eigen::Quaterniond(Eigen::AngleAxisd(1.7, Eigen::Vector3d::UnitX())),
                                         Eigen::Quaterniond(Eigen::AngleAxisd(2.9, Eigen::Vector3d(1, 1, 0).normalized()))};
    const Eigen::Quaterniond tangents[] = {{0.1, 0.4, -0.2, 1.3}, {-0.3, 1.1, 0.5, 0.2}, {0.2, -0.6, 0.9, 0.4}};
    for (int k = 0; k < 3; ++k) {
        appendQuaternion(output, tangents[k]); // in-tangent
        appendQuaternion(output, values[k]);
        appendQuaternion(output, tangents[k]); // out-tangent, the same: no corner
    }
    const SceneImport imported = importGltf({{"CUBICSPLINE", "rotation", times, output}}, "cubic.gltf");
    const model::MotionTrack& track = imported.scene.objects.at(0).track;
    QCOMPARE(track.interpolation, InterpolationMethod::Hermite);
    QCOMPARE(track.sketch.fittedCurve.size(), std::size_t{3});
    const model::TrackMotion motion(track);
    double worst = 0.0;
    for (int i = 0; i <= 2500; ++i) {
        const double t = i / 1000.0;
        worst = std::max(worst, angleBetween(motion.at(t).orientation, specCubicSpline(times, output, t)));
    }
    GYRE_CHECK(worst < 1e-9, QStringLiteral("off the specification's spline by %1 rad").arg(str(worst)));
}

// An in-tangent unlike the out-tangent is a corner no hermite track holds: the spline is baked at the
// frames, exact there.
void TstGltfSamplers::cubicSplineWithACornerIsBakedAtTheFrames()
{
    const std::vector<float> times{0.0f, 1.0f, 2.0f};
    std::vector<float> output;
    const Eigen::Quaterniond values[] = {aboutZ(0.0), aboutZ(1.0), aboutZ(2.5)};
    const Eigen::Quaterniond in[] = {{0, 0, 0, 0}, {0, 0, 0, 0.2}, {0, 0, 0, 0.9}};
    const Eigen::Quaterniond out[] = {{0, 0, 0, 0.5}, {0, 0, 0, 1.4}, {0, 0, 0, 0}};
    for (int k = 0; k < 3; ++k) {
        appendQuaternion(output, in[k]);
        appendQuaternion(output, values[k]);
        appendQuaternion(output, out[k]);
    }
    const SceneImport imported = importGltf({{"CUBICSPLINE", "rotation", times, output}}, "corner.gltf");
    const model::MotionTrack& track = imported.scene.objects.at(0).track;
    QCOMPARE(track.interpolation, InterpolationMethod::Slerp);
    QCOMPARE(track.keys.size(), std::size_t{49});
    const model::TrackMotion motion(track);
    for (int frame = 0; frame <= 48; ++frame) {
        const double t = frame / 24.0;
        GYRE_CHECK(angleBetween(motion.at(t).orientation, specCubicSpline(times, output, t)) < 1e-9,
                   QStringLiteral("frame %1 is off the specification's spline").arg(frame));
    }
}

// A hermite track with uneven keys and large turns, and one whose fit bends it: written as a
// CUBICSPLINE sampler, read back as the same motion at a thousand times per second.
void TstGltfSamplers::hermiteTrackIsWrittenAsCubicSpline()
{
    model::Scene scene;
    scene.startTime = 0.0;
    scene.endTime = 3.0;
    model::SceneObject object;
    object.id = scene.nextObjectId++;
    object.name = QStringLiteral("top");
    object.track.interpolation = InterpolationMethod::Hermite;
    const Eigen::Quaterniond tilted(Eigen::AngleAxisd(2.6, Eigen::Vector3d(1, 2, 3).normalized()));
    object.track.keys = {{0.0, {aboutZ(0.0), {0, 0, 0}}, true},
                         {0.7, {tilted, {1, 0, 0}}, true},
                         {1.5, {Eigen::Quaterniond(Eigen::AngleAxisd(-1.2, Eigen::Vector3d::UnitY())), {1, 1, 0}}, true},
                         {3.0, {aboutZ(3.0), {0, 1, 2}}, true}};
    scene.objects.push_back(object);
    object.id = scene.nextObjectId++;
    object.name = QStringLiteral("fitted");
    std::vector<OrientationKey> keys;
    for (const model::Keyframe& key : object.track.keys)
        keys.push_back({key.time, key.pose.orientation});
    object.track.sketch.fittedCurve = HermiteQuaternionSpline::throughKeys(keys).controlPoints();
    object.track.sketch.fittedCurve[1].derivative.coeffs() *= 1.8; // a bend Gyre's own rule would not give
    scene.objects.push_back(object);

    for (const auto format : {SceneFormat::Gltf, SceneFormat::Glb}) {
        const std::string extension(nameOf(kSceneFormatNames, format));
        const QString file = path(QStringLiteral("hermite.") + QString::fromStdString(extension));
        exportScene(scene, file, format, 24.0);
        QFile written(file);
        QVERIFY(written.open(QIODevice::ReadOnly));
        QCOMPARE(written.readAll().count("CUBICSPLINE"), 4); // rotation and translation of each
        ImportOptions options;
        options.timeOrigin = TimeOrigin::File;
        const SceneImport imported = importScene(file, options);
        QCOMPARE(imported.scene.objects.size(), std::size_t{2});
        for (std::size_t i = 0; i < 2; ++i) {
            const model::TrackMotion before(scene.objects[i].track);
            const model::TrackMotion after(imported.scene.objects[i].track);
            QCOMPARE(imported.scene.objects[i].track.interpolation, InterpolationMethod::Hermite);
            double worst = 0.0;
            for (int step = 0; step <= 3000; ++step) {
                const double t = step / 1000.0;
                worst = std::max(worst, angleBetween(before.at(t).orientation, after.at(t).orientation));
            }
            qInfo("%s, %s: worst %.3g rad (%.3g°)", qPrintable(file), qPrintable(scene.objects[i].name), worst,
                  worst * 180.0 / kPi);
            GYRE_CHECK(worst < 1e-5, QStringLiteral("%1 is off by %2 rad").arg(scene.objects[i].name, str(worst)));
        }
    }
}

// A fit over the middle keys only, its control points scaled by −1.4 (the same normalised curve on the
// other hemisphere) and bent: the keys' spline plays before and after it. Written as one CUBICSPLINE
// sampler with a corner at each end of the fit, it plays the track at every millisecond, evaluated here
// by the specification's formula; so does the translation, the hermite track's cubic positions.
void TstGltfSamplers::aFitOverSomeKeysIsWrittenAsOneSplineWithCorners()
{
    model::Scene scene;
    scene.startTime = 0.0;
    scene.endTime = 4.0;
    model::SceneObject object;
    object.id = scene.nextObjectId++;
    object.name = QStringLiteral("fitted");
    object.track.interpolation = InterpolationMethod::Hermite;
    const std::vector<double> times{0.0, 0.8, 1.7, 2.9, 4.0};
    std::vector<OrientationKey> middle;
    for (std::size_t i = 0; i < times.size(); ++i) {
        const Eigen::Quaterniond q(Eigen::AngleAxisd(0.9 * double(i), Eigen::Vector3d(1.0, double(i), 2.0).normalized()));
        object.track.keys.push_back({times[i], {q, {double(i), 0, 0}}, true});
        if (i >= 1 && i <= 3)
            middle.push_back({times[i], q});
    }
    std::vector<HermiteControlPoint> fit = HermiteQuaternionSpline::throughKeys(middle).controlPoints();
    fit[1].derivative.coeffs() *= 1.8;
    for (HermiteControlPoint& point : fit) {
        point.value.coeffs() *= -1.4;
        point.derivative.coeffs() *= -1.4;
    }
    object.track.sketch.fittedCurve = fit;
    scene.objects.push_back(object);

    const QString file = path(QStringLiteral("partial.gltf"));
    exportScene(scene, file, SceneFormat::Gltf, 24.0);
    QFile written(file);
    QVERIFY(written.open(QIODevice::ReadOnly));
    const QJsonObject gltf = QJsonDocument::fromJson(written.readAll()).object();
    QFile binFile(path(gltf["buffers"].toArray()[0].toObject()["uri"].toString()));
    QVERIFY(binFile.open(QIODevice::ReadOnly));
    const QByteArray bin = binFile.readAll();
    const QJsonArray samplers = gltf["animations"].toArray()[0].toObject()["samplers"].toArray();
    // The sampler of each path, by the channel that names it.
    std::map<QString, std::pair<std::vector<float>, std::vector<float>>> splines; // input, output
    for (const QJsonValue& channel : gltf["animations"].toArray()[0].toObject()["channels"].toArray()) {
        const QJsonObject sampler = samplers[channel["sampler"].toInt()].toObject();
        QCOMPARE(sampler["interpolation"].toString(), QStringLiteral("CUBICSPLINE"));
        splines[channel["target"]["path"].toString()] = {accessorFloats(gltf, bin, sampler["input"].toInt()),
                                                         accessorFloats(gltf, bin, sampler["output"].toInt())};
    }
    QCOMPARE(splines.size(), std::size_t{2});
    const auto& [inputs, output] = splines.at(QStringLiteral("rotation"));
    const auto& [positionInputs, positionOutput] = splines.at(QStringLiteral("translation"));
    QCOMPARE(output.size(), 3 * 4 * inputs.size());
    QCOMPARE(positionOutput.size(), 3 * 3 * positionInputs.size());
    // The file is Y-up: its rotation and position are Gyre's turned by the inverse of yUpToZUp().
    const model::TrackMotion motion(object.track);
    double worst = 0.0;
    double worstPosition = 0.0;
    for (int step = 0; step <= 4000; ++step) {
        const double t = step / 1000.0;
        const Pose pose = motion.at(t);
        worst = std::max(worst, angleBetween(pose.orientation, yUpToZUp() * specCubicSpline(inputs, output, t)));
        worstPosition = std::max(worstPosition,
                                 (pose.position - yUpToZUp() * specCubic<3>(positionInputs, positionOutput, t)).norm());
    }
    qInfo("a fit over keys 1 to 3 of 5, written as CUBICSPLINE: worst %.3g rad (%.3g°), %.3g m at every millisecond",
          worst, worst * 180.0 / kPi, worstPosition);
    GYRE_CHECK(worst < 1e-5, QStringLiteral("off by %1 rad").arg(str(worst)));
    GYRE_CHECK(worstPosition < 1e-5, QStringLiteral("off by %1 m").arg(str(worstPosition)));
    // The corners are real: at the fit's start the in- and out-tangents differ.
    const auto start = std::ranges::find(inputs, static_cast<float>(times[1]));
    QVERIFY(start != inputs.end());
    const std::size_t key = static_cast<std::size_t>(start - inputs.begin());
    QVERIFY((vec4(&output[(3 * key) * 4]) - vec4(&output[(3 * key + 2) * 4])).norm() > 0.1);
}

void TstGltfSamplers::accessorPastItsBufferIsRefusedNamingTheField()
{
    const QByteArray valid = gltfOf({{"LINEAR", "rotation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, 0, 1, 0}}});
    QJsonObject gltf = QJsonDocument::fromJson(valid).object();
    QJsonArray accessors = gltf["accessors"].toArray();
    QJsonObject output = accessors[1].toObject();
    output["count"] = 9;
    accessors[1] = output;
    gltf["accessors"] = accessors;
    QFile file(path("past.gltf"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(QJsonDocument(gltf).toJson());
    file.close();
    try {
        readGltfAnimations(file.fileName());
        QFAIL("an accessor past its buffer view was read");
    } catch (const InputError& error) {
        const QString message = QString::fromUtf8(error.what());
        QVERIFY2(message.contains(file.fileName()), qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("animations[0].samplers[0].output (accessors[1])")), qPrintable(message));
    }
}

// kMaxGltfTrackKeys holds however the keys come: a sampler's own keys, and a STEP sampler's hold keys.
void TstGltfSamplers::aTrackPastTheKeyBudgetIsRefusedBeforeItIsBuilt()
{
    const auto sampler = [](GltfInterpolation interpolation, std::size_t keys) {
        GltfSampler result;
        result.interpolation = interpolation;
        for (std::size_t k = 0; k < keys; ++k)
            result.times.push_back(static_cast<double>(k));
        result.values.assign(keys, Eigen::Vector4d(0, 0, 0, 1));
        return result;
    };
    const QString file = QStringLiteral("big.glb");
    const QString node = QStringLiteral("spinner");
    const auto refusal = [&](const GltfNodeMotion& motion) {
        try {
            gltfTrack(motion, Pose{}, 1.0, 24.0, file, node);
        } catch (const InputError& error) {
            return QString::fromUtf8(error.what());
        }
        return QString();
    };
    const QString linear = refusal({sampler(GltfInterpolation::Linear, kMaxGltfTrackKeys + 1), std::nullopt});
    QVERIFY2(linear.contains(file) && linear.contains(node) && linear.contains(QString::number(kMaxGltfTrackKeys)),
             qPrintable(linear));
    // Half the budget of steps and as many holds: over it too.
    QVERIFY(!refusal({sampler(GltfInterpolation::Step, kMaxGltfTrackKeys / 2 + 1), std::nullopt}).isEmpty());
    // Within the budget: built.
    QVERIFY(refusal({sampler(GltfInterpolation::Linear, 1000), std::nullopt}).isEmpty());
}

QTEST_GUILESS_MAIN(TstGltfSamplers)
#include "tst_gltf_samplers.moc"
