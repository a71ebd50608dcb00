// Every orientation curve is continuous, for any keys: either sign of each stored quaternion, and up
// to 179° between neighbouring keys. Each curve is sampled every 1/480 s and the angle between
// consecutive samples is bounded by what the keys' motion allows (see stepBound). A curve that
// changes sign or crosses a logarithm's cut part-way through a segment turns by tens of degrees in
// one step (squad through the keys of issue 20 turned 170° between two samples 1/480 s apart).

#include "core/orientation_curves.h"

#include "core_test_support.h"

#include <QObject>
#include <QTest>

#include <algorithm>
#include <memory>
#include <vector>

using namespace gyre;
using namespace gyre::test;

namespace {

constexpr double kStep = 1.0 / 480.0;

// The largest angle a curve of the method may turn in one step of kStep through these keys.
//
// Slerp turns at the key-to-key speed ω = (angle between keys)/(segment duration). Nlerp runs at most
// 2·tan(φ/2)/φ ≤ 4/π times faster than slerp over a half-angle φ ≤ π/2. Squad and the Hermite spline
// have no such closed bound; where they overshoot a key they run faster than ω, and a factor of 8
// leaves them room while a jump (tens of degrees in one step) still fails: the keys' slowest-looking
// worst case, 179° over 0.75 s, gives 8·ω·kStep ≈ 4°. Linear Euler angles turn at most at
// |ė₁| + |ė₂| + |ė₃|, and the Euler filter moves each angle by at most π between keys.
double stepBound(InterpolationMethod method, const std::vector<OrientationKey>& keys)
{
    double keySpeed = 0.0;
    double shortestSegment = keys.back().time - keys.front().time;
    for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
        const double duration = keys[i + 1].time - keys[i].time;
        keySpeed = std::max(keySpeed, angleBetween(keys[i].rotation, keys[i + 1].rotation) / duration);
        shortestSegment = std::min(shortestSegment, duration);
    }
    // Rounding: a step of kStep cannot be measured better than this.
    constexpr double kSlack = 1e-9;
    switch (method) {
    case InterpolationMethod::Slerp:
        return keySpeed * kStep + kSlack;
    case InterpolationMethod::Nlerp:
        return 4.0 / kPi * keySpeed * kStep + kSlack;
    case InterpolationMethod::Squad:
    case InterpolationMethod::Hermite:
        return 8.0 * keySpeed * kStep;
    case InterpolationMethod::Euler:
        return 3.0 * kPi / shortestSegment * kStep + kSlack;
    case InterpolationMethod::EulerCubic:
        // Each angle's slope is at most three times its chords' (orientation_curves.h).
        return 9.0 * kPi / shortestSegment * kStep + kSlack;
    case InterpolationMethod::Screw:
    case InterpolationMethod::Ballistic:
        break;
    }
    return 0.0;
}

struct WorstStep {
    double angle = 0.0;
    double time = 0.0;
};

// The largest angle between consecutive samples kStep apart over the keys' span, the last sample
// at the last key.
WorstStep worstStep(const OrientationCurve& curve)
{
    WorstStep worst;
    Eigen::Quaterniond previous = curve.sample(curve.startTime()).value;
    const auto steps = static_cast<long>(std::ceil((curve.endTime() - curve.startTime()) / kStep));
    for (long k = 1; k <= steps; ++k) {
        const double t = std::min(curve.startTime() + static_cast<double>(k) * kStep, curve.endTime());
        const Eigen::Quaterniond value = curve.sample(t).value;
        const double angle = angleBetween(previous, value);
        if (angle > worst.angle)
            worst = {angle, t};
        previous = value;
    }
    return worst;
}

// The keys of issue 20: 0°, 90°, 179°, 0° about x at 0.5, 1, 2 and 4.5 s.
std::vector<OrientationKey> issueKeys()
{
    const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
    return {{0.5, axisAngleQuaternion(x, 0.0)},
            {1.0, axisAngleQuaternion(x, kPi / 2.0)},
            {2.0, axisAngleQuaternion(x, 179.0 * kPi / 180.0)},
            {4.5, axisAngleQuaternion(x, 0.0)}};
}

// Seven keys, each turned from the one before by 90° to 179° about a random axis, over segments of
// 0.75 s to 1.5 s, each stored with a random sign.
std::vector<OrientationKey> wideKeys(Random& random)
{
    std::vector<OrientationKey> keys;
    Eigen::Quaterniond q = random.rotation();
    double time = random.uniform(-1.0, 1.0);
    for (int i = 0; i < 7; ++i) {
        keys.push_back({time, random.uniform(0.0, 1.0) < 0.5 ? negated(q) : q});
        q = q * random.rotationWithAngle(kPi / 2.0, 179.0 * kPi / 180.0);
        time += random.uniform(0.75, 1.5);
    }
    return keys;
}

void checkSteps(const CurveCase& c, const std::vector<OrientationKey>& keys, const QString& label)
{
    const std::unique_ptr<OrientationCurve> curve = makeOrientationCurve(c.method, keys, c.convention);
    const WorstStep worst = worstStep(*curve);
    const double bound = stepBound(c.method, keys);
    GYRE_CHECK(worst.angle <= bound, QStringLiteral("%1, %2: turns %3° in %4 s at t = %5, more than the %6° the keys allow")
                                         .arg(c.label, label, str(worst.angle * 180.0 / kPi), str(kStep), str(worst.time),
                                              str(bound * 180.0 / kPi)));
}

} // namespace

class TestCurveContinuity : public QObject {
    Q_OBJECT

private slots:
    void everyMethod_data();
    void issueKeysTurnSmoothly();
    void issueKeysTurnSmoothly_data() { everyMethod_data(); }
    void wideKeysOfEitherSignTurnSmoothly();
    void wideKeysOfEitherSignTurnSmoothly_data() { everyMethod_data(); }
};

void TestCurveContinuity::everyMethod_data()
{
    QTest::addColumn<int>("index");
    const std::vector<CurveCase> methods = allCurveCases();
    for (std::size_t i = 0; i < methods.size(); ++i)
        QTest::newRow(qPrintable(methods[i].label)) << int(i);
}

void TestCurveContinuity::issueKeysTurnSmoothly()
{
    QFETCH(int, index);
    const CurveCase c = allCurveCases()[std::size_t(index)];
    std::vector<OrientationKey> keys = issueKeys();
    checkSteps(c, keys, QStringLiteral("the issue's keys"));
    // The same rotations stored with the other sign, one key at a time.
    for (std::size_t flipped = 0; flipped < keys.size(); ++flipped) {
        std::vector<OrientationKey> other = keys;
        other[flipped].rotation = negated(other[flipped].rotation);
        checkSteps(c, other, QStringLiteral("the issue's keys, key %1 negated").arg(flipped));
    }
}

void TestCurveContinuity::wideKeysOfEitherSignTurnSmoothly()
{
    QFETCH(int, index);
    const CurveCase c = allCurveCases()[std::size_t(index)];
    Random random(2000 + std::uint64_t(index));
    for (int trial = 0; trial < 40 && !QTest::currentTestFailed(); ++trial)
        checkSteps(c, wideKeys(random), QStringLiteral("trial %1").arg(trial));
}

QTEST_APPLESS_MAIN(TestCurveContinuity)
#include "tst_curve_continuity.moc"
