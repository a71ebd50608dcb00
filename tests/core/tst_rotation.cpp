// Rotation representations (rotation.h): quaternion ↔ matrix ↔ axis-angle ↔ rotation vector, checked
// against Rodrigues' formula and a rotation-vector construction written in the test, on random
// rotations and on the edge cases (identity, tiny angles, exactly and nearly 180°); and the
// projection of near-rotations onto SO(3).

#include "core/rotation.h"

#include "core_test_support.h"

#include <QObject>
#include <QTest>

#include <limits>
#include <vector>

using namespace gyre;
using namespace gyre::test;

namespace {

// Rotations every conversion must handle: random ones plus the edge cases, each also negated.
std::vector<Eigen::Quaterniond> conversionCases()
{
    Random random(11);
    std::vector<Eigen::Quaterniond> cases;
    cases.push_back(Eigen::Quaterniond::Identity());
    for (int i = 0; i < 300; ++i)
        cases.push_back(random.rotation());
    const double angles[] = {1e-15, 1e-12, 1e-9, 1e-7, 1e-4, 0.5, kPi / 2.0, kPi - 1e-3, kPi - 1e-6,
                             kPi - 1e-9, kPi};
    for (double angle : angles) {
        for (int i = 0; i < 4; ++i)
            cases.push_back(axisAngleQuaternion(random.unitVector(), angle));
        cases.push_back(axisAngleQuaternion(Eigen::Vector3d::UnitX(), angle));
        cases.push_back(axisAngleQuaternion(Eigen::Vector3d::UnitZ(), angle));
    }
    const std::size_t count = cases.size();
    for (std::size_t i = 0; i < count; ++i)
        cases.push_back(negated(cases[i]));
    return cases;
}

} // namespace

class TestRotation : public QObject {
    Q_OBJECT

private slots:
    void axisAngleOfIdentity();
    void axisAngleRoundTrip();
    void axisAngleAcceptsNonUnitAxis();
    void rotationVectorRoundTrip();
    void rotationVectorMatchesIndependentConstruction();
    void rotationVectorExpMatchesRodrigues();
    void tinyRotationVectorsAreExact();
    void halfTurns();
    void matrixRoundTrip();
    void nearestRotationKeepsRotations();
    void nearestRotationIsThePolarFactor();
    void nearestRotationFlipsTheSmallestSingularValue();
    void nearestRotationIsNearest();
    void rotationMatrixErrorMeasuresOrthogonality();
    void rotationMatrixErrorRejectsReflectionsAndSingularMatrices();
};

void TestRotation::axisAngleOfIdentity()
{
    const AxisAngle aa = axisAngleFromQuaternion(Eigen::Quaterniond::Identity());
    QCOMPARE(aa.angle, 0.0);
    QVERIFY((aa.axis - Eigen::Vector3d::UnitX()).norm() == 0.0);
    QVERIFY(rotationVectorFromQuaternion(Eigen::Quaterniond::Identity()).norm() == 0.0);
    QVERIFY(rotationVectorFromQuaternion(negated(Eigen::Quaterniond::Identity())).norm() == 0.0);
    const Eigen::Quaterniond q = quaternionFromRotationVector(Eigen::Vector3d::Zero());
    QVERIFY(distanceUpToSign(q, Eigen::Quaterniond::Identity()) == 0.0);
    const Eigen::Quaterniond q0 = quaternionFromAxisAngle({Eigen::Vector3d::Zero(), 0.0});
    QVERIFY2(distanceUpToSign(q0, Eigen::Quaterniond::Identity()) == 0.0, qPrintable(str(q0)));
}

void TestRotation::axisAngleRoundTrip()
{
    for (const Eigen::Quaterniond& q : conversionCases()) {
        const AxisAngle aa = axisAngleFromQuaternion(q);
        GYRE_CHECK(aa.angle >= 0.0 && aa.angle <= kPi, QStringLiteral("q %1: angle %2").arg(str(q), str(aa.angle)));
        GYRE_CHECK(std::abs(aa.axis.norm() - 1.0) < 1e-14, QStringLiteral("q %1: axis %2").arg(str(q), str(aa.axis)));
        // The angle against 2·atan2(|v|, |w|), independently computed.
        const double expectedAngle = 2.0 * std::atan2(q.vec().norm(), std::abs(q.w()));
        GYRE_CHECK(std::abs(aa.angle - expectedAngle) <= 1e-14 * expectedAngle,
                   QStringLiteral("q %1: angle %2, expected %3").arg(str(q), str(aa.angle), str(expectedAngle)));
        const Eigen::Quaterniond back = quaternionFromAxisAngle(aa);
        GYRE_CHECK(distanceUpToSign(back, q) < 1e-15 * 4,
                   QStringLiteral("q %1 -> axis %2 angle %3 -> %4").arg(str(q), str(aa.axis), str(aa.angle), str(back)));
        GYRE_CHECK(std::abs(back.norm() - 1.0) < 1e-15 * 4, QStringLiteral("not unit: %1").arg(str(back)));
    }
}

void TestRotation::axisAngleAcceptsNonUnitAxis()
{
    Random random(12);
    for (int i = 0; i < 100; ++i) {
        const Eigen::Vector3d axis = random.unitVector();
        const double angle = random.uniform(-2.0 * kPi, 2.0 * kPi);
        const double scale = random.uniform(1e-3, 1e3);
        const Eigen::Quaterniond q = quaternionFromAxisAngle({scale * axis, angle});
        const Eigen::Quaterniond expected = axisAngleQuaternion(axis, angle);
        GYRE_CHECK(distanceUpToSign(q, expected) < 1e-14,
                   QStringLiteral("axis %1 angle %2: %3, expected %4").arg(str(scale * axis), str(angle), str(q), str(expected)));
    }
}

void TestRotation::rotationVectorRoundTrip()
{
    for (const Eigen::Quaterniond& q : conversionCases()) {
        const Eigen::Vector3d r = rotationVectorFromQuaternion(q);
        GYRE_CHECK(r.norm() <= kPi * (1.0 + 1e-15), QStringLiteral("q %1: |r| = %2 > π").arg(str(q), str(r.norm())));
        const Eigen::Quaterniond back = quaternionFromRotationVector(r);
        GYRE_CHECK(distanceUpToSign(back, q) < 4e-15, QStringLiteral("q %1 -> r %2 -> %3").arg(str(q), str(r), str(back)));
        // The rotation vector is also axis·angle of the axis-angle form.
        const AxisAngle aa = axisAngleFromQuaternion(q);
        if (aa.angle < kPi - 1e-6) {
            GYRE_CHECK((aa.angle * aa.axis - r).norm() <= 1e-15 * 4 * std::max(1.0, r.norm()) + 1e-300,
                       QStringLiteral("q %1: r %2, axis·angle %3").arg(str(q), str(r), str(Eigen::Vector3d(aa.angle * aa.axis))));
        }
    }
    // Random rotation vectors inside the ball of radius π come back unchanged.
    Random random(13);
    for (int i = 0; i < 300; ++i) {
        const Eigen::Vector3d r = random.unitVector() * random.uniform(0.0, kPi - 1e-6);
        const Eigen::Vector3d back = rotationVectorFromQuaternion(quaternionFromRotationVector(r));
        GYRE_CHECK((back - r).norm() < 1e-14, QStringLiteral("r %1 -> %2").arg(str(r), str(back)));
    }
}

void TestRotation::rotationVectorMatchesIndependentConstruction()
{
    for (const Eigen::Quaterniond& q : conversionCases()) {
        const Eigen::Vector3d r = rotationVectorFromQuaternion(q);
        const Eigen::Vector3d expected = rotationVectorOf(q);
        if (q.w() == 0.0) {
            // Exactly 180°: r and −r are both right.
            GYRE_CHECK(std::min((r - expected).norm(), (r + expected).norm()) < 1e-14,
                       QStringLiteral("q %1: r %2, expected ±%3").arg(str(q), str(r), str(expected)));
            continue;
        }
        // Relative accuracy, so that tiny rotation vectors are checked too.
        GYRE_CHECK((r - expected).norm() <= 1e-14 * expected.norm() + 1e-300,
                   QStringLiteral("q %1: r %2, expected %3").arg(str(q), str(r), str(expected)));
    }
}

void TestRotation::rotationVectorExpMatchesRodrigues()
{
    Random random(14);
    std::vector<Eigen::Vector3d> vectors;
    for (int i = 0; i < 300; ++i)
        vectors.push_back(random.unitVector() * random.uniform(0.0, 3.0 * kPi)); // beyond π too
    for (double angle : {0.0, 1e-12, 1e-7, 1e-4, kPi - 1e-9, kPi, kPi + 1e-9, 2.0 * kPi})
        vectors.push_back(random.unitVector() * angle);
    for (const Eigen::Vector3d& r : vectors) {
        const Eigen::Quaterniond q = quaternionFromRotationVector(r);
        GYRE_CHECK(std::abs(q.norm() - 1.0) < 4e-16 * 4, QStringLiteral("r %1: not unit %2").arg(str(r), str(q)));
        const Eigen::Matrix3d expected = rodrigues(r);
        const double error = (q.toRotationMatrix() - expected).cwiseAbs().maxCoeff();
        GYRE_CHECK(error < 1e-14, QStringLiteral("r %1: matrix differs from Rodrigues by %2").arg(str(r), str(error)));
        // The rotation actually turns vectors about r: r itself is fixed, and a perpendicular
        // vector turns by |r| (mod 2π) in the right-handed sense.
        GYRE_CHECK((q * r - r).norm() < 1e-14 * std::max(1.0, r.norm()),
                   QStringLiteral("r %1 is not fixed by its own rotation").arg(str(r)));
    }
}

void TestRotation::tinyRotationVectorsAreExact()
{
    Random random(15);
    for (double angle : {1e-100, 1e-15, 1e-12, 1e-9, 1e-7, 1e-5}) {
        for (int i = 0; i < 20; ++i) {
            const Eigen::Vector3d r = random.unitVector() * angle;
            const Eigen::Quaterniond q = quaternionFromRotationVector(r);
            // exp(r/2) = (1 − |r|²/8 + …, r/2 − …): the vector part must be r/2 to full relative accuracy.
            const Eigen::Vector3d expectedVec = 0.5 * r * (1.0 - angle * angle / 24.0);
            GYRE_CHECK((q.vec() - expectedVec).norm() <= 1e-15 * 2 * expectedVec.norm(),
                       QStringLiteral("r %1: q %2").arg(str(r), str(q)));
            GYRE_CHECK(std::abs(q.w() - (1.0 - angle * angle / 8.0)) <= 2e-16, QStringLiteral("r %1: q %2").arg(str(r), str(q)));
            const Eigen::Vector3d back = rotationVectorFromQuaternion(q);
            GYRE_CHECK((back - r).norm() <= 1e-14 * angle,
                       QStringLiteral("r %1 -> q %2 -> %3 (relative error %4)").arg(str(r), str(q), str(back), str((back - r).norm() / angle)));
            const AxisAngle aa = axisAngleFromQuaternion(q);
            GYRE_CHECK(std::abs(aa.angle - angle) <= 1e-14 * angle && (aa.axis - r / angle).norm() < 1e-14,
                       QStringLiteral("r %1 -> axis %2 angle %3").arg(str(r), str(aa.axis), str(aa.angle)));
            // The same through the matrix (Eigen's Shepperd conversion).
            const Eigen::Matrix3d m = q.toRotationMatrix();
            GYRE_CHECK((m - rodrigues(r)).cwiseAbs().maxCoeff() < 1e-15 * 4, QStringLiteral("r %1: matrix").arg(str(r)));
        }
    }
}

void TestRotation::halfTurns()
{
    Random random(16);
    for (int i = 0; i < 50; ++i) {
        const Eigen::Vector3d axis = random.unitVector();
        // Exactly 180°: (0, n); the result is ±π·n.
        const Eigen::Quaterniond half(0.0, axis.x(), axis.y(), axis.z());
        for (const Eigen::Quaterniond& q : {half, negated(half)}) {
            const Eigen::Vector3d r = rotationVectorFromQuaternion(q);
            GYRE_CHECK(std::abs(r.norm() - kPi) < 1e-14 && std::min((r - kPi * axis).norm(), (r + kPi * axis).norm()) < 1e-14,
                       QStringLiteral("q %1: r %2").arg(str(q), str(r)));
            const AxisAngle aa = axisAngleFromQuaternion(q);
            GYRE_CHECK(std::abs(aa.angle - kPi) < 1e-15 && std::abs(std::abs(aa.axis.dot(axis)) - 1.0) < 1e-14,
                       QStringLiteral("q %1: axis %2 angle %3").arg(str(q), str(aa.axis), str(aa.angle)));
        }
        // Nearly 180°, from either sign of q: the short arc is π − δ about n, never π + δ.
        for (double delta : {1e-3, 1e-6, 1e-8, 1e-10, 1e-12}) {
            const Eigen::Quaterniond q = axisAngleQuaternion(axis, kPi - delta);
            for (const Eigen::Quaterniond& p : {q, negated(q)}) {
                const Eigen::Vector3d r = rotationVectorFromQuaternion(p);
                const Eigen::Vector3d expected = (kPi - delta) * axis;
                GYRE_CHECK((r - expected).norm() < 1e-14,
                           QStringLiteral("δ %1, q %2: r %3, expected %4").arg(str(delta), str(p), str(r), str(expected)));
            }
            // Just past 180° the short arc flips to the other side: π − δ about −n.
            const Eigen::Quaterniond past = axisAngleQuaternion(axis, kPi + delta);
            const Eigen::Vector3d r = rotationVectorFromQuaternion(past);
            GYRE_CHECK((r + (kPi - delta) * axis).norm() < 1e-14,
                       QStringLiteral("δ %1: r %2, expected %3").arg(str(delta), str(r), str(Eigen::Vector3d(-(kPi - delta) * axis))));
        }
    }
}

void TestRotation::matrixRoundTrip()
{
    for (const Eigen::Quaterniond& q : conversionCases()) {
        const Eigen::Matrix3d m = q.toRotationMatrix();
        // The matrix of q is the Rodrigues matrix of its rotation vector, computed independently.
        const Eigen::Matrix3d expected = rodrigues(rotationVectorOf(q));
        GYRE_CHECK((m - expected).cwiseAbs().maxCoeff() < 1e-14, QStringLiteral("q %1: matrix differs from Rodrigues").arg(str(q)));
        GYRE_CHECK(rotationMatrixError(m) < 1e-15 * 4, QStringLiteral("q %1: rotationMatrixError %2").arg(str(q), str(rotationMatrixError(m))));
        const Eigen::Quaterniond back(m);
        GYRE_CHECK(distanceUpToSign(back, q) < 1e-15 * 4, QStringLiteral("q %1 -> matrix -> %2").arg(str(q), str(back)));
        // Matrix -> quaternion -> rotation vector -> matrix.
        const Eigen::Matrix3d again = quaternionFromRotationVector(rotationVectorFromQuaternion(back)).toRotationMatrix();
        GYRE_CHECK((again - m).cwiseAbs().maxCoeff() < 1e-14, QStringLiteral("q %1: matrix round trip").arg(str(q)));
        // Matrix acts on column vectors like the quaternion rotates them.
        const Eigen::Vector3d v(0.3, -1.2, 2.5);
        GYRE_CHECK((m * v - q * v).norm() < 1e-14, QStringLiteral("q %1: R·v ≠ q·v").arg(str(q)));
    }
}

void TestRotation::nearestRotationKeepsRotations()
{
    for (const Eigen::Quaterniond& q : conversionCases()) {
        const Eigen::Matrix3d m = q.toRotationMatrix();
        const Eigen::Matrix3d n = nearestRotation(m);
        GYRE_CHECK((n - m).cwiseAbs().maxCoeff() < 1e-14, QStringLiteral("q %1: nearestRotation moved a rotation").arg(str(q)));
    }
}

void TestRotation::nearestRotationIsThePolarFactor()
{
    // m = R·S with S symmetric positive definite: the nearest rotation is R (polar decomposition).
    Random random(17);
    for (int i = 0; i < 200; ++i) {
        const Eigen::Matrix3d r = random.rotation().toRotationMatrix();
        const Eigen::Matrix3d u = random.rotation().toRotationMatrix();
        const double magnitude = i < 100 ? 1e-6 : 0.5; // rounding-sized and gross deviations
        const Eigen::Vector3d stretches(1.0 + random.uniform(-magnitude, magnitude), 1.0 + random.uniform(-magnitude, magnitude),
                                        1.0 + random.uniform(-magnitude, magnitude));
        const Eigen::Matrix3d s = u * stretches.asDiagonal() * u.transpose();
        const Eigen::Matrix3d m = (i % 3 == 0 ? 2.5 : 1.0) * r * s;
        const Eigen::Matrix3d n = nearestRotation(m);
        const double error = (n - r).cwiseAbs().maxCoeff();
        GYRE_CHECK(error < 1e-13, QStringLiteral("case %1: nearestRotation(R·S) differs from R by %2").arg(i).arg(str(error)));
        GYRE_CHECK(rotationMatrixError(n) < 1e-14, QStringLiteral("case %1: result is not a rotation").arg(i));
    }
}

void TestRotation::nearestRotationFlipsTheSmallestSingularValue()
{
    // m = R·W·diag(3, 2, −1)·Wᵀ (R, W rotations) has det < 0. Its SVD is U = R·W, Σ = diag(3, 2, 1),
    // V = W·diag(1, 1, −1), so U·Vᵀ is a reflection; flipping the sign for the smallest singular
    // value gives U·diag(1, 1, −1)·Vᵀ = R, the nearest rotation.
    Random random(18);
    for (int i = 0; i < 100; ++i) {
        const Eigen::Matrix3d r = random.rotation().toRotationMatrix();
        const Eigen::Matrix3d w = random.rotation().toRotationMatrix();
        const Eigen::Matrix3d m = r * w * Eigen::Vector3d(3.0, 2.0, -1.0).asDiagonal() * w.transpose();
        const Eigen::Matrix3d n = nearestRotation(m);
        GYRE_CHECK(std::abs(n.determinant() - 1.0) < 1e-13, QStringLiteral("case %1: det %2").arg(i).arg(str(n.determinant())));
        GYRE_CHECK((n - r).cwiseAbs().maxCoeff() < 1e-12, QStringLiteral("case %1: differs from R by %2").arg(i).arg(str((n - r).cwiseAbs().maxCoeff())));
    }
}

void TestRotation::nearestRotationIsNearest()
{
    // For arbitrary matrices: the result is a rotation, idempotent, and no sampled rotation nearby is
    // closer in the Frobenius norm.
    Random random(19);
    for (int i = 0; i < 60; ++i) {
        Eigen::Matrix3d m;
        for (int k = 0; k < 9; ++k)
            m(k / 3, k % 3) = random.uniform(-2.0, 2.0);
        const Eigen::Matrix3d n = nearestRotation(m);
        GYRE_CHECK(rotationMatrixError(n) < 1e-14, QStringLiteral("case %1: not a rotation").arg(i));
        GYRE_CHECK((nearestRotation(n) - n).cwiseAbs().maxCoeff() < 1e-14, QStringLiteral("case %1: not idempotent").arg(i));
        const double best = (m - n).norm();
        const Eigen::Quaterniond qn(n);
        for (int k = 0; k < 50; ++k) {
            const Eigen::Quaterniond nearby = qn * random.rotationWithAngle(1e-4, 0.3);
            const double other = (m - nearby.toRotationMatrix()).norm();
            GYRE_CHECK(other >= best - 1e-12, QStringLiteral("case %1: a rotation at distance %2 beats %3").arg(i).arg(str(other), str(best)));
        }
    }
}

void TestRotation::rotationMatrixErrorMeasuresOrthogonality()
{
    // For m = R·diag(a, b, c), mᵀm − I = diag(a² − 1, b² − 1, c² − 1).
    Random random(20);
    for (int i = 0; i < 100; ++i) {
        const Eigen::Matrix3d r = random.rotation().toRotationMatrix();
        const Eigen::Vector3d d(1.0 + random.uniform(-1e-3, 1e-3), 1.0 + random.uniform(-0.1, 0.1), random.uniform(0.2, 2.0));
        const Eigen::Matrix3d m = r * d.asDiagonal();
        const double expected = (d.cwiseProduct(d) - Eigen::Vector3d::Ones()).cwiseAbs().maxCoeff();
        const double error = rotationMatrixError(m);
        GYRE_CHECK(std::abs(error - expected) < 1e-13, QStringLiteral("case %1: %2, expected %3").arg(i).arg(str(error), str(expected)));
    }
    // A shear: m = I + ε·e₀e₁ᵀ, mᵀm − I has off-diagonal ε and diagonal ε².
    for (double eps : {1e-9, 1e-4, 0.1}) {
        Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
        m(0, 1) = eps;
        const double expected = std::max(eps, eps * eps);
        QVERIFY2(std::abs(rotationMatrixError(m) - expected) < 1e-15, qPrintable(str(rotationMatrixError(m))));
    }
}

void TestRotation::rotationMatrixErrorRejectsReflectionsAndSingularMatrices()
{
    constexpr double inf = std::numeric_limits<double>::infinity();
    Random random(21);
    const Eigen::Matrix3d r = random.rotation().toRotationMatrix();
    QCOMPARE(rotationMatrixError(-r), inf);
    QCOMPARE(rotationMatrixError(r * Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal()), inf);
    QCOMPARE(rotationMatrixError(Eigen::Matrix3d::Zero()), inf);
    Eigen::Matrix3d singular = r;
    singular.col(2).setZero(); // det = 0 exactly
    QCOMPARE(rotationMatrixError(singular), inf);
}

QTEST_APPLESS_MAIN(TestRotation)
#include "tst_rotation.moc"
