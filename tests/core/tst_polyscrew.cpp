// Polyscrews (polyscrew.h): evaluation through the control poses, span by span as the screws
// between them, clamped or wrapped at the ends; and the trajectory samples of a body point, checked
// on motions whose kinematics are known exactly (uniform rotation about a fixed axis, uniform
// translation).

#include "core/polyscrew.h"

#include "core_test_support.h"

#include <QObject>
#include <QTest>

#include <stdexcept>
#include <vector>

using namespace gyre;
using namespace gyre::test;

namespace {

std::vector<Pose> randomWalk(Random& random, std::size_t n)
{
    std::vector<Pose> poses;
    Pose p = random.pose(3.0);
    for (std::size_t i = 0; i < n; ++i) {
        poses.push_back(p);
        p.orientation = random.rotationWithAngle(0.0, 2.0) * p.orientation;
        p.position += random.vector(2.0);
    }
    return poses;
}

} // namespace

class TestPolyscrew : public QObject {
    Q_OBJECT

private slots:
    void passesThroughItsPoses();
    void eachSpanIsItsScrew();
    void openEndsAreClamped();
    void cyclesWrap();
    void singlePose();
    void invalidArgumentsThrow();
    void trajectoryOfUniformRotation();
    void trajectoryOfUniformTranslation();
};

void TestPolyscrew::passesThroughItsPoses()
{
    Random random(200);
    for (bool cyclic : {false, true}) {
        for (std::size_t perUnit : {std::size_t(1), std::size_t(4), std::size_t(16)}) {
            const std::vector<Pose> poses = randomWalk(random, 9);
            const Polyscrew motion(poses, cyclic, perUnit);
            QCOMPARE(motion.isCyclic(), cyclic);
            QCOMPARE(motion.poses().size(), poses.size());
            const std::size_t spans = cyclic ? poses.size() : poses.size() - 1;
            QCOMPARE(motion.spanCount(), spans);
            QVERIFY(std::abs(motion.duration() - double(spans) / double(perUnit)) < 1e-15);
            for (std::size_t i = 0; i < poses.size(); ++i) {
                const Pose p = motion.at(double(i) / double(perUnit));
                GYRE_CHECK(poseDistance(p, poses[i]) < 1e-12,
                           QStringLiteral("%1, %2 per unit: at pose %3 got %4, expected %5").arg(cyclic ? "cyclic" : "open").arg(perUnit).arg(i).arg(str(p), str(poses[i])));
            }
        }
    }
}

void TestPolyscrew::eachSpanIsItsScrew()
{
    Random random(201);
    for (bool cyclic : {false, true}) {
        for (std::size_t perUnit : {std::size_t(1), std::size_t(8)}) {
            const std::vector<Pose> poses = randomWalk(random, 7);
            const Polyscrew motion(poses, cyclic, perUnit);
            for (std::size_t k = 0; k < motion.spanCount(); ++k) {
                const Screw screw(poses[k], poses[(k + 1) % poses.size()]);
                for (double t : {0.1, 0.25, 0.5, 0.9}) {
                    const double u = (double(k) + t) / double(perUnit);
                    const Pose got = motion.at(u);
                    const Pose expected = screw.at(t);
                    GYRE_CHECK(poseDistance(got, expected) < 1e-12,
                               QStringLiteral("%1, span %2, t %3: %4, expected %5").arg(cyclic ? "cyclic" : "open").arg(k).arg(str(t), str(got), str(expected)));
                }
            }
        }
    }
}

void TestPolyscrew::openEndsAreClamped()
{
    Random random(202);
    const std::vector<Pose> poses = randomWalk(random, 5);
    const Polyscrew motion(poses, false, 2);
    for (double u : {-10.0, -0.5, -1e-9}) {
        QVERIFY2(poseDistance(motion.at(u), poses.front()) < 1e-12, qPrintable(QStringLiteral("u %1: %2").arg(str(u), str(motion.at(u)))));
    }
    for (double u : {motion.duration(), motion.duration() + 1e-9, motion.duration() + 3.0}) {
        QVERIFY2(poseDistance(motion.at(u), poses.back()) < 1e-12, qPrintable(QStringLiteral("u %1: %2").arg(str(u), str(motion.at(u)))));
    }
}

void TestPolyscrew::cyclesWrap()
{
    Random random(203);
    const std::vector<Pose> poses = randomWalk(random, 6);
    for (std::size_t perUnit : {std::size_t(1), std::size_t(4)}) {
        const Polyscrew motion(poses, true, perUnit);
        const double duration = motion.duration();
        QVERIFY2(poseDistance(motion.at(duration), poses.front()) < 1e-12, qPrintable(str(motion.at(duration))));
        // The closing span runs from the last pose back to the first.
        const Screw closing(poses.back(), poses.front());
        const Pose inClosing = motion.at(duration - 0.3 / double(perUnit));
        QVERIFY2(poseDistance(inClosing, closing.at(0.7)) < 1e-12, qPrintable(str(inClosing)));
        for (double u : {0.0, 0.13, 1.0, 2.71}) {
            for (double turns : {-2.0, -1.0, 1.0, 3.0}) {
                const Pose a = motion.at(u);
                const Pose b = motion.at(u + turns * duration);
                GYRE_CHECK(poseDistance(a, b) < 1e-10, QStringLiteral("%1 per unit, u %2 and %3 turns later: %4 vs %5").arg(perUnit).arg(str(u), str(turns), str(a), str(b)));
            }
        }
    }
}

void TestPolyscrew::singlePose()
{
    Random random(204);
    const Pose p = random.pose(3.0);
    const Polyscrew motion({p}, false, 1);
    QCOMPARE(motion.spanCount(), std::size_t(0));
    QCOMPARE(motion.duration(), 0.0);
    for (double u : {-1.0, 0.0, 0.5, 2.0})
        QVERIFY(poseDistance(motion.at(u), p) < 1e-15);
}

void TestPolyscrew::invalidArgumentsThrow()
{
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, Polyscrew({}, false, 1));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, Polyscrew({}, true, 1));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, Polyscrew({Pose{}, Pose{}}, false, 0));
}

void TestPolyscrew::trajectoryOfUniformRotation()
{
    // Poses turned about one fixed axis by equal steps: every screw is the same rotation, so a body
    // point moves on a circle at constant angular speed. Central differences of a circular motion
    // give a velocity exactly tangent (⟂ radius) and an acceleration exactly centripetal, with
    // magnitudes ω·r·sinc(ωh) and ω²·r·sinc²(ωh/2).
    Random random(205);
    for (std::size_t perUnit : {std::size_t(1), std::size_t(2)}) {
        const int n = 64;
        const Eigen::Vector3d centre = random.vector(4.0);
        const Eigen::Vector3d axis = random.unitVector();
        const Pose start = random.pose(4.0);
        std::vector<Pose> poses;
        for (int k = 0; k < n; ++k)
            poses.push_back(helicalMotion(start, centre, axis, 2.0 * kPi * k / n, 0.0));
        const Polyscrew motion(poses, true, perUnit);
        const Eigen::Vector3d local(0.8, -1.1, 0.4);
        const std::size_t samples = 256;
        const std::vector<TrajectorySample> trajectory = sampleTrajectory(motion, local, samples);
        QCOMPARE(trajectory.size(), samples);
        const double omega = 2.0 * kPi / motion.duration(); // radians per unit of u
        const double h = motion.duration() / double(samples);
        const Eigen::Vector3d first = start.apply(local);
        const Eigen::Vector3d firstRel = first - centre;
        const double axial = firstRel.dot(axis);
        const double radius = (firstRel - axial * axis).norm();
        QVERIFY(radius > 0.5);
        const double speed = omega * radius * std::sin(omega * h) / (omega * h);
        const double sinc = std::sin(omega * h / 2.0) / (omega * h / 2.0);
        const double centripetal = omega * omega * radius * sinc * sinc;
        for (std::size_t k = 0; k < samples; ++k) {
            const TrajectorySample& s = trajectory[k];
            const QString label = QStringLiteral("%1 per unit, sample %2").arg(perUnit).arg(k);
            GYRE_CHECK(std::abs(s.u - double(k) * h) < 1e-12, QStringLiteral("%1: u %2, expected %3").arg(label, str(s.u), str(double(k) * h)));
            const Eigen::Vector3d expectedPosition = motion.at(s.u).apply(local);
            GYRE_CHECK((s.position - expectedPosition).norm() < 1e-12, QStringLiteral("%1: position %2, expected %3").arg(label, str(s.position), str(expectedPosition)));
            const Eigen::Vector3d rel = s.position - centre;
            const Eigen::Vector3d radial = rel - rel.dot(axis) * axis;
            GYRE_CHECK(std::abs(radial.norm() - radius) < 1e-10 && std::abs(rel.dot(axis) - axial) < 1e-10, QStringLiteral("%1: off the circle").arg(label));
            const Eigen::Vector3d tangent = axis.cross(radial).normalized();
            GYRE_CHECK(std::abs(s.velocity.dot(radial)) < 1e-8 * radius * speed && std::abs(s.velocity.dot(axis)) < 1e-8 * speed,
                       QStringLiteral("%1: velocity %2 not ⟂ radius %3").arg(label, str(s.velocity), str(radial)));
            GYRE_CHECK((s.velocity - speed * tangent).norm() < 1e-7 * speed,
                       QStringLiteral("%1: velocity %2, expected %3").arg(label, str(s.velocity), str(Eigen::Vector3d(speed * tangent))));
            GYRE_CHECK(std::abs(s.velocity.norm() - omega * radius) < 1e-3 * omega * radius, QStringLiteral("%1: |v| ≠ ωr").arg(label));
            const Eigen::Vector3d expectedAcceleration = -centripetal * radial.normalized();
            GYRE_CHECK((s.acceleration - expectedAcceleration).norm() < 1e-6 * centripetal,
                       QStringLiteral("%1: acceleration %2, expected %3").arg(label, str(s.acceleration), str(expectedAcceleration)));
            GYRE_CHECK(std::abs(s.acceleration.norm() - omega * omega * radius) < 1e-3 * omega * omega * radius, QStringLiteral("%1: |a| ≠ ω²r").arg(label));
        }
    }
}

void TestPolyscrew::trajectoryOfUniformTranslation()
{
    Random random(206);
    for (std::size_t perUnit : {std::size_t(1), std::size_t(4)}) {
        const Eigen::Vector3d step = random.vector(2.0);
        const Eigen::Quaterniond orientation = random.rotation();
        std::vector<Pose> poses;
        for (int k = 0; k < 10; ++k)
            poses.push_back({orientation, Eigen::Vector3d(1.0, 2.0, 3.0) + double(k) * step});
        const Polyscrew motion(poses, false, perUnit);
        const Eigen::Vector3d local(0.3, 0.2, -0.9);
        const std::size_t samples = 37;
        const std::vector<TrajectorySample> trajectory = sampleTrajectory(motion, local, samples);
        QCOMPARE(trajectory.size(), samples);
        const Eigen::Vector3d velocity = step * double(perUnit); // per unit of u
        for (std::size_t k = 0; k < samples; ++k) {
            const TrajectorySample& s = trajectory[k];
            const double u = motion.duration() * double(k) / double(samples - 1);
            const QString label = QStringLiteral("%1 per unit, sample %2").arg(perUnit).arg(k);
            GYRE_CHECK(std::abs(s.u - u) < 1e-12, QStringLiteral("%1: u %2, expected %3").arg(label, str(s.u), str(u)));
            const Eigen::Vector3d expected = orientation * local + Eigen::Vector3d(1.0, 2.0, 3.0) + u * velocity;
            GYRE_CHECK((s.position - expected).norm() < 1e-12, QStringLiteral("%1: position %2, expected %3").arg(label, str(s.position), str(expected)));
            GYRE_CHECK((s.velocity - velocity).norm() < 1e-9 * velocity.norm(), QStringLiteral("%1: velocity %2, expected %3").arg(label, str(s.velocity), str(velocity)));
            GYRE_CHECK(s.acceleration.norm() < 1e-8 * velocity.norm() * double(perUnit), QStringLiteral("%1: acceleration %2").arg(label, str(s.acceleration)));
        }
    }
}

QTEST_APPLESS_MAIN(TestPolyscrew)
#include "tst_polyscrew.moc"
