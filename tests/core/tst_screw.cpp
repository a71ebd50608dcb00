// The screw between two poses (screw.h) against the SE(3) geodesic La·exp(t·log(La⁻¹Lb)), with the
// exponential and logarithm written in the test with 3×3 and 4×4 matrices; on random pairs and on
// the hard cases (identical poses, pure translations, rotations tending to zero, rotations near
// 180°, large translations). Also the screw parameters against a screw built from a known axis,
// the invariances of the geodesic, and the trigonometry-free midpoint.

#include "core/screw.h"

#include "core_test_support.h"

#include <QObject>
#include <QTest>

#include <vector>

using namespace gyre;
using namespace gyre::test;

namespace {

const std::vector<double> kParameters = {-0.5, -0.1, 0.0, 0.25, 0.5, 0.75, 1.0, 1.2, 1.5};

// The pose `relative` applied in the body frame of `base`: base·relative.
Pose compose(const Pose& base, const Eigen::Quaterniond& rotation, const Eigen::Vector3d& translation)
{
    Pose p;
    p.orientation = base.orientation * rotation;
    p.position = base.orientation * translation + base.position;
    return p;
}

Eigen::Vector3d applyMatrix(const Eigen::Matrix4d& m, const Eigen::Vector3d& x)
{
    return m.topLeftCorner<3, 3>() * x + m.topRightCorner<3, 1>();
}

// Checks Screw(a, b).at(t) against the geodesic for the standard parameters and raises `largest` to
// the largest error (GYRE_CHECK inside: callers test QTest::currentTestFailed()).
void checkAgainstGeodesic(const Pose& a, const Pose& b, double tolerance, const QString& label, double* largest = nullptr)
{
    const Screw screw(a, b);
    const Eigen::Matrix4d ma = poseMatrix(a);
    const Vector6d xi = se3Log(inverseRigid(ma) * poseMatrix(b));
    for (double t : kParameters) {
        const Pose got = screw.at(t);
        const Eigen::Matrix4d expected = ma * se3Exp(t * xi); // the geodesic La·exp(t·log(La⁻¹Lb))
        const double error = poseMatrixDistance(got, expected);
        // screwInterpolate, the one-shot entry point the subdivision's ghost poses use.
        const Pose oneShot = screwInterpolate(a, t, b);
        const double oneShotError = poseMatrixDistance(oneShot, expected);
        if (largest)
            *largest = std::max({*largest, error, oneShotError});
        GYRE_CHECK(oneShotError < tolerance, QStringLiteral("%1, t %2: screwInterpolate error %3\n   from %4\n   to   %5\n   got  %6")
                                                 .arg(label, str(t), str(oneShotError), str(a), str(b), str(oneShot)));
        GYRE_CHECK(std::abs(got.orientation.norm() - 1.0) < 1e-14, QStringLiteral("%1, t %2: orientation not unit").arg(label, str(t)));
        GYRE_CHECK(error < tolerance, QStringLiteral("%1, t %2: error %3\n   from %4\n   to   %5\n   got  %6\n   expected position %7")
                                          .arg(label, str(t), str(error), str(a), str(b), str(got), str(Eigen::Vector3d(expected.topRightCorner<3, 1>()))));
    }
}

} // namespace

class TestScrew : public QObject {
    Q_OBJECT

private slots:
    void referenceExpLogAreInverse();
    void randomPairsFollowTheGeodesic();
    void endpoints();
    void identicalPoses();
    void pureTranslation();
    void rotationTendingToZero();
    void rotationNearHalfTurn();
    void largeTranslations();
    void parametersMatchTheRelativeMotion();
    void knownScrewIsRecovered();
    void axisPointsMoveAlongTheAxis();
    void reversedScrewIsTheSameMotion();
    void geodesicIsFrameIndependent();
    void midpoint();
};

void TestScrew::referenceExpLogAreInverse()
{
    // The test's own SE(3) exp and log, checked before they judge anything.
    Random random(80);
    for (int i = 0; i < 200; ++i) {
        Vector6d xi;
        xi.head<3>() = random.vector(5.0);
        xi.tail<3>() = random.unitVector() * (i < 20 ? std::pow(10.0, -random.uniform(3.0, 12.0)) : random.uniform(0.0, kPi - 1e-3));
        const Eigen::Matrix4d m = se3Exp(xi);
        const Vector6d back = se3Log(m);
        GYRE_CHECK((back - xi).norm() < 1e-12 * (1.0 + xi.norm()), QStringLiteral("case %1: log(exp ξ) ≠ ξ").arg(i));
        // exp(ξ) moves the origin along the helix: its rotation block is orthonormal.
        GYRE_CHECK((m.topLeftCorner<3, 3>().transpose() * m.topLeftCorner<3, 3>() - Eigen::Matrix3d::Identity()).norm() < 1e-14,
                   QStringLiteral("case %1: exp not rigid").arg(i));
        // exp(ξ/2)² = exp(ξ).
        const Eigen::Matrix4d half = se3Exp(0.5 * xi);
        GYRE_CHECK((half * half - m).norm() < 1e-12 * (1.0 + xi.norm()), QStringLiteral("case %1: exp(ξ/2)² ≠ exp(ξ)").arg(i));
    }
}

void TestScrew::randomPairsFollowTheGeodesic()
{
    Random random(81);
    double largest = 0.0;
    for (int i = 0; i < 200; ++i) {
        const Pose a = random.pose(5.0);
        const Pose b = random.pose(5.0);
        checkAgainstGeodesic(a, b, 1e-9, QStringLiteral("pair %1").arg(i), &largest);
        if (QTest::currentTestFailed())
            return;
        const Screw screw(a, b);
        for (int k = 0; k < 2; ++k) {
            const double t = random.uniform(-0.5, 1.5);
            const double error = poseMatrixDistance(screw.at(t), geodesic(a, b, t));
            GYRE_CHECK(error < 1e-9, QStringLiteral("pair %1, t %2: error %3").arg(i).arg(str(t), str(error)));
        }
    }
    qInfo("largest deviation from the geodesic over random pairs: %g", largest);
}

void TestScrew::endpoints()
{
    Random random(82);
    for (int i = 0; i < 300; ++i) {
        const Pose a = random.pose(10.0);
        const Pose b = random.pose(10.0);
        const Screw screw(a, b);
        const Pose start = screw.at(0.0);
        const Pose end = screw.at(1.0);
        GYRE_CHECK(distanceUpToSign(start.orientation, a.orientation) < 1e-14 && (start.position - a.position).norm() < 1e-13,
                   QStringLiteral("at(0) = %1, from %2").arg(str(start), str(a)));
        GYRE_CHECK(distanceUpToSign(end.orientation, b.orientation) < 1e-14 && (end.position - b.position).norm() < 1e-12,
                   QStringLiteral("at(1) = %1, to %2").arg(str(end), str(b)));
    }
}

void TestScrew::identicalPoses()
{
    Random random(83);
    for (int i = 0; i < 20; ++i) {
        const Pose a = random.pose(5.0);
        Pose same = a;
        if (i % 2)
            same.orientation = negated(a.orientation); // the same pose, written with −q
        const Screw screw(a, same);
        QCOMPARE(screw.angle(), 0.0);
        QCOMPARE(screw.slide(), 0.0);
        QVERIFY((screw.axisDirection() - Eigen::Vector3d::UnitX()).norm() == 0.0);
        QVERIFY(!screw.axisPoint().has_value());
        for (double t : kParameters) {
            const Pose p = screw.at(t);
            QVERIFY2(distanceUpToSign(p.orientation, a.orientation) < 1e-15 && (p.position - a.position).norm() < 1e-15,
                     qPrintable(QStringLiteral("t %1: %2, expected %3").arg(str(t), str(p), str(a))));
        }
    }
}

void TestScrew::pureTranslation()
{
    Random random(84);
    for (int i = 0; i < 50; ++i) {
        const Pose a = random.pose(5.0);
        const Eigen::Vector3d c = random.vector(3.0);
        Pose b = a;
        b.position += c;
        if (i % 2)
            b.orientation = negated(b.orientation);
        const Screw screw(a, b);
        GYRE_CHECK(screw.angle() == 0.0, QStringLiteral("angle %1").arg(str(screw.angle())));
        GYRE_CHECK((screw.axisDirection() - c.normalized()).norm() < 1e-15 * 4, QStringLiteral("axis %1, travel %2").arg(str(screw.axisDirection()), str(c)));
        GYRE_CHECK(std::abs(screw.slide() - c.norm()) < 1e-14, QStringLiteral("slide %1, |c| %2").arg(str(screw.slide()), str(c.norm())));
        GYRE_CHECK(!screw.axisPoint().has_value(), QStringLiteral("a pure translation has no axis point"));
        for (double t : kParameters) {
            const Pose p = screw.at(t);
            const Eigen::Vector3d expected = a.position + t * c;
            GYRE_CHECK(distanceUpToSign(p.orientation, a.orientation) < 1e-15 && (p.position - expected).norm() < 1e-14,
                       QStringLiteral("t %1: %2, expected position %3").arg(str(t), str(p), str(expected)));
        }
        checkAgainstGeodesic(a, b, 1e-12, QStringLiteral("translation %1").arg(i));
        if (QTest::currentTestFailed())
            return;
    }
}

void TestScrew::rotationTendingToZero()
{
    Random random(85);
    for (double angle : {1e-3, 1e-5, 1e-7, 1e-9, 1e-10, 1e-12, 1e-14}) {
        for (bool translated : {false, true}) {
            for (int i = 0; i < 10; ++i) {
                const Pose a = random.pose(5.0);
                const Eigen::Vector3d axis = random.unitVector();
                const Eigen::Vector3d translation = translated ? random.vector(3.0) : Eigen::Vector3d::Zero();
                const Pose b = compose(a, axisAngleQuaternion(axis, angle), translation);
                const QString label = QStringLiteral("angle %1%2 case %3").arg(str(angle), translated ? QStringLiteral(" with translation") : QString()).arg(i);
                checkAgainstGeodesic(a, b, 1e-9, label);
                if (QTest::currentTestFailed())
                    return;
                const Screw screw(a, b);
                GYRE_CHECK(std::abs(screw.angle() - angle) < 1e-14, QStringLiteral("%1: angle %2").arg(label, str(screw.angle())));
                GYRE_CHECK(std::abs(screw.axisDirection().norm() - 1.0) < 1e-14, QStringLiteral("%1: axis %2").arg(label, str(screw.axisDirection())));
                if (!translated)
                    GYRE_CHECK(std::abs(screw.slide()) < 1e-13, QStringLiteral("%1: slide %2 for a rotation about a.position").arg(label, str(screw.slide())));
            }
        }
    }
}

void TestScrew::rotationNearHalfTurn()
{
    Random random(86);
    for (double delta : {1e-3, 1e-5, 1e-6, 1e-7, 1e-8}) {
        for (bool translated : {false, true}) {
            for (int i = 0; i < 10; ++i) {
                const Pose a = random.pose(5.0);
                const Eigen::Vector3d axis = random.unitVector();
                const Eigen::Vector3d translation = translated ? random.vector(3.0) : Eigen::Vector3d::Zero();
                const Pose b = compose(a, axisAngleQuaternion(axis, kPi - delta), translation);
                const QString label = QStringLiteral("π − %1%2 case %3").arg(str(delta), translated ? QStringLiteral(" with translation") : QString()).arg(i);
                checkAgainstGeodesic(a, b, 1e-9, label);
                if (QTest::currentTestFailed())
                    return;
                const Screw screw(a, b);
                GYRE_CHECK(std::abs(screw.angle() - (kPi - delta)) < 1e-12, QStringLiteral("%1: angle %2").arg(label, str(screw.angle())));
                // The axis is a's body axis seen in the world, on the short-arc side.
                const Eigen::Vector3d worldAxis = a.orientation * axis;
                GYRE_CHECK((screw.axisDirection() - worldAxis).norm() < 1e-9, QStringLiteral("%1: axis %2, expected %3").arg(label, str(screw.axisDirection()), str(worldAxis)));
            }
        }
    }
}

void TestScrew::largeTranslations()
{
    Random random(87);
    for (double scale : {1e3, 1e6}) {
        for (int i = 0; i < 40; ++i) {
            Pose a = random.pose(scale);
            Pose b = random.pose(scale);
            if (i % 3 == 0)
                b.orientation = a.orientation * random.rotationWithAngle(1e-6, 1e-3);
            checkAgainstGeodesic(a, b, 1e-9, QStringLiteral("scale %1 case %2").arg(str(scale)).arg(i));
            if (QTest::currentTestFailed())
                return;
        }
    }
}

void TestScrew::parametersMatchTheRelativeMotion()
{
    // M = Lb·La⁻¹ = (R, c): S and the angle from the rotation vector of R, the slide d = c·S, and the
    // axis point P with P·S = 0 and M(P) = P + d·S.
    Random random(88);
    for (int i = 0; i < 300; ++i) {
        const Pose a = random.pose(5.0);
        const Pose b = random.pose(5.0);
        const Screw screw(a, b);
        const Eigen::Matrix4d m = poseMatrix(b) * inverseRigid(poseMatrix(a));
        const Eigen::Vector3d r = rotationVectorOf(b.orientation * a.orientation.conjugate());
        if (r.norm() < 1e-6 || r.norm() > kPi - 1e-6)
            continue;
        const Eigen::Vector3d s = r.normalized();
        const Eigen::Vector3d c = m.topRightCorner<3, 1>();
        const QString label = QStringLiteral("pair %1").arg(i);
        GYRE_CHECK(std::abs(screw.axisDirection().norm() - 1.0) < 1e-14, label);
        GYRE_CHECK(screw.angle() >= 0.0 && screw.angle() <= kPi, label);
        GYRE_CHECK(std::abs(screw.angle() - r.norm()) < 1e-13, QStringLiteral("%1: angle %2, expected %3").arg(label, str(screw.angle()), str(r.norm())));
        GYRE_CHECK((screw.axisDirection() - s).norm() < 1e-12, QStringLiteral("%1: axis %2, expected %3").arg(label, str(screw.axisDirection()), str(s)));
        GYRE_CHECK(std::abs(screw.slide() - c.dot(s)) < 1e-12, QStringLiteral("%1: slide %2, expected %3").arg(label, str(screw.slide()), str(c.dot(s))));
        const std::optional<Eigen::Vector3d> p = screw.axisPoint();
        GYRE_CHECK(p.has_value(), QStringLiteral("%1: no axis point").arg(label));
        GYRE_CHECK(std::abs(p->dot(s)) < 1e-12 * (1.0 + p->norm()), QStringLiteral("%1: axis point %2 is not the one nearest the origin").arg(label, str(*p)));
        const Eigen::Vector3d moved = applyMatrix(m, *p);
        GYRE_CHECK((moved - *p - screw.slide() * s).norm() < 1e-11 * (1.0 + p->norm()),
                   QStringLiteral("%1: M(P) − P = %2, expected %3").arg(label, str(Eigen::Vector3d(moved - *p)), str(Eigen::Vector3d(screw.slide() * s))));
    }
}

void TestScrew::knownScrewIsRecovered()
{
    Random random(89);
    for (int i = 0; i < 200; ++i) {
        const Pose a = random.pose(5.0);
        const Eigen::Vector3d centre = random.vector(5.0);
        const Eigen::Vector3d axis = random.unitVector();
        const double angle = random.uniform(1e-3, kPi - 1e-3);
        const double slide = random.uniform(-3.0, 3.0);
        const Pose b = helicalMotion(a, centre, axis, angle, slide);
        const Screw screw(a, b);
        const Eigen::Vector3d nearest = centre - centre.dot(axis) * axis;
        const QString label = QStringLiteral("case %1 (angle %2, slide %3)").arg(i).arg(str(angle), str(slide));
        GYRE_CHECK((screw.axisDirection() - axis).norm() < 1e-12 && std::abs(screw.angle() - angle) < 1e-12 && std::abs(screw.slide() - slide) < 1e-12,
                   QStringLiteral("%1: axis %2 angle %3 slide %4, expected axis %5").arg(label, str(screw.axisDirection()), str(screw.angle()), str(screw.slide()), str(axis)));
        GYRE_CHECK(screw.axisPoint().has_value() && (*screw.axisPoint() - nearest).norm() < 1e-9,
                   QStringLiteral("%1: axis point %2, expected %3").arg(label, screw.axisPoint() ? str(*screw.axisPoint()) : QStringLiteral("none"), str(nearest)));
        for (double t : kParameters) {
            const Pose expected = helicalMotion(a, centre, axis, t * angle, t * slide);
            GYRE_CHECK(poseDistance(screw.at(t), expected) < 1e-11, QStringLiteral("%1, t %2: %3, expected %4").arg(label, str(t), str(screw.at(t)), str(expected)));
        }
        // Turned the long way (angle > π), the same end pose gives the short-arc screw about −S.
        const double longAngle = 2.0 * kPi - angle;
        const Pose c = helicalMotion(a, centre, axis, longAngle, slide);
        const Screw shortScrew(a, c);
        GYRE_CHECK((shortScrew.axisDirection() + axis).norm() < 1e-12 && std::abs(shortScrew.angle() - angle) < 1e-12 &&
                       std::abs(shortScrew.slide() + slide) < 1e-12,
                   QStringLiteral("%1, long way: axis %2 angle %3 slide %4").arg(label, str(shortScrew.axisDirection()), str(shortScrew.angle()), str(shortScrew.slide())));
        GYRE_CHECK(shortScrew.axisPoint().has_value() && (*shortScrew.axisPoint() - nearest).norm() < 1e-9, QStringLiteral("%1, long way: axis point").arg(label));
    }
}

void TestScrew::axisPointsMoveAlongTheAxis()
{
    // The world motion at(t)·La⁻¹ moves every point of the axis by t·d along S and no other way.
    Random random(90);
    for (int i = 0; i < 100; ++i) {
        const Pose a = random.pose(5.0);
        const Pose b = random.pose(5.0);
        const Screw screw(a, b);
        if (!screw.axisPoint() || screw.angle() < 1e-3)
            continue;
        const Eigen::Vector3d p = *screw.axisPoint();
        const Eigen::Vector3d s = screw.axisDirection();
        for (double t : kParameters) {
            const Eigen::Matrix4d world = poseMatrix(screw.at(t)) * inverseRigid(poseMatrix(a));
            for (double lambda : {-4.0, 0.0, 2.5}) {
                const Eigen::Vector3d x = p + lambda * s;
                const Eigen::Vector3d moved = applyMatrix(world, x);
                const Eigen::Vector3d expected = x + t * screw.slide() * s;
                GYRE_CHECK((moved - expected).norm() < 1e-10 * (1.0 + p.norm()),
                           QStringLiteral("pair %1, t %2, λ %3: axis point moved to %4, expected %5").arg(i).arg(str(t), str(lambda), str(moved), str(expected)));
            }
            // A point off the axis keeps its distance from the axis.
            const Eigen::Vector3d off = p + 1.7 * s.unitOrthogonal();
            const Eigen::Vector3d movedOff = applyMatrix(world, off);
            const Eigen::Vector3d rel = movedOff - p;
            GYRE_CHECK(std::abs((rel - rel.dot(s) * s).norm() - 1.7) < 1e-10, QStringLiteral("pair %1, t %2: off-axis point changed its radius").arg(i).arg(str(t)));
        }
    }
}

void TestScrew::reversedScrewIsTheSameMotion()
{
    Random random(91);
    for (int i = 0; i < 300; ++i) {
        const Pose a = random.pose(5.0);
        const Pose b = compose(a, random.rotationWithAngle(0.0, kPi - 1e-3), random.vector(4.0));
        const double t = random.uniform(-0.5, 1.5);
        const Pose forward = screwInterpolate(a, t, b);
        const Pose backward = screwInterpolate(b, 1.0 - t, a);
        GYRE_CHECK(poseDistance(forward, backward) < 1e-11,
                   QStringLiteral("case %1, t %2: s(a, t, b) = %3, s(b, 1 − t, a) = %4").arg(i).arg(str(t), str(forward), str(backward)));
        GYRE_CHECK(poseDistance(forward, Screw(a, b).at(t)) < 1e-12, QStringLiteral("case %1: screwInterpolate differs from Screw::at").arg(i));
    }
}

void TestScrew::geodesicIsFrameIndependent()
{
    // s(G·La, t, G·Lb) = G·s(La, t, Lb) (world frame) and s(La·H, t, Lb·H) = s(La, t, Lb)·H (the
    // object's local frame): the screw does not depend on where the object's origin is placed.
    Random random(92);
    for (int i = 0; i < 200; ++i) {
        const Pose a = random.pose(5.0);
        const Pose b = compose(a, random.rotationWithAngle(0.0, kPi - 1e-2), random.vector(4.0));
        const Pose g = random.pose(5.0);
        const Pose hh = random.pose(5.0);
        const double t = random.uniform(-0.5, 1.5);
        const Eigen::Matrix4d mg = poseMatrix(g);
        const Eigen::Matrix4d mh = poseMatrix(hh);
        const Eigen::Matrix4d base = poseMatrix(Screw(a, b).at(t));
        auto pose = [](const Eigen::Matrix4d& m) {
            Pose p;
            p.orientation = Eigen::Quaterniond(Eigen::Matrix3d(m.topLeftCorner<3, 3>()));
            p.position = m.topRightCorner<3, 1>();
            return p;
        };
        const Pose left = Screw(pose(mg * poseMatrix(a)), pose(mg * poseMatrix(b))).at(t);
        GYRE_CHECK(poseMatrixDistance(left, mg * base) < 1e-10, QStringLiteral("case %1: not left-invariant").arg(i));
        const Pose right = Screw(pose(poseMatrix(a) * mh), pose(poseMatrix(b) * mh)).at(t);
        GYRE_CHECK(poseMatrixDistance(right, base * mh) < 1e-10, QStringLiteral("case %1: depends on the local frame").arg(i));
    }
}

void TestScrew::midpoint()
{
    Random random(93);
    std::vector<std::pair<Pose, Pose>> pairs;
    for (int i = 0; i < 200; ++i)
        pairs.emplace_back(random.pose(5.0), random.pose(5.0));
    for (double angle : {0.0, 1e-12, 1e-8, 1e-4, kPi - 1e-4, kPi - 1e-8}) {
        for (int i = 0; i < 5; ++i) {
            const Pose a = random.pose(5.0);
            pairs.emplace_back(a, compose(a, axisAngleQuaternion(random.unitVector(), angle), i % 2 ? random.vector(3.0) : Eigen::Vector3d::Zero()));
        }
    }
    const Pose same = random.pose(5.0);
    pairs.emplace_back(same, same);
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const auto& [a, b] = pairs[i];
        const Pose mid = Screw::midpoint(a, b);
        const Pose half = Screw(a, b).at(0.5);
        GYRE_CHECK(std::abs(mid.orientation.norm() - 1.0) < 1e-14, QStringLiteral("pair %1: midpoint orientation not unit").arg(i));
        GYRE_CHECK(poseDistance(mid, half) < 1e-12, QStringLiteral("pair %1: midpoint %2, at(0.5) %3").arg(i).arg(str(mid), str(half)));
        GYRE_CHECK(poseMatrixDistance(mid, geodesic(a, b, 0.5)) < 1e-9, QStringLiteral("pair %1: midpoint off the geodesic").arg(i));
    }
}

QTEST_APPLESS_MAIN(TestScrew)
#include "tst_screw.moc"
