// Quaternion algebra (quaternion_math.h): exp and log and their differentials against their
// definitions and central finite differences, short-arc slerp and nlerp against constructions
// written in the test (including tiny arcs, arcs near 180° and extrapolation), and the world-frame
// angular velocity ω = 2q′q⁻¹.

#include "core/quaternion_math.h"

#include "core_test_support.h"

#include <QObject>
#include <QTest>

#include <vector>

using namespace gyre;
using namespace gyre::test;

namespace {

// quatExp by definition, via the rotation vector 2v.
Eigen::Quaterniond expOf(const Eigen::Vector3d& v) { return quaternionOfRotationVector(2.0 * v); }

// Slerp by construction: q0 times the short-arc rotation q0⁻¹q1 scaled by t.
Eigen::Quaterniond slerpOf(const Eigen::Quaterniond& q0, const Eigen::Quaterniond& q1, double t)
{
    return q0 * quaternionOfRotationVector(t * rotationVectorOf(q0.conjugate() * q1));
}

Eigen::Quaterniond normalizedCopy(const Eigen::Quaterniond& q)
{
    Eigen::Quaterniond r;
    r.coeffs() = q.coeffs() / q.coeffs().norm();
    return r;
}

double coeffDistance(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) { return (a.coeffs() - b.coeffs()).norm(); }

} // namespace

class TestQuaternionMath : public QObject {
    Q_OBJECT

private slots:
    void expMatchesDefinition();
    void logInvertsExp();
    void expDerivativeMatchesFiniteDifferences();
    void logDerivativeMatchesFiniteDifferences();
    void shortArcAndAlignment();
    void slerpEndpointsAndShortArc();
    void slerpMatchesConstruction();
    void slerpTinyArcs();
    void slerpNearHalfTurn();
    void slerpExtrapolates();
    void slerpWithinRoundingOfTheLogExpFormula();
    void nlerp();
    void angularVelocityIsWorldFrame();
    void angularVelocityMatchesFiniteDifferences();
    void normalizedDerivativeMatchesFiniteDifferences();
};

void TestQuaternionMath::expMatchesDefinition()
{
    Random random(41);
    std::vector<Eigen::Vector3d> vs = {Eigen::Vector3d::Zero()};
    for (int i = 0; i < 200; ++i)
        vs.push_back(random.unitVector() * random.uniform(0.0, 5.0));
    for (double m : {1e-14, 1e-10, 1e-7, 1e-4, kPi / 2.0, kPi})
        vs.push_back(random.unitVector() * m);
    for (const Eigen::Vector3d& v : vs) {
        const Eigen::Quaterniond q = quatExp(v);
        const Eigen::Quaterniond expected = expOf(v);
        GYRE_CHECK(coeffDistance(q, expected) < 1e-15 * 4, QStringLiteral("v %1: %2, expected %3").arg(str(v), str(q), str(expected)));
        GYRE_CHECK((q.vec() - expected.vec()).norm() <= 1e-15 * 2 * expected.vec().norm(),
                   QStringLiteral("v %1: vector part %2 not accurate relative to %3").arg(str(v), str(q.vec()), str(expected.vec())));
    }
    QVERIFY(coeffDistance(quatExp(Eigen::Vector3d::Zero()), Eigen::Quaterniond::Identity()) == 0.0);
}

void TestQuaternionMath::logInvertsExp()
{
    Random random(42);
    for (int i = 0; i < 300; ++i) {
        const double m = i < 20 ? std::pow(10.0, -random.uniform(4.0, 14.0)) : random.uniform(0.0, kPi / 2.0 - 1e-6);
        const Eigen::Vector3d v = random.unitVector() * m;
        const Eigen::Vector3d back = quatLog(quatExp(v));
        GYRE_CHECK((back - v).norm() <= 1e-14 * v.norm(), QStringLiteral("v %1 -> %2").arg(str(v), str(back)));
    }
    for (int i = 0; i < 300; ++i) {
        const Eigen::Quaterniond q = random.rotation();
        const Eigen::Vector3d v = quatLog(q);
        GYRE_CHECK(v.norm() <= kPi / 2.0 * (1.0 + 1e-15), QStringLiteral("q %1: |log| = %2").arg(str(q), str(v.norm())));
        GYRE_CHECK(distanceUpToSign(quatExp(v), q) < 1e-15 * 4, QStringLiteral("q %1: exp(log q) = %2").arg(str(q), str(quatExp(v))));
        GYRE_CHECK((2.0 * v - rotationVectorOf(q)).norm() < 1e-14, QStringLiteral("q %1: 2·log %2, rotation vector %3").arg(str(q), str(Eigen::Vector3d(2.0 * v)), str(rotationVectorOf(q))));
        GYRE_CHECK((quatLog(negated(q)) - v).norm() < 1e-14, QStringLiteral("q %1: log(−q) = %2 ≠ log(q) = %3").arg(str(q), str(quatLog(negated(q))), str(v)));
    }
    QVERIFY(quatLog(Eigen::Quaterniond::Identity()).norm() == 0.0);
    QVERIFY(quatLog(negated(Eigen::Quaterniond::Identity())).norm() == 0.0);
}

void TestQuaternionMath::expDerivativeMatchesFiniteDifferences()
{
    Random random(43);
    std::vector<Eigen::Vector3d> vs = {Eigen::Vector3d::Zero()};
    for (double m : {1e-12, 1e-8, 1e-5, 1e-3})
        vs.push_back(random.unitVector() * m);
    for (int i = 0; i < 100; ++i)
        vs.push_back(random.unitVector() * random.uniform(0.0, 3.0));
    const double h = 1e-6;
    for (const Eigen::Vector3d& v : vs) {
        const Eigen::Vector3d dv = random.vector(2.0);
        const Eigen::Quaterniond analytic = quatExpDerivative(v, dv);
        Eigen::Quaterniond fd;
        fd.coeffs() = (expOf(v + h * dv).coeffs() - expOf(v - h * dv).coeffs()) / (2.0 * h);
        GYRE_CHECK(coeffDistance(analytic, fd) < 1e-8, QStringLiteral("v %1, dv %2: %3, finite differences %4").arg(str(v), str(dv), str(analytic), str(fd)));
        // The derivative is tangent to the unit sphere at exp(v).
        GYRE_CHECK(std::abs(analytic.coeffs().dot(quatExp(v).coeffs())) < 1e-14, QStringLiteral("v %1: not tangent").arg(str(v)));
    }
    // At zero the differential is exactly dv ↦ (0, dv).
    const Eigen::Vector3d dv(0.3, -0.5, 1.25);
    QVERIFY(coeffDistance(quatExpDerivative(Eigen::Vector3d::Zero(), dv), pure(dv)) < 1e-16);
}

void TestQuaternionMath::logDerivativeMatchesFiniteDifferences()
{
    Random random(44);
    const double h = 1e-6;
    std::vector<Eigen::Quaterniond> qs = {Eigen::Quaterniond::Identity()};
    for (double angle : {1e-12, 1e-8, 1e-4})
        qs.push_back(axisAngleQuaternion(random.unitVector(), angle));
    for (int i = 0; i < 100; ++i)
        qs.push_back(random.rotationWithAngle(0.0, kPi - 0.2));
    for (const Eigen::Quaterniond& q : qs) {
        QVERIFY(q.w() > 0.0);
        const Eigen::Vector3d u = random.vector(2.0);
        // A curve on the unit sphere through q: q·exp(εu), with derivative q·(0, u) at ε = 0.
        const Eigen::Quaterniond dq = q * pure(u);
        const Eigen::Vector3d analytic = quatLogDerivative(q, dq);
        const Eigen::Vector3d fd = (rotationVectorOf(q * expOf(h * u)) - rotationVectorOf(q * expOf(-h * u))) / (4.0 * h);
        GYRE_CHECK((analytic - fd).norm() < 1e-8, QStringLiteral("q %1, dq %2: %3, finite differences %4").arg(str(q), str(dq), str(analytic), str(fd)));
        // The same on a curve moving in the world frame: exp(εu)·q.
        const Eigen::Quaterniond dqWorld = pure(u) * q;
        const Eigen::Vector3d analyticWorld = quatLogDerivative(q, dqWorld);
        const Eigen::Vector3d fdWorld = (rotationVectorOf(expOf(h * u) * q) - rotationVectorOf(expOf(-h * u) * q)) / (4.0 * h);
        GYRE_CHECK((analyticWorld - fdWorld).norm() < 1e-8, QStringLiteral("q %1, dq %2: %3, finite differences %4").arg(str(q), str(dqWorld), str(analyticWorld), str(fdWorld)));
    }
    // Chain rule: d log(exp(v + ε dv)) = dv.
    for (int i = 0; i < 100; ++i) {
        const Eigen::Vector3d v = random.unitVector() * random.uniform(0.0, kPi / 2.0 - 0.1);
        const Eigen::Vector3d dv = random.vector(2.0);
        const Eigen::Vector3d back = quatLogDerivative(quatExp(v), quatExpDerivative(v, dv));
        GYRE_CHECK((back - dv).norm() < 1e-12, QStringLiteral("v %1, dv %2: chain rule gives %3").arg(str(v), str(dv), str(back)));
    }
}

void TestQuaternionMath::shortArcAndAlignment()
{
    Random random(45);
    for (int i = 0; i < 200; ++i) {
        const Eigen::Quaterniond q = random.rotation();
        const Eigen::Quaterniond s = shortArc(q);
        GYRE_CHECK(s.w() >= 0.0 && distanceUpToSign(s, q) == 0.0 && std::abs(std::abs(s.coeffs().dot(q.coeffs())) - 1.0) < 1e-15,
                   QStringLiteral("shortArc(%1) = %2").arg(str(q), str(s)));
        const Eigen::Quaterniond from = random.rotation();
        const Eigen::Quaterniond a = alignedWith(q, from);
        GYRE_CHECK(a.coeffs().dot(from.coeffs()) >= 0.0 && distanceUpToSign(a, q) == 0.0,
                   QStringLiteral("alignedWith(%1, %2) = %3").arg(str(q), str(from), str(a)));
    }
}

void TestQuaternionMath::slerpEndpointsAndShortArc()
{
    Random random(46);
    for (int i = 0; i < 200; ++i) {
        const Eigen::Quaterniond q0 = random.rotation();
        const Eigen::Quaterniond q1 = random.rotation();
        GYRE_CHECK(coeffDistance(slerp(q0, q1, 0.0), q0) < 1e-15 * 4, QStringLiteral("slerp(%1, %2, 0) = %3").arg(str(q0), str(q1), str(slerp(q0, q1, 0.0))));
        GYRE_CHECK(coeffDistance(slerp(q0, q1, 1.0), sameHemisphere(q1, q0)) < 1e-14,
                   QStringLiteral("slerp(%1, %2, 1) = %3").arg(str(q0), str(q1), str(slerp(q0, q1, 1.0))));
        for (double t : {0.1, 0.5, 0.77}) {
            const Eigen::Quaterniond a = slerp(q0, q1, t);
            const Eigen::Quaterniond b = slerp(q0, negated(q1), t);
            GYRE_CHECK(distanceUpToSign(a, b) < 1e-14, QStringLiteral("t %1: slerp to q1 %2, to −q1 %3").arg(str(t), str(a), str(b)));
            // On the short arc the angles from q0 and to q1 add up to the angle between them (≤ π).
            const double total = angleBetween(q0, q1);
            GYRE_CHECK(std::abs(angleBetween(q0, a) - t * total) < 1e-13 && std::abs(angleBetween(a, q1) - (1.0 - t) * total) < 1e-13,
                       QStringLiteral("t %1: slerp(%2, %3) = %4 is not on the short arc").arg(str(t), str(q0), str(q1), str(a)));
        }
    }
}

void TestQuaternionMath::slerpMatchesConstruction()
{
    Random random(47);
    for (int i = 0; i < 300; ++i) {
        const Eigen::Quaterniond q0 = random.rotation();
        const Eigen::Quaterniond q1 = random.rotation();
        const double t = random.uniform(0.0, 1.0);
        const Eigen::Quaterniond got = slerp(q0, q1, t);
        const Eigen::Quaterniond expected = slerpOf(q0, q1, t);
        GYRE_CHECK(std::abs(got.norm() - 1.0) < 1e-15 * 4, QStringLiteral("not unit: %1").arg(str(got)));
        GYRE_CHECK(distanceUpToSign(got, expected) < 1e-14,
                   QStringLiteral("slerp(%1, %2, %3) = %4, expected %5").arg(str(q0), str(q1), str(t), str(got), str(expected)));
    }
}

void TestQuaternionMath::slerpTinyArcs()
{
    Random random(48);
    for (double angle : {1e-15, 1e-13, 1e-10, 1e-7, 1e-5}) {
        for (int i = 0; i < 20; ++i) {
            const Eigen::Vector3d axis = random.unitVector();
            // From the identity the arc is exactly known, and the result must have full relative accuracy.
            const Eigen::Quaterniond q1 = axisAngleQuaternion(axis, angle);
            for (double t : {0.0, 0.25, 0.5, 1.0, 1.5}) {
                const Eigen::Quaterniond s = slerp(Eigen::Quaterniond::Identity(), q1, t);
                const Eigen::Vector3d expected = std::sin(0.5 * t * angle) * axis;
                GYRE_CHECK(s.w() > 0.0 && (s.vec() - expected).norm() <= 1e-13 * expected.norm() + 2e-16,
                           QStringLiteral("arc %1, t %2: slerp(1, %3) = %4, expected vector part %5").arg(str(angle), str(t), str(q1), str(s), str(expected)));
            }
            // From a random q0 the arc q0⁻¹q1 is only known to rounding, so check relative to it.
            const Eigen::Quaterniond q0 = random.rotation();
            const Eigen::Quaterniond q1b = q0 * q1;
            const Eigen::Vector3d arc = rotationVectorOf(q0.conjugate() * q1b);
            for (double t : {0.25, 0.5, 0.75, 2.0}) {
                const Eigen::Quaterniond s = slerp(q0, q1b, t);
                const Eigen::Vector3d reached = rotationVectorOf(q0.conjugate() * s);
                GYRE_CHECK((reached - t * arc).norm() <= 1e-3 * t * arc.norm() + 1e-15,
                           QStringLiteral("arc %1, t %2: reached %3, expected %4").arg(str(angle), str(t), str(reached), str(Eigen::Vector3d(t * arc))));
                GYRE_CHECK(distanceUpToSign(s, slerpOf(q0, q1b, t)) < 1e-15 * 4, QStringLiteral("arc %1, t %2").arg(str(angle), str(t)));
            }
        }
    }
    // Identical and opposite-sign identical keys.
    const Eigen::Quaterniond q = random.rotation();
    for (double t : {0.0, 0.3, 1.0, 2.0}) {
        QVERIFY(distanceUpToSign(slerp(q, q, t), q) < 1e-15 * 4);
        QVERIFY(distanceUpToSign(slerp(q, negated(q), t), q) < 1e-15 * 4);
    }
}

void TestQuaternionMath::slerpNearHalfTurn()
{
    Random random(49);
    for (double delta : {1e-3, 1e-6, 1e-8, 1e-10}) {
        for (int i = 0; i < 20; ++i) {
            const Eigen::Quaterniond q0 = random.rotation();
            const Eigen::Vector3d axis = random.unitVector();
            const Eigen::Quaterniond q1 = q0 * axisAngleQuaternion(axis, kPi - delta);
            for (const Eigen::Quaterniond& target : {q1, negated(q1)}) {
                for (double t : {0.0, 0.1, 0.5, 0.9, 1.0}) {
                    const Eigen::Quaterniond s = slerp(q0, target, t);
                    const Eigen::Quaterniond expected = q0 * axisAngleQuaternion(axis, t * (kPi - delta));
                    GYRE_CHECK(distanceUpToSign(s, expected) < 1e-13,
                               QStringLiteral("δ %1, t %2: slerp(%3, %4) = %5, expected %6").arg(str(delta), str(t), str(q0), str(target), str(s), str(expected)));
                }
            }
        }
    }
    // Exactly 180°: either arc will do, but the result is unit and a fraction t of the way.
    for (int i = 0; i < 20; ++i) {
        const Eigen::Quaterniond q0 = random.rotation();
        const Eigen::Quaterniond q1 = q0 * Eigen::Quaterniond(0.0, 0.0, 0.6, 0.8);
        for (double t : {0.2, 0.5, 0.8}) {
            const Eigen::Quaterniond s = slerp(q0, q1, t);
            GYRE_CHECK(std::abs(s.norm() - 1.0) < 1e-14 && std::abs(angleBetween(q0, s) - t * kPi) < 1e-12 &&
                           std::abs(angleBetween(s, q1) - (1.0 - t) * kPi) < 1e-12,
                       QStringLiteral("half turn, t %1: %2").arg(str(t), str(s)));
        }
    }
}

void TestQuaternionMath::slerpExtrapolates()
{
    Random random(50);
    for (int i = 0; i < 100; ++i) {
        const Eigen::Quaterniond q0 = random.rotation();
        const Eigen::Quaterniond q1 = q0 * random.rotationWithAngle(0.0, 3.0);
        for (double t : {-3.0, -0.5, 1.7, 2.5, 6.0}) {
            const Eigen::Quaterniond got = slerp(q0, q1, t);
            const Eigen::Quaterniond expected = slerpOf(q0, q1, t);
            GYRE_CHECK(distanceUpToSign(got, expected) < 1e-13,
                       QStringLiteral("t %1: slerp(%2, %3) = %4, expected %5").arg(str(t), str(q0), str(q1), str(got), str(expected)));
        }
    }
}

// slerp computes θ and sin tθ, cos tθ with the core's fast trigonometry and no quaternion product;
// the reference is the log-exp formula with the standard library's atan2, sin and cos (slerpOf),
// normalised, as slerp was written before. Over random pairs and the edges: near-identical and
// near-opposite quaternions (tiny arcs either way), arcs near a half turn, identical and negated keys,
// keys off the unit sphere (slerp normalises), and t from −1 to 2.
void TestQuaternionMath::slerpWithinRoundingOfTheLogExpFormula()
{
    constexpr double kBound = 2e-15; // on each coefficient, about 9 units of 2⁻⁵³
    Random random(52);
    double worst = 0.0;
    for (int i = 0; i < 20000; ++i) {
        const Eigen::Quaterniond q0 = random.rotation();
        const double tiny = std::pow(10.0, random.uniform(-16.0, 0.0));
        // Near a half turn the short arc is decided by the sign of a w of about (π − angle)/2, which
        // rounding would decide alone below 1e-12.
        const double nearHalfTurn = kPi - std::pow(10.0, random.uniform(-12.0, 0.0));
        Eigen::Quaterniond q1;
        switch (i % 5) {
        case 0: q1 = random.rotation(); break;
        case 1: q1 = q0 * random.rotationWithAngle(tiny, tiny); break;
        case 2: q1 = negated(q0 * random.rotationWithAngle(tiny, tiny)); break;
        case 3: q1 = q0 * random.rotationWithAngle(nearHalfTurn, nearHalfTurn); break;
        default: q1 = i % 2 == 0 ? q0 : negated(q0); break;
        }
        const double t = random.uniform(-1.0, 2.0);
        const Eigen::Quaterniond expected = normalizedCopy(slerpOf(q0, sameHemisphere(q1, q0), t));
        const bool offSphere = i % 7 == 6;
        const Eigen::Quaterniond got = offSphere ? slerp(scaled(q0, 3.0), scaled(q1, 0.25), t) : slerp(q0, q1, t);
        const double error = (got.coeffs() - expected.coeffs()).cwiseAbs().maxCoeff();
        worst = std::max(worst, error);
        GYRE_CHECK(error <= kBound, QStringLiteral("slerp(%1, %2, %3)%4 = %5, expected %6 (off by %7)")
                                        .arg(str(q0), str(q1), str(t), offSphere ? QStringLiteral(" off the sphere") : QString(),
                                             str(got), str(expected), str(error)));
    }
    qInfo("worst coefficient difference from the log-exp formula: %.3g", worst);
}

void TestQuaternionMath::nlerp()
{
    Random random(51);
    for (int i = 0; i < 200; ++i) {
        const Eigen::Quaterniond q0 = random.rotation();
        const Eigen::Quaterniond q1 = q0 * random.rotationWithAngle(0.0, kPi - 1e-3);
        const Eigen::Quaterniond q1Given = (i % 2) ? negated(q1) : q1;
        for (double t : {0.0, 0.2, 0.5, 0.9, 1.0}) {
            const Eigen::Quaterniond got = gyre::nlerp(q0, q1Given, t);
            const Eigen::Quaterniond expected = normalizedCopy(combination(1.0 - t, q0, t, sameHemisphere(q1Given, q0)));
            GYRE_CHECK(distanceUpToSign(got, expected) < 1e-14 && std::abs(got.norm() - 1.0) < 1e-15 * 4,
                       QStringLiteral("nlerp(%1, %2, %3) = %4, expected %5").arg(str(q0), str(q1Given), str(t), str(got), str(expected)));
            // It stays on the great circle of the slerp: the rotation from q0 turns about the same axis.
            const Eigen::Vector3d part = rotationVectorOf(q0.conjugate() * got);
            const Eigen::Vector3d whole = rotationVectorOf(q0.conjugate() * q1);
            GYRE_CHECK(part.cross(whole).norm() < 1e-12 && part.dot(whole) >= -1e-15,
                       QStringLiteral("t %1: nlerp leaves the great circle (%2 vs %3)").arg(str(t), str(part), str(whole)));
        }
        const Eigen::Quaterniond middle = gyre::nlerp(q0, q1Given, 0.5);
        GYRE_CHECK(distanceUpToSign(middle, slerpOf(q0, q1, 0.5)) < 1e-14, QStringLiteral("nlerp midpoint %1 is not the slerp midpoint").arg(str(middle)));
    }
}

void TestQuaternionMath::angularVelocityIsWorldFrame()
{
    Random random(52);
    for (int i = 0; i < 100; ++i) {
        const Eigen::Quaterniond q0 = random.rotation();
        const Eigen::Vector3d omega = random.vector(3.0);
        const double t = random.uniform(-2.0, 2.0);
        // Constant world-frame ω: q(t) = exp(tω/2)·q0, q′ = (0, ω/2)·q.
        const Eigen::Quaterniond qWorld = quaternionOfRotationVector(t * omega) * q0;
        const Eigen::Quaterniond dqWorld = pure(0.5 * omega) * qWorld;
        GYRE_CHECK((angularVelocity(qWorld, dqWorld) - omega).norm() < 1e-13,
                   QStringLiteral("world ω %1: got %2").arg(str(omega), str(angularVelocity(qWorld, dqWorld))));
        // Constant body-frame ω_b: q(t) = q0·exp(tω_b/2), q′ = q·(0, ω_b/2); the world ω is q·ω_b.
        const Eigen::Quaterniond qBody = q0 * quaternionOfRotationVector(t * omega);
        const Eigen::Quaterniond dqBody = qBody * pure(0.5 * omega);
        const Eigen::Vector3d expected = qBody * omega;
        GYRE_CHECK((angularVelocity(qBody, dqBody) - expected).norm() < 1e-13,
                   QStringLiteral("body ω %1: got %2, expected %3").arg(str(omega), str(angularVelocity(qBody, dqBody)), str(expected)));
        // Scaling the curve by a changing factor s(t) does not change ω: (s·q)′ = s′·q + s·q′.
        const double s = random.uniform(0.2, 3.0);
        const double ds = random.uniform(-2.0, 2.0);
        const Eigen::Quaterniond scaledQ = combination(s, qWorld, 0.0, qWorld);
        const Eigen::Quaterniond scaledDq = combination(ds, qWorld, s, dqWorld);
        GYRE_CHECK((angularVelocity(scaledQ, scaledDq) - omega).norm() < 1e-13,
                   QStringLiteral("scaled by %1 (rate %2): got %3, expected %4").arg(str(s), str(ds), str(angularVelocity(scaledQ, scaledDq)), str(omega)));
    }
}

void TestQuaternionMath::angularVelocityMatchesFiniteDifferences()
{
    // A non-unit polynomial curve p(t); ω of p/|p| from central differences of the unit curve.
    Random random(53);
    const double h = 1e-6;
    for (int i = 0; i < 100; ++i) {
        const Eigen::Quaterniond a = random.rotation();
        const Eigen::Quaterniond b = combination(random.uniform(-1, 1), random.rotation(), 0.0, a);
        const Eigen::Quaterniond c = combination(random.uniform(-1, 1), random.rotation(), 0.0, a);
        auto p = [&](double t) { return combination(1.0, combination(1.0, a, t, b), t * t, c); };
        auto dp = [&](double t) { return combination(1.0, b, 2.0 * t, c); };
        const double t = random.uniform(-0.3, 0.3);
        if (p(t).coeffs().norm() < 0.2)
            continue;
        const Eigen::Quaterniond unit = normalizedCopy(p(t));
        Eigen::Quaterniond fd;
        fd.coeffs() = (normalizedCopy(p(t + h)).coeffs() - normalizedCopy(p(t - h)).coeffs()) / (2.0 * h);
        const Eigen::Vector3d expected = 2.0 * (fd * unit.conjugate()).vec();
        const Eigen::Vector3d got = angularVelocity(p(t), dp(t));
        GYRE_CHECK((got - expected).norm() < 1e-7 * (1.0 + expected.norm()),
                   QStringLiteral("case %1: ω %2, finite differences %3").arg(i).arg(str(got), str(expected)));
    }
}

void TestQuaternionMath::normalizedDerivativeMatchesFiniteDifferences()
{
    Random random(54);
    const double h = 1e-6;
    for (int i = 0; i < 100; ++i) {
        Eigen::Quaterniond p = random.rotation();
        p.coeffs() *= random.uniform(0.3, 3.0);
        Eigen::Quaterniond dp = random.rotation();
        dp.coeffs() *= random.uniform(0.0, 2.0);
        const Eigen::Quaterniond got = normalizedDerivative(p, dp);
        Eigen::Quaterniond fd;
        fd.coeffs() = (normalizedCopy(combination(1.0, p, h, dp)).coeffs() - normalizedCopy(combination(1.0, p, -h, dp)).coeffs()) / (2.0 * h);
        GYRE_CHECK(coeffDistance(got, fd) < 1e-8 * (1.0 + fd.coeffs().norm()),
                   QStringLiteral("p %1, dp %2: %3, finite differences %4").arg(str(p), str(dp), str(got), str(fd)));
    }
}

QTEST_APPLESS_MAIN(TestQuaternionMath)
#include "tst_quaternion_math.moc"
