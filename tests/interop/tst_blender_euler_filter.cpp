// Issue 23's Euler filter on import, against a real client: Blender (wrapping_spin.py) writes an FBX whose object
// spins about Z through keys of 0°, 170°, 190°, 350° and 530°, which Assimp hands over as quaternions, so that
// the angles read back from them wrap into (−180°, 180°] and saw-tooth. gyre-cli import --euler-filter must put
// the track in Euler mode (extrinsic xyz, Blender's XYZ) with stored angles that are a continuous ramp: every
// consecutive difference below π, the z angle at Blender's keys the degrees Blender keyed (530° at the end, not
// 170° or its twin (180°, 180°, 350°)), and each key's orientation the one Blender evaluates there.

#include "cli_test_support.h"
#include "model/project_file.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace gyre;
using gyre::test::CliTestCase;

namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;
// Blender writes the FBX curves and Assimp turns them into quaternions in single precision.
constexpr double kSinglePrecisionRadians = 2e-6;

const QString kFiles = qEnvironmentVariable("GYRE_BLENDER_FILES");

} // namespace

class TestBlenderEulerFilter : public CliTestCase {
    Q_OBJECT

private slots:
    void importedSpinIsARamp()
    {
        const QString fbx = kFiles + QStringLiteral("/wrapping_spin.fbx");
        QFile json(kFiles + QStringLiteral("/wrapping_spin.json"));
        QVERIFY2(json.open(QIODevice::ReadOnly), qPrintable(json.fileName()));
        const QJsonObject blender = QJsonDocument::fromJson(json.readAll()).object();
        const double fps = blender.value(QStringLiteral("fps")).toDouble();
        const double frameStart = blender.value(QStringLiteral("frame_start")).toDouble();
        QVERIFY(fps > 0.0);

        // Without the option the keys are quaternions, as the file's.
        QVERIFY(succeeds({QStringLiteral("import"), fbx, QStringLiteral("-o"), path(QStringLiteral("plain.gyre"))}));
        const model::Scene plain = model::readProject(path(QStringLiteral("plain.gyre")));
        QCOMPARE(plain.objects.size(), std::size_t{1});
        QVERIFY(!plain.objects.front().track.rotationMode.isEuler());

        QVERIFY(succeeds({QStringLiteral("import"), fbx, QStringLiteral("-o"), path(QStringLiteral("filtered.gyre")),
                          QStringLiteral("--euler-filter")}));
        const model::Scene scene = model::readProject(path(QStringLiteral("filtered.gyre")));
        QCOMPARE(scene.objects.size(), std::size_t{1});
        const model::SceneObject& spin = scene.objects.front();
        QCOMPARE(spin.name, QStringLiteral("Spin"));
        QCOMPARE(spin.parent, model::kNoObject); // its local pose is its world pose
        const model::MotionTrack& track = spin.track;
        QVERIFY(track.rotationMode.isEuler());
        QCOMPARE(track.rotationMode.convention, EulerConvention{});
        QCOMPARE(track.interpolation, InterpolationMethod::Euler);
        QVERIFY(track.keys.size() >= 5);
        for (std::size_t k = 0; k < track.keys.size(); ++k) {
            QVERIFY(track.keys[k].eulerAngles.has_value());
            const Eigen::Vector3d angles = *track.keys[k].eulerAngles;
            QVERIFY2(angles.head<2>().norm() < kSinglePrecisionRadians, qPrintable(QString::number(k)));
            if (k > 0) {
                const double step = (angles - *track.keys[k - 1].eulerAngles).cwiseAbs().maxCoeff();
                QVERIFY2(step < std::numbers::pi, qPrintable(QStringLiteral("key %1: step %2°").arg(k).arg(step * kDegrees)));
            }
        }

        double worstApart = 0.0;
        const QJsonArray keys = blender.value(QStringLiteral("keys")).toArray();
        QCOMPARE(keys.size(), 5);
        for (const QJsonValue& value : keys) {
            const QJsonObject key = value.toObject();
            const double time = (key.value(QStringLiteral("frame")).toDouble() - frameStart) / fps;
            const auto at = std::find_if(track.keys.begin(), track.keys.end(),
                                         [time](const model::Keyframe& keyframe) { return std::abs(keyframe.time - time) < 1e-9; });
            QVERIFY2(at != track.keys.end(), qPrintable(QString::number(time)));
            const double degrees = key.value(QStringLiteral("degrees")).toDouble();
            const double stored = at->eulerAngles->z();
            QVERIFY2(std::abs(stored - degrees / kDegrees) < kSinglePrecisionRadians,
                     qPrintable(QStringLiteral("at %1 s: stored %2°, Blender keyed %3°").arg(time).arg(stored * kDegrees).arg(degrees)));
            const QJsonArray w = key.value(QStringLiteral("rotation")).toArray();
            const Eigen::Quaterniond expected(w[0].toDouble(), w[1].toDouble(), w[2].toDouble(), w[3].toDouble());
            const double apart = 2.0 * std::acos(std::min(1.0, std::abs(expected.normalized().dot(at->pose.orientation.normalized()))));
            QVERIFY2(apart < kSinglePrecisionRadians, qPrintable(QStringLiteral("at %1 s: %2° from Blender's").arg(time).arg(apart * kDegrees)));
            worstApart = std::max(worstApart, apart);
        }
        const double last = track.keys.back().eulerAngles->z() * kDegrees;
        qInfo("%zu keys; the last stored z %.9f°; at Blender's keys at most %.3g rad from Blender's rotation", track.keys.size(),
              last, worstApart);
        QVERIFY2(std::abs(last - 530.0) < kSinglePrecisionRadians * kDegrees, qPrintable(QString::number(last, 'g', 12)));
    }
};

QTEST_GUILESS_MAIN(TestBlenderEulerFilter)
#include "tst_blender_euler_filter.moc"
