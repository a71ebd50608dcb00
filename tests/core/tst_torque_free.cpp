// Torque-free motion (torque_free.h) checked by physics: what it conserves (world angular momentum, its
// direction, kinetic energy), a fixed-step RK4 of Euler's equations written here, the closed form of the
// symmetric top against the integration, and the flip of a body spun about its intermediate axis.

#include "core/mass_properties.h"
#include "core/torque_free.h"

#include "core_test_support.h"
#include "rigid_body_test_support.h"

#include <QObject>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <stdexcept>

using namespace gyre;
using namespace gyre::test;

namespace {

// The reference: Euler's equations I·ω̇ = (I·ω)×ω for the body angular velocity and q̇ = ½·q⊗(0, ω_body),
// classical RK4 at a fixed step, the tensor used as given (no principal axes).
struct RigidState {
    Eigen::Vector4d q;  // w, x, y, z
    Eigen::Vector3d omegaBody;
};

Eigen::Vector4d qvec(const Eigen::Quaterniond& q) { return {q.w(), q.x(), q.y(), q.z()}; }
Eigen::Quaterniond quat(const Eigen::Vector4d& v) { return Eigen::Quaterniond(v[0], v[1], v[2], v[3]); }

RigidState derivative(const Eigen::Matrix3d& inertia, const RigidState& s)
{
    const Eigen::Vector3d domega = inertia.inverse() * (inertia * s.omegaBody).cross(s.omegaBody);
    const Eigen::Quaterniond dq = quat(s.q) * pure(s.omegaBody);
    return {0.5 * qvec(dq), domega};
}

RigidState advanced(const RigidState& s, const RigidState& d, double h)
{
    return {s.q + h * d.q, s.omegaBody + h * d.omegaBody};
}

RigidState rk4Step(const Eigen::Matrix3d& inertia, const RigidState& s, double h)
{
    const RigidState k1 = derivative(inertia, s);
    const RigidState k2 = derivative(inertia, advanced(s, k1, h / 2));
    const RigidState k3 = derivative(inertia, advanced(s, k2, h / 2));
    const RigidState k4 = derivative(inertia, advanced(s, k3, h));
    return {s.q + h / 6 * (k1.q + 2 * k2.q + 2 * k3.q + k4.q),
            s.omegaBody + h / 6 * (k1.omegaBody + 2 * k2.omegaBody + 2 * k3.omegaBody + k4.omegaBody)};
}

} // namespace

class TestTorqueFree : public QObject {
    Q_OBJECT

private slots:
    void refusesBadInertia();
    void conservesMomentumAndEnergy();
    void agreesWithFixedStepRk4();
    void angularVelocityIsTheOrientationsDerivative();
    void symmetricTopMatchesItsClosedForm();
    void intermediateAxisFlips();
    void startIsTheGivenState();
    void endOrientationIsTheMotionsEnd();
};

void TestTorqueFree::refusesBadInertia()
{
    const Eigen::Vector3d omega(1.0, 2.0, 3.0);
    for (const Eigen::Matrix3d& inertia : {inertiaTensor({1.0, 1.0, -1.0}), inertiaTensor({1.0, 1.0, 1.0, 2.0}),
                                           inertiaTensor({1.0, NAN, 1.0}), inertiaTensor({1.0, 1.0, 3.0})})
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 TorqueFreeMotion(inertia, Eigen::Quaterniond::Identity(), omega, 1.0));
}

void TestTorqueFree::conservesMomentumAndEnergy()
{
    Random random(11);
    for (int trial = 0; trial < 4; ++trial) {
        const Eigen::Matrix3d inertia = rotatedInertia({0.6, 0.8 + 0.15 * trial, 1.4}, random.rotation());
        const Eigen::Quaterniond start = random.rotation();
        const Eigen::Vector3d omega = random.vector(12.0);
        const double duration = 2.5;
        const TorqueFreeMotion motion(inertia, start, omega, duration);
        QVERIFY(!motion.closedForm());
        const Eigen::Vector3d l0 = momentumOf(inertia, start, omega);
        const double e0 = 0.5 * omega.dot(l0);
        const auto orientationAt = [&](double t) { return motion.orientation(t); };
        for (int i = 0; i <= 997; ++i) {
            const double t = std::clamp(duration * i / 997.0, 1e-6, duration - 1e-6);
            const Eigen::Quaterniond q = motion.orientation(t);
            const Eigen::Vector3d w = differencedAngularVelocity(orientationAt, t);
            const Eigen::Vector3d l = momentumOf(inertia, q, w);
            const double e = 0.5 * w.dot(l);
            GYRE_CHECK(std::abs(l.norm() - l0.norm()) < 1e-9 * l0.norm(), QStringLiteral("|L| at %1").arg(t));
            GYRE_CHECK(l.normalized().cross(l0.normalized()).norm() < 1e-9, QStringLiteral("L's direction at %1").arg(t));
            GYRE_CHECK(std::abs(e - e0) < 1e-9 * e0, QStringLiteral("energy at %1: %2 vs %3").arg(t).arg(str(e), str(e0)));
        }
    }
}

void TestTorqueFree::agreesWithFixedStepRk4()
{
    Random random(23);
    const Eigen::Matrix3d inertia = rotatedInertia({0.7, 1.0, 1.6}, random.rotation());
    const Eigen::Quaterniond start = random.rotation();
    const Eigen::Vector3d omega = random.vector(8.0);
    const double duration = 2.0;
    const TorqueFreeMotion motion(inertia, start, omega, duration);
    const int steps = 40000;  // h = 5e-5 s: RK4's error ~ (h·|ω|)⁴ per unit time, far below the tolerance below
    const double h = duration / steps;
    RigidState state{qvec(start), start.conjugate() * omega};
    double worstAngle = 0.0, worstOmega = 0.0;
    for (int i = 1; i <= steps; ++i) {
        state = rk4Step(inertia, state, h);
        if (i % 400 != 0)
            continue;
        const Eigen::Quaterniond reference = quat(state.q).normalized();
        const Eigen::Vector3d referenceOmega = reference * state.omegaBody;
        worstAngle = std::max(worstAngle, angleBetween(reference, motion.orientation(i * h)));
        worstOmega = std::max(worstOmega, (referenceOmega - motion.angularVelocity(i * h)).norm() / omega.norm());
    }
    GYRE_CHECK(worstAngle < 1e-8, QStringLiteral("orientation differs from RK4 by %1 rad").arg(worstAngle));
    GYRE_CHECK(worstOmega < 1e-8, QStringLiteral("ω differs from RK4 by %1 relative").arg(worstOmega));
}

void TestTorqueFree::angularVelocityIsTheOrientationsDerivative()
{
    Random random(31);
    const Eigen::Matrix3d inertia = rotatedInertia({0.5, 0.9, 1.3}, random.rotation());
    const TorqueFreeMotion motion(inertia, random.rotation(), random.vector(6.0), 1.5);
    const double h = 1e-5;
    for (double t = 0.1; t < 1.4; t += 0.0731) {
        const Eigen::Quaterniond difference = motion.orientation(t + h) * motion.orientation(t - h).conjugate();
        const Eigen::Vector3d finite = rotationVectorOf(difference) / (2 * h);
        GYRE_CHECK((finite - motion.angularVelocity(t)).norm() < 1e-6 * motion.angularVelocity(t).norm(),
                   QStringLiteral("at %1: %2 vs %3").arg(t).arg(str(finite), str(motion.angularVelocity(t))));
    }
}

void TestTorqueFree::symmetricTopMatchesItsClosedForm()
{
    Random random(41);
    for (const Eigen::Vector3d& moments : {Eigen::Vector3d(1.0, 1.0, 1.9), Eigen::Vector3d(0.4, 1.2, 1.2)}) {
        const Eigen::Matrix3d inertia = rotatedInertia(moments, random.rotation());
        const Eigen::Quaterniond start = random.rotation();
        const Eigen::Vector3d omega = random.vector(9.0);
        const TorqueFreeMotion closed(inertia, start, omega, 3.0);
        const TorqueFreeMotion integrated(inertia, start, omega, 3.0, TorqueFreeMotion::Solver::Numerical);
        QVERIFY(closed.closedForm());
        QVERIFY(!integrated.closedForm());
        for (double t = 0.0; t <= 3.0; t += 0.0173) {
            GYRE_CHECK(angleBetween(closed.orientation(t), integrated.orientation(t)) < 1e-9,
                       QStringLiteral("at %1").arg(t));
            GYRE_CHECK((closed.angularVelocity(t) - integrated.angularVelocity(t)).norm() < 1e-9 * omega.norm(),
                       QStringLiteral("ω at %1").arg(t));
        }
    }
}

void TestTorqueFree::intermediateAxisFlips()
{
    // Moments 1 < 2 < 3 about x, y, z; a spin about y, the intermediate axis, with a small disturbance. The
    // body's y axis, which starts along L, turns to point against it and back (the Dzhanibekov effect).
    const Eigen::Matrix3d inertia = inertiaTensor({1.0, 2.0, 3.0});
    const Eigen::Vector3d omega(1e-3, 10.0, 1e-3);
    const TorqueFreeMotion motion(inertia, Eigen::Quaterniond::Identity(), omega, 6.0);
    const Eigen::Vector3d along = motion.angularMomentum().normalized();
    double least = 1.0, firstReversal = -1.0;
    for (double t = 0.0; t <= 6.0; t += 0.001) {
        const double cosine = (motion.orientation(t) * Eigen::Vector3d::UnitY()).dot(along);
        least = std::min(least, cosine);
        if (firstReversal < 0.0 && cosine < -0.99)
            firstReversal = t;
    }
    QVERIFY2(least < -0.99, qPrintable(QStringLiteral("the intermediate axis reached only %1 against L").arg(least)));
    QVERIFY(firstReversal > 0.1);
    // The flip is the body's: L stays where it was.
    const auto orientationAt = [&](double t) { return motion.orientation(t); };
    const Eigen::Vector3d end =
        momentumOf(inertia, motion.orientation(6.0 - 1e-6), differencedAngularVelocity(orientationAt, 6.0 - 1e-6));
    QVERIFY(end.normalized().cross(along).norm() < 1e-9);
}

void TestTorqueFree::startIsTheGivenState()
{
    Random random(53);
    const Eigen::Matrix3d inertia = rotatedInertia({0.7, 1.1, 1.6}, random.rotation());
    const Eigen::Quaterniond start = random.rotation();
    const Eigen::Vector3d omega = random.vector(5.0);
    const TorqueFreeMotion motion(inertia, start, omega, 1.0);
    QVERIFY(angleBetween(motion.orientation(0.0), start) < 1e-14);
    QVERIFY((motion.angularVelocity(0.0) - omega).norm() < 1e-12 * omega.norm());
    QVERIFY(std::abs(motion.kineticEnergy() - 0.5 * omega.dot(momentumOf(inertia, start, omega))) < 1e-12);
    QVERIFY(angleBetween(motion.orientation(-1.0), start) < 1e-14);
    QVERIFY(angleBetween(motion.orientation(2.0), motion.orientation(1.0)) == 0.0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, TorqueFreeMotion(inertia, start, omega, -1.0));
}

// endOrientation integrates as the constructor does and keeps no step between: its end is the motion's end to
// the bit, for an asymmetric body at the solver's and playback's tolerances, a symmetric one (its closed form)
// and no time at all; and both refuse a flight past the step budget.
void TestTorqueFree::endOrientationIsTheMotionsEnd()
{
    Random random(59);
    const Eigen::Quaterniond start = random.rotation();
    const Eigen::Vector3d omega = random.vector(6.0);
    const Eigen::Matrix3d asymmetric = rotatedInertia({0.7, 1.1, 1.6}, random.rotation());
    const Eigen::Matrix3d symmetric = rotatedInertia({0.8, 0.8, 1.3}, random.rotation());
    const auto same = [](const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) { return a.coeffs() == b.coeffs(); };
    for (const double tolerance : {1e-5, kTorqueFreeTolerance}) {
        const TorqueFreeMotion motion(asymmetric, start, omega, 1.3, TorqueFreeMotion::Solver::Automatic, tolerance);
        QVERIFY(motion.stepCount() > 2);
        QVERIFY(same(TorqueFreeMotion::endOrientation(asymmetric, start, omega, 1.3, tolerance), motion.orientation(1.3)));
    }
    QVERIFY(same(TorqueFreeMotion::endOrientation(symmetric, start, omega, 1.3), TorqueFreeMotion(symmetric, start, omega, 1.3).orientation(1.3)));
    QVERIFY(same(TorqueFreeMotion::endOrientation(asymmetric, start, omega, 0.0), TorqueFreeMotion(asymmetric, start, omega, 0.0).orientation(0.0)));
    // A spin of 10⁶ rad/s for a second needs millions of steps.
    const Eigen::Vector3d tooFast = 1e6 * omega.normalized();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, TorqueFreeMotion(asymmetric, start, tooFast, 1.0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, TorqueFreeMotion::endOrientation(asymmetric, start, tooFast, 1.0));
}

QTEST_APPLESS_MAIN(TestTorqueFree)
#include "tst_torque_free.moc"
