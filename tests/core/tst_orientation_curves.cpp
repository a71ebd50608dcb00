// Orientation curves (orientation_curves.h) through keys at non-uniform times: every curve passes
// through its keys, stays unit, and reports a derivative and a world angular velocity that agree
// with central finite differences of its own values. Each curve is also compared with its
// definition built in the test: slerp and nlerp per segment, Shoemake's squad from its quadrangle
// points, the Hermite spline of the sketch-editing paper from the Hermite basis and its derivative
// estimates, and linear interpolation of Euler angles.

#include "core/orientation_curves.h"

#include "core_test_support.h"

#include <QObject>
#include <QTest>

#include <memory>
#include <stdexcept>
#include <vector>

using namespace gyre;
using namespace gyre::test;

namespace {

const std::vector<double> kTimes = {0.0, 0.4, 1.3, 1.6, 2.9, 3.2};

Eigen::Quaterniond normalizedCopy(const Eigen::Quaterniond& q)
{
    Eigen::Quaterniond r;
    r.coeffs() = q.coeffs() / q.coeffs().norm();
    return r;
}

double coeffDistance(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) { return (a.coeffs() - b.coeffs()).norm(); }

// Keys at the given times, each turned from the one before by an angle in [minStep, maxStep];
// every other key is handed over negated, to exercise the sign alignment.
std::vector<OrientationKey> randomKeys(Random& random, const std::vector<double>& times, double minStep, double maxStep)
{
    std::vector<OrientationKey> keys;
    Eigen::Quaterniond q = random.rotation();
    for (std::size_t i = 0; i < times.size(); ++i) {
        keys.push_back({times[i], i % 2 == 1 ? negated(q) : q});
        q = q * random.rotationWithAngle(minStep, maxStep);
    }
    return keys;
}

// The keys made sign-consistent, each on the hemisphere of the one before.
std::vector<Eigen::Quaterniond> alignedKeys(const std::vector<OrientationKey>& keys)
{
    std::vector<Eigen::Quaterniond> aligned;
    for (const OrientationKey& key : keys)
        aligned.push_back(aligned.empty() ? key.rotation : sameHemisphere(key.rotation, aligned.back()));
    return aligned;
}

Eigen::Quaterniond slerpOf(const Eigen::Quaterniond& q0, const Eigen::Quaterniond& q1, double t)
{
    return q0 * quaternionOfRotationVector(t * rotationVectorOf(q0.conjugate() * q1));
}

// Quaternion log and exp (half-angle): log q = rotation vector / 2.
Eigen::Vector3d logOf(const Eigen::Quaterniond& q) { return 0.5 * rotationVectorOf(q); }
Eigen::Quaterniond expOf(const Eigen::Vector3d& v) { return quaternionOfRotationVector(2.0 * v); }

// A rotation from Euler angles, composed of elementary quaternions.
Eigen::Quaterniond eulerQuaternion(const Eigen::Vector3d& e, const EulerConvention& c)
{
    const Eigen::Quaterniond q1 = axisAngleQuaternion(Eigen::Vector3d::Unit(c.axes[0]), e[0]);
    const Eigen::Quaterniond q2 = axisAngleQuaternion(Eigen::Vector3d::Unit(c.axes[1]), e[1]);
    const Eigen::Quaterniond q3 = axisAngleQuaternion(Eigen::Vector3d::Unit(c.axes[2]), e[2]);
    return c.frame == AngleFrame::Intrinsic ? q1 * q2 * q3 : q3 * q2 * q1;
}

// The cubic Hermite interpolant in R⁴ on [t0, t1] with values p0, p1 and time derivatives m0, m1,
// and its first two time derivatives.
struct Cubic {
    Eigen::Vector4d value, first, second;
};

Cubic hermite(double t0, double t1, const Eigen::Vector4d& p0, const Eigen::Vector4d& m0, const Eigen::Vector4d& p1,
              const Eigen::Vector4d& m1, double t)
{
    const double d = t1 - t0;
    const double u = (t - t0) / d;
    const double u2 = u * u;
    const double u3 = u2 * u;
    Cubic c;
    c.value = (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * d * m0 + (-2 * u3 + 3 * u2) * p1 + (u3 - u2) * d * m1;
    c.first = ((6 * u2 - 6 * u) * p0 + (3 * u2 - 4 * u + 1) * d * m0 + (-6 * u2 + 6 * u) * p1 + (3 * u2 - 2 * u) * d * m1) / d;
    c.second = ((12 * u - 6) * p0 + (6 * u - 4) * d * m0 + (-12 * u + 6) * p1 + (6 * u - 2) * d * m1) / (d * d);
    return c;
}

Eigen::Quaterniond fromCoeffs(const Eigen::Vector4d& c)
{
    Eigen::Quaterniond q;
    q.coeffs() = c;
    return q;
}

// The checks every orientation curve must pass. Uses GYRE_CHECK: callers test
// QTest::currentTestFailed() afterwards.
void checkCurve(const OrientationCurve& curve, const std::vector<OrientationKey>& keys, const QString& label)
{
    GYRE_CHECK(curve.keys().size() == keys.size(), label);
    GYRE_CHECK(curve.startTime() == keys.front().time && curve.endTime() == keys.back().time, label);

    // The stored keys are the given rotations, sign-consistent.
    for (std::size_t i = 0; i < keys.size(); ++i) {
        GYRE_CHECK(curve.keys()[i].time == keys[i].time, label);
        GYRE_CHECK(distanceUpToSign(curve.keys()[i].rotation, keys[i].rotation) < 1e-15,
                   QStringLiteral("%1: stored key %2 is %3, given %4").arg(label).arg(i).arg(str(curve.keys()[i].rotation), str(keys[i].rotation)));
        if (i > 0)
            GYRE_CHECK(curve.keys()[i].rotation.coeffs().dot(curve.keys()[i - 1].rotation.coeffs()) >= 0.0,
                       QStringLiteral("%1: stored keys %2 and %3 are not sign-consistent").arg(label).arg(i - 1).arg(i));
    }

    // Through the keys.
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const OrientationSample s = curve.sample(keys[i].time);
        GYRE_CHECK(distanceUpToSign(s.value, keys[i].rotation) < 1e-12,
                   QStringLiteral("%1: at key %2 (t = %3) value %4, key %5").arg(label).arg(i).arg(str(keys[i].time), str(s.value), str(keys[i].rotation)));
    }

    // Unit values, derivatives and angular velocities against central differences, inside segments.
    const double h = 1e-6;
    for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
        const double t0 = keys[i].time;
        const double d = keys[i + 1].time - t0;
        for (double u : {0.03, 0.2, 0.37, 0.5, 0.71, 0.97}) {
            const double t = t0 + u * d;
            const OrientationSample s = curve.sample(t);
            const QString at = QStringLiteral("%1, t = %2").arg(label, str(t));
            GYRE_CHECK(std::abs(s.value.norm() - 1.0) < 1e-14, QStringLiteral("%1: value %2 not unit").arg(at, str(s.value)));
            const Eigen::Quaterniond plus = sameHemisphere(curve.sample(t + h).value, s.value);
            const Eigen::Quaterniond minus = sameHemisphere(curve.sample(t - h).value, s.value);
            Eigen::Quaterniond fd;
            fd.coeffs() = (plus.coeffs() - minus.coeffs()) / (2.0 * h);
            GYRE_CHECK(coeffDistance(s.derivative, fd) < 1e-6 * (1.0 + fd.coeffs().norm()),
                       QStringLiteral("%1: derivative %2, finite differences %3").arg(at, str(s.derivative), str(fd)));
            GYRE_CHECK(std::abs(s.derivative.coeffs().dot(s.value.coeffs())) < 1e-12 * (1.0 + s.derivative.coeffs().norm()),
                       QStringLiteral("%1: derivative %2 not tangent to the unit sphere at %3").arg(at, str(s.derivative), str(s.value)));
            const Eigen::Vector3d omega = 2.0 * (fd * s.value.conjugate()).vec();
            GYRE_CHECK((s.angularVelocity - omega).norm() < 1e-6 * (1.0 + omega.norm()),
                       QStringLiteral("%1: angular velocity %2, from finite differences %3").arg(at, str(s.angularVelocity), str(omega)));
        }
        // Continuous across the key at the end of the segment.
        if (i + 2 < keys.size()) {
            const double tk = keys[i + 1].time;
            const Eigen::Quaterniond left = curve.sample(tk - 1e-10).value;
            const Eigen::Quaterniond right = curve.sample(tk + 1e-10).value;
            GYRE_CHECK(distanceUpToSign(left, right) < 1e-8, QStringLiteral("%1: jumps at key %2").arg(label).arg(i + 1));
        }
    }

    // Outside the span: the end orientation, held still.
    for (double t : {keys.front().time - 1.0, keys.front().time - 1e-9}) {
        const OrientationSample s = curve.sample(t);
        GYRE_CHECK(distanceUpToSign(s.value, keys.front().rotation) < 1e-12 && s.derivative.coeffs().norm() == 0.0 &&
                       s.angularVelocity.norm() == 0.0,
                   QStringLiteral("%1: before the start (t = %2) value %3, derivative %4").arg(label, str(t), str(s.value), str(s.derivative)));
    }
    for (double t : {keys.back().time + 1e-9, keys.back().time + 2.5}) {
        const OrientationSample s = curve.sample(t);
        GYRE_CHECK(distanceUpToSign(s.value, keys.back().rotation) < 1e-12 && s.derivative.coeffs().norm() == 0.0 &&
                       s.angularVelocity.norm() == 0.0,
                   QStringLiteral("%1: after the end (t = %2) value %3, derivative %4").arg(label, str(t), str(s.value), str(s.derivative)));
    }
}

// Keys for an Euler curve: a path of angles with modest steps and the middle angle away from lock.
std::vector<OrientationKey> eulerKeys(Random& random, const EulerConvention& c, const std::vector<double>& times)
{
    std::vector<OrientationKey> keys;
    Eigen::Vector3d e(random.uniform(-kPi, kPi), c.isProperEuler() ? 1.2 : 0.1, random.uniform(-kPi, kPi));
    for (std::size_t i = 0; i < times.size(); ++i) {
        keys.push_back({times[i], i % 2 == 1 ? negated(eulerQuaternion(e, c)) : eulerQuaternion(e, c)});
        e += Eigen::Vector3d(random.uniform(-1.0, 1.0), random.uniform(-0.4, 0.4), random.uniform(-1.0, 1.0));
        e[1] = c.isProperEuler() ? std::clamp(e[1], 0.5, kPi - 0.5) : std::clamp(e[1], -1.0, 1.0);
    }
    return keys;
}

} // namespace

class TestOrientationCurves : public QObject {
    Q_OBJECT

private slots:
    void everyCurve_data();
    void everyCurve();
    void singleKeyHoldsStill_data();
    void singleKeyHoldsStill();
    void invalidKeysThrow();
    void methodNames();
    void slerpCurveIsSlerpPerSegment();
    void nlerpCurveIsNlerpPerSegment();
    void squadMatchesDefinition();
    void squadIsC1AtInteriorKeys();
    void hermiteThroughKeysUsesCentralDerivativeEstimates();
    void hermiteWithGivenControlPoints();
    void hermiteIsC1();
    void hermiteThroughASteadySpinKeepsItsSpeed();
    void eulerCurveIsLinearInAngles();
};

void TestOrientationCurves::everyCurve_data()
{
    QTest::addColumn<int>("index");
    const std::vector<CurveCase> cases = allCurveCases();
    for (std::size_t i = 0; i < cases.size(); ++i)
        QTest::newRow(qPrintable(cases[i].label)) << int(i);
}

void TestOrientationCurves::everyCurve()
{
    QFETCH(int, index);
    const CurveCase c = allCurveCases()[std::size_t(index)];
    Random random(60 + std::uint64_t(index));
    for (int trial = 0; trial < 6; ++trial) {
        const std::vector<OrientationKey> keys =
            c.method == InterpolationMethod::Euler ? eulerKeys(random, c.convention, kTimes) : randomKeys(random, kTimes, 0.2, 1.4);
        const std::unique_ptr<OrientationCurve> curve = makeOrientationCurve(c.method, keys, c.convention);
        QVERIFY(curve != nullptr);
        checkCurve(*curve, keys, QStringLiteral("%1 trial %2").arg(c.label).arg(trial));
        if (QTest::currentTestFailed())
            return;
    }
    // The concrete class the factory returns.
    const std::vector<OrientationKey> keys = randomKeys(random, kTimes, 0.2, 1.0);
    const std::unique_ptr<OrientationCurve> curve = makeOrientationCurve(c.method, keys, c.convention);
    switch (c.method) {
    case InterpolationMethod::Slerp:
        QVERIFY(dynamic_cast<const SlerpCurve*>(curve.get()) != nullptr);
        break;
    case InterpolationMethod::Nlerp:
        QVERIFY(dynamic_cast<const NlerpCurve*>(curve.get()) != nullptr);
        break;
    case InterpolationMethod::Squad:
        QVERIFY(dynamic_cast<const SquadCurve*>(curve.get()) != nullptr);
        break;
    case InterpolationMethod::Hermite:
        QVERIFY(dynamic_cast<const HermiteQuaternionSpline*>(curve.get()) != nullptr);
        break;
    case InterpolationMethod::Euler:
    case InterpolationMethod::EulerCubic:
        QVERIFY(dynamic_cast<const EulerAngleCurve*>(curve.get()) != nullptr);
        break;
    case InterpolationMethod::Screw:
    case InterpolationMethod::Ballistic:
        QFAIL("not an orientation curve");
    }
}

void TestOrientationCurves::singleKeyHoldsStill_data() { everyCurve_data(); }

void TestOrientationCurves::singleKeyHoldsStill()
{
    QFETCH(int, index);
    const CurveCase c = allCurveCases()[std::size_t(index)];
    Random random(70);
    const Eigen::Quaterniond q = random.rotation();
    const std::unique_ptr<OrientationCurve> curve = makeOrientationCurve(c.method, {{1.5, q}}, c.convention);
    for (double t : {-3.0, 1.5, 1.5 + 1e-12, 7.0}) {
        const OrientationSample s = curve->sample(t);
        QVERIFY2(distanceUpToSign(s.value, q) < 1e-14 && s.derivative.coeffs().norm() == 0.0 && s.angularVelocity.norm() == 0.0,
                 qPrintable(QStringLiteral("t %1: value %2, derivative %3").arg(str(t), str(s.value), str(s.derivative))));
    }
}

void TestOrientationCurves::invalidKeysThrow()
{
    const Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
    const std::vector<std::vector<OrientationKey>> bad = {
        {},
        {{0.0, q}, {0.0, q}},
        {{0.0, q}, {1.0, q}, {0.5, q}},
        {{0.0, q}, {1.0, q}, {1.0, q}},
    };
    for (const CurveCase& c : allCurveCases()) {
        for (const std::vector<OrientationKey>& keys : bad)
            QVERIFY_THROWS_EXCEPTION(std::invalid_argument, makeOrientationCurve(c.method, keys, c.convention));
    }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, HermiteQuaternionSpline({}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             HermiteQuaternionSpline({HermiteControlPoint{1.0, q, {}}, HermiteControlPoint{1.0, q, {}}}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, makeOrientationCurve(InterpolationMethod::Screw, {{0.0, q}, {1.0, q}}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             makeOrientationCurve(InterpolationMethod::Ballistic, {{0.0, q}, {1.0, q}}));
}

void TestOrientationCurves::methodNames()
{
    for (InterpolationMethod m : {InterpolationMethod::Slerp, InterpolationMethod::Nlerp, InterpolationMethod::Squad,
                                  InterpolationMethod::Hermite, InterpolationMethod::Euler, InterpolationMethod::Screw,
                                  InterpolationMethod::Ballistic}) {
        const std::string_view name = interpolationMethodName(m);
        QVERIFY(!name.empty());
        const std::optional<InterpolationMethod> parsed = parseInterpolationMethod(name);
        QVERIFY2(parsed.has_value() && *parsed == m, std::string(name).c_str());
    }
    QVERIFY(!parseInterpolationMethod("").has_value());
    QVERIFY(!parseInterpolationMethod("bezier").has_value());
}

void TestOrientationCurves::slerpCurveIsSlerpPerSegment()
{
    Random random(71);
    for (int trial = 0; trial < 5; ++trial) {
        const std::vector<OrientationKey> keys = randomKeys(random, kTimes, 0.1, 2.8);
        const SlerpCurve curve(keys);
        const std::vector<Eigen::Quaterniond> a = alignedKeys(keys);
        for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
            const double d = keys[i + 1].time - keys[i].time;
            // The slerp segment turns at a constant world angular velocity: the rotation vector of
            // qᵢ₊₁qᵢ⁻¹ over the segment's duration.
            const Eigen::Vector3d omega = rotationVectorOf(a[i + 1] * a[i].conjugate()) / d;
            for (double u : {0.0, 0.1, 0.5, 0.8, 0.99}) {
                const OrientationSample s = curve.sample(keys[i].time + u * d);
                const Eigen::Quaterniond expected = slerpOf(a[i], a[i + 1], u);
                GYRE_CHECK(distanceUpToSign(s.value, expected) < 1e-13,
                           QStringLiteral("segment %1, u %2: %3, expected %4").arg(i).arg(str(u), str(s.value), str(expected)));
                GYRE_CHECK((s.angularVelocity - omega).norm() < 1e-12 * (1.0 + omega.norm()),
                           QStringLiteral("segment %1, u %2: ω %3, expected constant %4").arg(i).arg(str(u), str(s.angularVelocity), str(omega)));
            }
        }
    }
}

void TestOrientationCurves::nlerpCurveIsNlerpPerSegment()
{
    Random random(72);
    for (int trial = 0; trial < 5; ++trial) {
        const std::vector<OrientationKey> keys = randomKeys(random, kTimes, 0.1, 2.8);
        const NlerpCurve curve(keys);
        const std::vector<Eigen::Quaterniond> a = alignedKeys(keys);
        for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
            const double d = keys[i + 1].time - keys[i].time;
            for (double u : {0.0, 0.1, 0.5, 0.8, 0.99}) {
                const OrientationSample s = curve.sample(keys[i].time + u * d);
                const Eigen::Quaterniond expected = normalizedCopy(combination(1.0 - u, a[i], u, a[i + 1]));
                GYRE_CHECK(distanceUpToSign(s.value, expected) < 1e-14,
                           QStringLiteral("segment %1, u %2: %3, expected %4").arg(i).arg(str(u), str(s.value), str(expected)));
            }
        }
    }
}

void TestOrientationCurves::squadMatchesDefinition()
{
    Random random(73);
    for (int trial = 0; trial < 5; ++trial) {
        const std::vector<OrientationKey> keys = randomKeys(random, kTimes, 0.2, 1.2);
        const SquadCurve curve(keys);
        const std::vector<Eigen::Quaterniond> a = alignedKeys(keys);
        const std::size_t n = a.size();
        // Inner quadrangle points sᵢ = qᵢ·exp(−(log(qᵢ⁻¹qᵢ₊₁) + log(qᵢ⁻¹qᵢ₋₁))/4), s = q at the ends.
        std::vector<Eigen::Quaterniond> s(n);
        s[0] = a[0];
        s[n - 1] = a[n - 1];
        for (std::size_t i = 1; i + 1 < n; ++i)
            s[i] = a[i] * expOf(-(logOf(a[i].conjugate() * a[i + 1]) + logOf(a[i].conjugate() * a[i - 1])) / 4.0);
        for (std::size_t i = 0; i + 1 < n; ++i) {
            const double d = keys[i + 1].time - keys[i].time;
            for (double u : {0.0, 0.15, 0.4, 0.5, 0.66, 0.9, 1.0}) {
                const double t = std::min(keys[i].time + u * d, keys[i + 1].time);
                if (u == 1.0 && i + 2 < n)
                    continue; // the key itself belongs to the next segment
                const Eigen::Quaterniond expected = slerpOf(slerpOf(a[i], a[i + 1], u), slerpOf(s[i], s[i + 1], u), 2.0 * u * (1.0 - u));
                const OrientationSample sample = curve.sample(t);
                GYRE_CHECK(distanceUpToSign(sample.value, expected) < 1e-13,
                           QStringLiteral("trial %1 segment %2, u %3: %4, expected %5").arg(trial).arg(i).arg(str(u), str(sample.value), str(expected)));
            }
        }
    }
}

void TestOrientationCurves::squadIsC1AtInteriorKeys()
{
    // Shoemake's squad is C¹ in the segment parameter u: at an interior key both one-sided dq/du
    // equal qᵢ·(0, (log(qᵢ⁻¹qᵢ₊₁) − log(qᵢ⁻¹qᵢ₋₁))/2). In time, dq/dt = (dq/du)/duration, so dq/dt
    // is continuous only where neighbouring segments last equally long.
    Random random(74);
    const double eps = 1e-9;
    const std::vector<double> uniform = {0.0, 0.5, 1.0, 1.5, 2.0, 2.5};
    for (int trial = 0; trial < 6; ++trial) {
        const bool isUniform = trial % 2 == 0;
        const std::vector<double>& times = isUniform ? uniform : kTimes;
        const std::vector<OrientationKey> keys = randomKeys(random, times, 0.2, 1.2);
        const SquadCurve curve(keys);
        const SlerpCurve piecewise(keys);
        const std::vector<Eigen::Quaterniond> a = alignedKeys(keys);
        for (std::size_t i = 1; i + 1 < keys.size(); ++i) {
            const double ti = keys[i].time;
            const double dLeft = ti - keys[i - 1].time;
            const double dRight = keys[i + 1].time - ti;
            const OrientationSample left = curve.sample(ti - eps);
            const OrientationSample right = curve.sample(ti + eps);
            // Express both derivatives on the sign of aᵢ.
            const double sl = left.value.coeffs().dot(a[i].coeffs()) >= 0.0 ? 1.0 : -1.0;
            const double sr = right.value.coeffs().dot(a[i].coeffs()) >= 0.0 ? 1.0 : -1.0;
            const Eigen::Vector4d duLeft = sl * dLeft * left.derivative.coeffs();
            const Eigen::Vector4d duRight = sr * dRight * right.derivative.coeffs();
            const Eigen::Vector3d half = (logOf(a[i].conjugate() * a[i + 1]) - logOf(a[i].conjugate() * a[i - 1])) / 2.0;
            const Eigen::Vector4d expected = (a[i] * pure(half)).coeffs();
            GYRE_CHECK((duLeft - expected).norm() < 1e-6 && (duRight - expected).norm() < 1e-6,
                       QStringLiteral("trial %1 key %2: dq/du left %3, right %4, expected %5")
                           .arg(trial).arg(i).arg(str(fromCoeffs(duLeft)), str(fromCoeffs(duRight)), str(fromCoeffs(expected))));
            if (isUniform) {
                const Eigen::Vector4d dtLeft = sl * left.derivative.coeffs();
                const Eigen::Vector4d dtRight = sr * right.derivative.coeffs();
                GYRE_CHECK((dtLeft - dtRight).norm() < 1e-6 * (1.0 + dtLeft.norm()),
                           QStringLiteral("trial %1 key %2: dq/dt left %3, right %4").arg(trial).arg(i).arg(str(fromCoeffs(dtLeft)), str(fromCoeffs(dtRight))));
                const Eigen::Vector3d wLeft = left.angularVelocity;
                const Eigen::Vector3d wRight = right.angularVelocity;
                GYRE_CHECK((wLeft - wRight).norm() < 1e-6 * (1.0 + wLeft.norm()),
                           QStringLiteral("trial %1 key %2: ω left %3, right %4").arg(trial).arg(i).arg(str(wLeft), str(wRight)));
            }
            // The same check tells piecewise slerp apart: it has a corner at the key.
            const Eigen::Vector3d cornerLeft = piecewise.sample(ti - eps).angularVelocity;
            const Eigen::Vector3d cornerRight = piecewise.sample(ti + eps).angularVelocity;
            GYRE_CHECK((cornerLeft - cornerRight).norm() > 1e-3, QStringLiteral("slerp with no corner at key %1?").arg(i));
        }
    }
}

void TestOrientationCurves::hermiteThroughKeysUsesCentralDerivativeEstimates()
{
    Random random(75);
    using Rule = HermiteQuaternionSpline::KeyDerivatives;
    const double h = 1e-6;
    for (int trial = 0; trial < 5; ++trial) {
        const std::vector<OrientationKey> keys = randomKeys(random, kTimes, 0.2, 1.4);
        const Rule rule = trial % 2 == 0 ? Rule::Chord : Rule::Geodesic;
        const HermiteQuaternionSpline spline = HermiteQuaternionSpline::throughKeys(keys, rule);
        const std::vector<Eigen::Quaterniond> a = alignedKeys(keys);
        const std::size_t n = a.size();
        // Chord (InitCurve): q′(tᵢ) = (qᵢ₊₁ − qᵢ₋₁)/(tᵢ₊₁ − tᵢ₋₁) on the sign-aligned keys. Geodesic:
        // q′ = ½·qᵢ·(0, ω) with ω the body rotation vectors from the rotation matrices Rᵢ⁻¹Rᵢ₊₁ and
        // Rᵢ₋₁⁻¹Rᵢ, summed over the two spans' time. Both one-sided at the ends.
        std::vector<Eigen::Vector4d> m(n);
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t lo = i == 0 ? 0 : i - 1;
            const std::size_t hi = i + 1 == n ? n - 1 : i + 1;
            const double span = keys[hi].time - keys[lo].time;
            if (rule == Rule::Chord) {
                m[i] = (a[hi].coeffs() - a[lo].coeffs()) / span;
                continue;
            }
            const Eigen::Matrix3d r = a[i].toRotationMatrix();
            const Eigen::AngleAxisd ahead(r.transpose() * a[hi].toRotationMatrix());
            const Eigen::AngleAxisd behind(a[lo].toRotationMatrix().transpose() * r);
            const Eigen::Vector3d omega = (ahead.angle() * ahead.axis() + behind.angle() * behind.axis()) / span;
            m[i] = (a[i] * Eigen::Quaterniond(0.0, omega.x() / 2, omega.y() / 2, omega.z() / 2)).coeffs();
        }
        // The spline may hold all keys negated; fix that one global sign from the first key.
        const double sign = spline.raw(keys[0].time).value.coeffs().dot(a[0].coeffs()) >= 0.0 ? 1.0 : -1.0;
        for (std::size_t i = 0; i < n; ++i) {
            const HermiteQuaternionSpline::RawSample r = spline.raw(keys[i].time);
            GYRE_CHECK((sign * r.value.coeffs() - a[i].coeffs()).norm() < 1e-14,
                       QStringLiteral("trial %1 key %2: raw value %3, aligned key %4").arg(trial).arg(i).arg(str(r.value), str(a[i])));
            GYRE_CHECK((sign * r.derivative.coeffs() - m[i]).norm() < 1e-12 * (1.0 + m[i].norm()),
                       QStringLiteral("trial %1 key %2: raw derivative %3, expected %4").arg(trial).arg(i).arg(str(r.derivative), str(fromCoeffs(m[i]))));
        }
        // Between keys the raw curve is the cubic Hermite interpolant of those values and derivatives,
        // and its derivatives agree with finite differences.
        for (std::size_t i = 0; i + 1 < n; ++i) {
            const double t0 = keys[i].time;
            const double t1 = keys[i + 1].time;
            for (double u : {0.1, 0.33, 0.5, 0.8}) {
                const double t = t0 + u * (t1 - t0);
                const Cubic c = hermite(t0, t1, a[i].coeffs(), m[i], a[i + 1].coeffs(), m[i + 1], t);
                const HermiteQuaternionSpline::RawSample r = spline.raw(t);
                const QString at = QStringLiteral("trial %1, t %2").arg(trial).arg(str(t));
                GYRE_CHECK((sign * r.value.coeffs() - c.value).norm() < 1e-13, QStringLiteral("%1: raw value %2, expected %3").arg(at, str(r.value), str(fromCoeffs(c.value))));
                GYRE_CHECK((sign * r.derivative.coeffs() - c.first).norm() < 1e-12 * (1.0 + c.first.norm()),
                           QStringLiteral("%1: raw derivative %2, expected %3").arg(at, str(r.derivative), str(fromCoeffs(c.first))));
                GYRE_CHECK((sign * r.secondDerivative.coeffs() - c.second).norm() < 1e-11 * (1.0 + c.second.norm()),
                           QStringLiteral("%1: raw second derivative %2, expected %3").arg(at, str(r.secondDerivative), str(fromCoeffs(c.second))));
                const Eigen::Vector4d fd1 = (spline.raw(t + h).value.coeffs() - spline.raw(t - h).value.coeffs()) / (2.0 * h);
                const Eigen::Vector4d fd2 = (spline.raw(t + h).derivative.coeffs() - spline.raw(t - h).derivative.coeffs()) / (2.0 * h);
                GYRE_CHECK((r.derivative.coeffs() - fd1).norm() < 1e-7 * (1.0 + fd1.norm()), QStringLiteral("%1: raw derivative vs finite differences").arg(at));
                GYRE_CHECK((r.secondDerivative.coeffs() - fd2).norm() < 1e-6 * (1.0 + fd2.norm()),
                           QStringLiteral("%1: raw second derivative %2, finite differences %3").arg(at, str(r.secondDerivative), str(fromCoeffs(fd2))));
                // sample() is the normalised raw curve.
                const OrientationSample s = spline.sample(t);
                GYRE_CHECK(coeffDistance(s.value, normalizedCopy(r.value)) < 1e-15 * 4, QStringLiteral("%1: sample is not raw/|raw|").arg(at));
            }
        }
        // Held constant outside the span.
        GYRE_CHECK(coeffDistance(spline.raw(kTimes.back() + 1.0).value, spline.raw(kTimes.back()).value) < 1e-15 &&
                       coeffDistance(spline.raw(kTimes.front() - 1.0).value, spline.raw(kTimes.front()).value) < 1e-15,
                   QStringLiteral("trial %1: raw value not held outside the span").arg(trial));
    }
}

void TestOrientationCurves::hermiteWithGivenControlPoints()
{
    Random random(76);
    for (int trial = 0; trial < 5; ++trial) {
        std::vector<HermiteControlPoint> points;
        Eigen::Quaterniond q = random.rotation();
        for (double t : kTimes) {
            HermiteControlPoint p;
            p.time = t;
            p.value = q;
            p.derivative = combination(0.0, q, 1.0, q * pure(random.vector(0.4))); // tangent
            p.derivative.coeffs() += 0.05 * random.rotation().coeffs(); // and some radial part
            points.push_back(p);
            q = q * random.rotationWithAngle(0.2, 1.0);
        }
        const HermiteQuaternionSpline spline(points);
        QCOMPARE(spline.controlPoints().size(), points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            const HermiteQuaternionSpline::RawSample r = spline.raw(points[i].time);
            GYRE_CHECK(coeffDistance(r.value, points[i].value) < 1e-15 && coeffDistance(r.derivative, points[i].derivative) < 1e-13,
                       QStringLiteral("trial %1 point %2: raw %3 / %4, given %5 / %6").arg(trial).arg(i)
                           .arg(str(r.value), str(r.derivative), str(points[i].value), str(points[i].derivative)));
            GYRE_CHECK(coeffDistance(spline.controlPoints()[i].value, points[i].value) == 0.0, QStringLiteral("control point %1 changed").arg(i));
        }
        for (std::size_t i = 0; i + 1 < points.size(); ++i) {
            for (double u : {0.25, 0.5, 0.9}) {
                const double t = points[i].time + u * (points[i + 1].time - points[i].time);
                const Cubic c = hermite(points[i].time, points[i + 1].time, points[i].value.coeffs(), points[i].derivative.coeffs(),
                                        points[i + 1].value.coeffs(), points[i + 1].derivative.coeffs(), t);
                const HermiteQuaternionSpline::RawSample r = spline.raw(t);
                GYRE_CHECK((r.value.coeffs() - c.value).norm() < 1e-13 && (r.derivative.coeffs() - c.first).norm() < 1e-12 &&
                               (r.secondDerivative.coeffs() - c.second).norm() < 1e-11,
                           QStringLiteral("trial %1, t %2: raw differs from the Hermite cubic").arg(trial).arg(str(t)));
            }
        }
        checkCurve(spline, [&] {
            std::vector<OrientationKey> keys;
            for (const HermiteControlPoint& p : points)
                keys.push_back({p.time, p.value});
            return keys;
        }(), QStringLiteral("hermite control points trial %1").arg(trial));
        if (QTest::currentTestFailed())
            return;
    }
}

void TestOrientationCurves::hermiteIsC1()
{
    Random random(77);
    const double eps = 1e-9;
    for (int trial = 0; trial < 5; ++trial) {
        const std::vector<OrientationKey> keys = randomKeys(random, kTimes, 0.2, 1.4);
        const HermiteQuaternionSpline spline = HermiteQuaternionSpline::throughKeys(keys);
        for (std::size_t i = 1; i + 1 < keys.size(); ++i) {
            const double t = keys[i].time;
            const Eigen::Vector4d left = spline.raw(t - eps).derivative.coeffs();
            const Eigen::Vector4d right = spline.raw(t + eps).derivative.coeffs();
            GYRE_CHECK((left - right).norm() < 1e-6 * (1.0 + left.norm()), QStringLiteral("trial %1 key %2: raw derivative jumps").arg(trial).arg(i));
            const Eigen::Vector3d wl = spline.sample(t - eps).angularVelocity;
            const Eigen::Vector3d wr = spline.sample(t + eps).angularVelocity;
            GYRE_CHECK((wl - wr).norm() < 1e-6 * (1.0 + wl.norm()), QStringLiteral("trial %1 key %2: ω jumps from %3 to %4").arg(trial).arg(i).arg(str(wl), str(wr)));
        }
    }
}

// A steady 9 rad/s spin about a tilted axis, keyed every 1/6 s (86° apart) and at uneven times: the
// spline with geodesic derivatives plays it within 1% of 9 rad/s everywhere between the second and the
// second-last key (its one-sided end derivatives are exact too for a steady spin). The paper's chord
// derivatives, shorter than the arcs, ripple by more than 5%.
void TestOrientationCurves::hermiteThroughASteadySpinKeepsItsSpeed()
{
    using Rule = HermiteQuaternionSpline::KeyDerivatives;
    const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, -0.5).normalized();
    const double speed = 9.0;
    for (const std::vector<double>& times : {std::vector<double>{0, 1 / 6., 2 / 6., 3 / 6., 4 / 6., 5 / 6., 1},
                                             std::vector<double>{0, 0.1, 0.3, 0.35, 0.5, 0.7, 0.75, 0.9}}) {
        std::vector<OrientationKey> keys;
        for (const double t : times)
            keys.push_back({t, Eigen::Quaterniond(Eigen::AngleAxisd(speed * t, axis))});
        double worst[2] = {0.0, 0.0};
        for (const Rule rule : {Rule::Geodesic, Rule::Chord}) {
            const HermiteQuaternionSpline spline = HermiteQuaternionSpline::throughKeys(keys, rule);
            for (double t = times[1]; t <= times[times.size() - 2]; t += 1e-3) {
                const double error = std::abs(spline.sample(t).angularVelocity.norm() / speed - 1.0);
                worst[rule == Rule::Chord] = std::max(worst[rule == Rule::Chord], error);
            }
        }
        GYRE_CHECK(worst[0] < 0.01, QStringLiteral("geodesic: speed off by %1%").arg(100 * worst[0]));
        GYRE_CHECK(worst[1] > 0.05, QStringLiteral("chord: speed off by only %1%").arg(100 * worst[1]));
    }
}

void TestOrientationCurves::eulerCurveIsLinearInAngles()
{
    Random random(78);
    for (const char* order : {"xyz", "zxz", "yxz", "zyx"}) {
        for (AngleFrame frame : {AngleFrame::Extrinsic, AngleFrame::Intrinsic}) {
            const EulerConvention c = *EulerConvention::parse(order, frame);
            const std::vector<OrientationKey> keys = eulerKeys(random, c, kTimes);
            const EulerAngleCurve curve(keys, c);
            for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
                const double t0 = keys[i].time;
                const double d = keys[i + 1].time - t0;
                const int steps = 8;
                std::vector<Eigen::Quaterniond> samples;
                for (int k = 0; k <= steps; ++k)
                    samples.push_back(curve.sample(k == steps ? keys[i + 1].time - 1e-12 : t0 + d * k / steps).value);
                const std::vector<Eigen::Vector3d> e = unwrappedEulerAngles(samples, c);
                for (int k = 0; k <= steps; ++k) {
                    const Eigen::Vector3d linear = e[0] + (double(k) / steps) * (e[std::size_t(steps)] - e[0]);
                    GYRE_CHECK((e[std::size_t(k)] - linear).cwiseAbs().maxCoeff() < 1e-9,
                               QStringLiteral("%1 segment %2 step %3: angles %4, linear %5")
                                   .arg(QString::fromStdString(c.name())).arg(i).arg(k).arg(str(e[std::size_t(k)]), str(linear)));
                }
            }
            // The same curve is not linear in slerp's sense: its values differ from slerp somewhere.
            const SlerpCurve slerpCurve(keys);
            double largest = 0.0;
            for (double t = kTimes.front(); t < kTimes.back(); t += 0.05)
                largest = std::max(largest, angleBetween(curve.sample(t).value, slerpCurve.sample(t).value));
            GYRE_CHECK(largest > 1e-3, QStringLiteral("%1: Euler curve equals slerp?").arg(QString::fromStdString(c.name())));
        }
    }
}

QTEST_APPLESS_MAIN(TestOrientationCurves)
#include "tst_orientation_curves.moc"
