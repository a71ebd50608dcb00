// The graph editor's channels (model/motion_channels.h) and the Euler filter's command on tracks
// whose answers are known without Gyre: a spin of 450° about z keyed every 90°, whose z angle must
// be a ramp past ±180° (unwrapped), whose quaternion keeps one sign through a full turn, and whose
// stored keys, flipped to −q at random, the filter puts back in one hemisphere without moving the
// motion at any time; and whether the filter would change a key, as the menu asks it, against the keys
// the filter makes.

#include "core/euler_angles.h"
#include "model/commands/apply_euler_filter_command.h"
#include "model/document.h"
#include "model/motion_channels.h"
#include "model/commands/import_objects_command.h"

#include <QTest>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

using namespace gyre;
using namespace gyre::model;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kKeys = 6; // 0°, 90°, ..., 450° at 0, 1, ..., 5 s

Eigen::Quaterniond aboutZ(double degrees)
{
    return Eigen::Quaterniond(Eigen::AngleAxisd(degrees * kPi / 180.0, Eigen::Vector3d::UnitZ()));
}

// Seven keys of a random tumble: in Euler mode (unless `quaternion`) with the angles of each key stored a turn
// off, or as the convention's twin, at random, or as read from the quaternion; each quaternion's sign at random.
MotionTrack randomTrack(std::mt19937& random, const EulerConvention& convention, bool quaternion)
{
    std::uniform_real_distribution<double> angle(-kPi, kPi);
    MotionTrack track;
    track.rotationMode = {quaternion ? RotationMode::Kind::Quaternion : RotationMode::Kind::Euler, convention};
    Eigen::Vector3d angles = Eigen::Vector3d::Zero();
    for (int k = 0; k < 7; ++k) {
        angles += Eigen::Vector3d(angle(random), angle(random), angle(random)) * 0.4;
        Eigen::Quaterniond q = quaternionFromEulerAngles(angles, convention);
        if (random() % 2 == 0)
            q.coeffs() = -q.coeffs();
        Keyframe key{double(k), Pose{q, Eigen::Vector3d::Zero()}, true};
        if (!quaternion) {
            Eigen::Vector3d stored = eulerAnglesFromQuaternion(q, convention).angles;
            if (random() % 4 == 0) // the twin: R_i(e1 + π)·R_j(π − e2)·R_k(e3 + π), or −e2 for proper Euler
                stored = {stored[0] + kPi, convention.isProperEuler() ? -stored[1] : kPi - stored[1], stored[2] + kPi};
            if (random() % 3 == 0)
                stored[random() % 3] += 2.0 * kPi * (random() % 2 == 0 ? 1.0 : -1.0);
            key.eulerAngles = stored;
        }
        track.keys.push_back(key);
    }
    return track;
}

SceneObject spin(bool flipOddKeys)
{
    SceneObject object;
    object.id = 1;
    object.track.interpolation = InterpolationMethod::Slerp;
    for (int k = 0; k < kKeys; ++k) {
        Eigen::Quaterniond q = aboutZ(90.0 * k);
        if (flipOddKeys && k % 2 == 1)
            q.coeffs() = -q.coeffs();
        object.track.keys.push_back(Keyframe{double(k), Pose{q, Eigen::Vector3d::Zero()}, true});
    }
    return object;
}

} // namespace

class TstMotionChannels : public QObject {
    Q_OBJECT

private slots:
    // The momentum and energy against a body made of point masses, each moving at v = ω × r:
    // L = Σ m·r × v and E = ½·Σ m·|v|², with I = Σ m·(|r|²·𝟙 − r·rᵀ) the only thing passed in.
    void momentumAndEnergyAreThoseOfPointMasses()
    {
        const std::vector<std::pair<double, Eigen::Vector3d>> masses{
            {1.0, {0.3, -0.2, 0.1}}, {2.0, {-0.1, 0.4, 0.2}}, {0.5, {0.2, 0.1, -0.5}}, {1.5, {-0.3, -0.1, 0.05}}};
        Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
        for (const auto& [m, r] : masses)
            inertia += m * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
        // Half a turn a second about a tilted axis, from a tilted start.
        const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, 2).normalized();
        const Eigen::Quaterniond start(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -1, 0).normalized()));
        SceneObject object;
        object.track.interpolation = InterpolationMethod::Slerp;
        for (int k = 0; k < 4; ++k)
            object.track.keys.push_back(
                Keyframe{double(k), Pose{Eigen::Quaterniond(Eigen::AngleAxisd(kPi / 2.0 * k, axis)) * start, {}}, true});
        const Eigen::Vector3d omega = kPi / 2.0 * axis;
        const TrackMotion motion(object.track);
        for (const VelocityFrame frame : {VelocityFrame::World, VelocityFrame::Local}) {
            ChannelSettings settings{{}, frame, 0.0, 3.0, 31};
            settings.inertia = inertia;
            const ChannelCurves curves = sampleChannels(motion, object.track.keys, settings);
            // Not the first and last samples, at the ends of the keys, where the motion stops.
            for (std::size_t i = 1; i + 1 < curves.times.size(); ++i) {
                const Eigen::Quaterniond q = motion.at(curves.times[i]).orientation;
                Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
                double energy = 0.0;
                for (const auto& [m, r] : masses) {
                    const Eigen::Vector3d position = q * r;
                    const Eigen::Vector3d velocity = omega.cross(position);
                    momentum += m * position.cross(velocity);
                    energy += 0.5 * m * velocity.squaredNorm();
                }
                const Eigen::Vector3d expected = frame == VelocityFrame::World ? momentum : Eigen::Vector3d(q.conjugate() * momentum);
                const Eigen::Vector3d actual(curves.value(Channel::AngularMomentumX, i), curves.value(Channel::AngularMomentumY, i),
                                             curves.value(Channel::AngularMomentumZ, i));
                QVERIFY2((actual - expected).norm() < 1e-7, qPrintable(QStringLiteral("L at sample %1").arg(i)));
                QVERIFY(std::abs(curves.value(Channel::AngularMomentumMagnitude, i) - momentum.norm()) < 1e-7);
                QVERIFY(std::abs(curves.value(Channel::KineticEnergy, i) - energy) < 1e-7);
            }
        }
    }

    void aSpinIsARampAndTheQuaternionKeepsItsSign()
    {
        const SceneObject object = spin(false);
        const TrackMotion motion(object.track);
        const ChannelCurves curves = sampleChannels(motion, object.track.keys, {{}, VelocityFrame::World, 0.0, 5.0, 501});
        QCOMPARE(curves.times.size(), std::size_t(501));
        for (std::size_t i = 0; i < curves.times.size(); ++i) {
            const double t = curves.times[i];
            QVERIFY(std::abs(curves.value(Channel::EulerThird, i) - 90.0 * t) < 1e-6);
            // q(t) = (cos(45°·t), 0, 0, sin(45°·t)) continuous: w passes −1 at 4 s, not jumping back.
            QVERIFY(std::abs(curves.value(Channel::QuaternionW, i) - std::cos(kPi / 4.0 * t)) < 1e-9);
            QVERIFY(std::abs(curves.value(Channel::QuaternionZ, i) - std::sin(kPi / 4.0 * t)) < 1e-9);
        }
        QCOMPARE(curves.keySamples.size(), std::size_t(kKeys));
        QCOMPARE(curves.times[curves.keySamples[3].first], 3.0);
        // e2 stays 0, 90° from the xyz order's lock.
        QVERIFY(curves.gimbalZones.empty());
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, sampleChannels(motion, object.track.keys, {{}, VelocityFrame::World, 1.0, 1.0, 10}));
    }

    void theFilterFlipsSignsAndKeepsTheMotion()
    {
        Document document;
        auto* import = new ImportObjectsCommand(document, {spin(true)});
        document.push(import);
        const ObjectId id = import->ids().front();
        const MotionTrack before = document.object(id)->track;
        QVERIFY(ApplyEulerFilterCommand::changes(before));
        document.push(new ApplyEulerFilterCommand(document, id));
        const MotionTrack& after = document.object(id)->track;
        QVERIFY(!ApplyEulerFilterCommand::changes(after));
        QCOMPARE(after.keys[0].pose.orientation.coeffs(), before.keys[0].pose.orientation.coeffs());
        for (int k = 1; k < kKeys; ++k)
            QVERIFY(after.keys[k].pose.orientation.coeffs().dot(after.keys[k - 1].pose.orientation.coeffs()) >= 0.0);
        const TrackMotion was(before);
        const TrackMotion is(after);
        for (double t = -0.5; t <= 5.5; t += 0.05)
            QVERIFY(std::abs(std::abs(was.at(t).orientation.dot(is.at(t).orientation)) - 1.0) < 1e-12);
        document.undoStack().undo();
        for (int k = 0; k < kKeys; ++k)
            QCOMPARE(document.object(id)->track.keys[k].pose.orientation.coeffs(), before.keys[k].pose.orientation.coeffs());
    }

    // changes finds the first key the filter would change without filtering a copy: on tracks of every kind of
    // jump (signs flipped, angles a turn off or on the twin solution, or continuous already) and on every kind of
    // subset (runs, the first key, indices past the last), it says whether filteredKeys differs from the keys.
    void changesSaysWhetherTheFilterChangesAKey()
    {
        std::mt19937 random(3517);
        const std::vector<EulerConvention> conventions = EulerConvention::all();
        int changing = 0;
        int unchanging = 0;
        for (int trial = 0; trial < 400; ++trial) {
            MotionTrack track = randomTrack(random, conventions[random() % conventions.size()], trial % 4 == 0);
            // A quarter of the tracks filtered once already, where little or nothing is left to change.
            if (trial % 4 == 1)
                track.keys = ApplyEulerFilterCommand::filteredKeys(track);
            ApplyEulerFilterCommand::KeySubset subset;
            if (trial % 3 != 0) {
                subset.emplace();
                for (std::size_t i = 0; i < track.keys.size() + 2; ++i)
                    if (random() % 3 == 0)
                        subset->push_back(i);
            }
            const std::vector<Keyframe> filtered = ApplyEulerFilterCommand::filteredKeys(track, subset);
            bool differs = false;
            for (std::size_t i = 0; i < filtered.size(); ++i)
                differs = differs || filtered[i].pose.orientation.coeffs() != track.keys[i].pose.orientation.coeffs() ||
                          filtered[i].eulerAngles != track.keys[i].eulerAngles;
            QVERIFY2(ApplyEulerFilterCommand::changes(track, subset) == differs, qPrintable(QString::number(trial)));
            ++(differs ? changing : unchanging);
        }
        QVERIFY(changing > 50 && unchanging > 50);
    }
};

QTEST_MAIN(TstMotionChannels)
#include "tst_motion_channels.moc"
