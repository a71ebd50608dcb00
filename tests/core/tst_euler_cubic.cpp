// Euler angle curves built from stored angles (EulerAngleCurve::throughAngles, orientation_curves.h): the linear
// shape is the straight line between the angles as given (0 then 2π is a full turn); the cubic shape's automatic
// slopes are those Blender's Auto Clamped keys have, computed here from their definition: the neighbours' chord
// slope, zero at the ends and at extrema, at most three times either side's chord. The cubic passes its keys, is
// C¹ at them, never leaves the range of the two keys a segment joins on monotone keys, and its orientation,
// derivative and angular velocity agree with the angles and finite differences.

#include "core/orientation_curves.h"

#include <QObject>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using namespace gyre;

namespace {

constexpr double kPi = std::numbers::pi;

using AngleKeys = std::vector<EulerAngleCurve::AngleKey>;

// Uneven times; the first angle monotone rising (with a long flat-ish step), the second with a peak and a valley,
// the third a full turn and more.
const AngleKeys kKeys = {
    {0.0, {0.0, 0.1, 0.0}},
    {0.5, {0.2, 0.9, 1.5 * kPi}},
    {0.7, {2.5, 0.2, 2.0 * kPi}},
    {1.9, {2.6, -0.6, 3.0 * kPi}},
    {2.2, {4.0, -0.1, 4.0 * kPi}},
};

double slopeByDefinition(const AngleKeys& keys, std::size_t i, int axis)
{
    if (i == 0 || i + 1 == keys.size())
        return 0.0;
    const auto at = [&](std::size_t k) { return keys[k].angles[axis]; };
    const double before = (at(i) - at(i - 1)) / (keys[i].time - keys[i - 1].time);
    const double after = (at(i + 1) - at(i)) / (keys[i + 1].time - keys[i].time);
    if (before * after <= 0.0)
        return 0.0;
    const double chord = (at(i + 1) - at(i - 1)) / (keys[i + 1].time - keys[i - 1].time);
    const double bound = 3.0 * std::min(std::abs(before), std::abs(after));
    return std::abs(chord) <= bound ? chord : (chord > 0 ? bound : -bound);
}

} // namespace

class TestEulerCubic : public QObject {
    Q_OBJECT

private slots:
    void linearAnglesAreTheStraightLineBetweenTheStoredAngles()
    {
        const EulerConvention z = *EulerConvention::parse("zyx", AngleFrame::Intrinsic);
        const EulerAngleCurve curve = EulerAngleCurve::throughAngles(
            {{0.0, Eigen::Vector3d::Zero()}, {2.0, Eigen::Vector3d(2.0 * kPi, 0.0, 0.0)}}, z,
            EulerAngleCurve::Shape::Linear);
        // A full turn about z: at a quarter of the time a quarter turn, at half a half turn.
        for (const double time : {0.5, 1.0, 1.5}) {
            const double angle = kPi * time;
            QVERIFY(std::abs(curve.anglesAt(time).x() - angle) < 1e-12);
            const Eigen::Quaterniond expected(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()));
            QVERIFY(std::abs(std::abs(curve.sample(time).value.coeffs().dot(expected.coeffs())) - 1.0) < 1e-12);
            QVERIFY((curve.sample(time).angularVelocity - Eigen::Vector3d(0.0, 0.0, kPi)).norm() < 1e-9);
        }
        QVERIFY(curve.keySlopes().empty());
    }

    void cubicSlopesAreTheAutomaticOnes()
    {
        const EulerAngleCurve curve =
            EulerAngleCurve::throughAngles(kKeys, EulerConvention{}, EulerAngleCurve::Shape::Cubic);
        QCOMPARE(curve.keySlopes().size(), kKeys.size());
        for (std::size_t i = 0; i < kKeys.size(); ++i)
            for (int axis = 0; axis < 3; ++axis)
                QVERIFY2(std::abs(curve.keySlopes()[i][axis] - slopeByDefinition(kKeys, i, axis)) < 1e-12,
                         qPrintable(QStringLiteral("key %1 axis %2").arg(i).arg(axis)));
        // Flat at the ends, at the second angle's peak (key 1) and valley (key 3).
        QCOMPARE(curve.keySlopes().front(), Eigen::Vector3d::Zero());
        QCOMPARE(curve.keySlopes().back(), Eigen::Vector3d::Zero());
        QCOMPARE(curve.keySlopes()[1][1], 0.0);
        QCOMPARE(curve.keySlopes()[3][1], 0.0);
        // The third angle rises steadily: a slope of its own at the inner keys.
        QVERIFY(curve.keySlopes()[2][2] > 0.0);
    }

    void cubicPassesItsKeysAndIsSmoothAtThem()
    {
        const EulerAngleCurve curve =
            EulerAngleCurve::throughAngles(kKeys, EulerConvention{}, EulerAngleCurve::Shape::Cubic);
        // Steps small against the cubics' curvature (|p″| < 400 rad/s² here), large against rounding.
        constexpr double h = 1e-7;
        for (std::size_t i = 0; i < kKeys.size(); ++i) {
            QVERIFY((curve.anglesAt(kKeys[i].time) - kKeys[i].angles).norm() < 1e-12);
            if (i == 0 || i + 1 == kKeys.size())
                continue;
            // C¹: the one-sided difference quotients on both sides meet the key's slope.
            const Eigen::Vector3d left = (curve.anglesAt(kKeys[i].time) - curve.anglesAt(kKeys[i].time - h)) / h;
            const Eigen::Vector3d right = (curve.anglesAt(kKeys[i].time + h) - curve.anglesAt(kKeys[i].time)) / h;
            QVERIFY2((left - curve.keySlopes()[i]).norm() < 1e-4, qPrintable(QString::number(i)));
            QVERIFY2((right - curve.keySlopes()[i]).norm() < 1e-4, qPrintable(QString::number(i)));
        }
    }

    void cubicNeverOvershootsMonotoneKeys()
    {
        // The first angle rises with very uneven steps, where Catmull-Rom slopes alone would overshoot.
        const AngleKeys keys = {{0.0, {0.0, 0, 0}}, {0.1, {3.0, 0, 0}}, {1.0, {3.05, 0, 0}},
                                {1.1, {6.0, 0, 0}}, {3.0, {6.1, 0, 0}}};
        const EulerAngleCurve curve = EulerAngleCurve::throughAngles(keys, EulerConvention{}, EulerAngleCurve::Shape::Cubic);
        for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
            const double low = keys[i].angles.x();
            const double high = keys[i + 1].angles.x();
            for (int step = 0; step <= 200; ++step) {
                const double time = keys[i].time + (keys[i + 1].time - keys[i].time) * step / 200.0;
                const double angle = curve.anglesAt(time).x();
                QVERIFY2(angle >= low - 1e-12 && angle <= high + 1e-12, qPrintable(QString::number(time)));
            }
        }
    }

    void cubicOrientationFollowsItsAngles()
    {
        const EulerConvention convention = *EulerConvention::parse("xzx", AngleFrame::Extrinsic);
        const EulerAngleCurve curve = EulerAngleCurve::throughAngles(kKeys, convention, EulerAngleCurve::Shape::Cubic);
        constexpr double h = 1e-6;
        for (const double time : {0.1, 0.6, 1.2, 2.0}) {
            const OrientationSample sample = curve.sample(time);
            const Eigen::Quaterniond expected = quaternionFromEulerAngles(curve.anglesAt(time), convention);
            QVERIFY(std::abs(std::abs(sample.value.coeffs().dot(expected.coeffs())) - 1.0) < 1e-12);
            // The derivative against a central difference of the curve's own values, signs aligned.
            Eigen::Quaterniond before = curve.sample(time - h).value;
            Eigen::Quaterniond after = curve.sample(time + h).value;
            if (before.coeffs().dot(sample.value.coeffs()) < 0)
                before.coeffs() *= -1.0;
            if (after.coeffs().dot(sample.value.coeffs()) < 0)
                after.coeffs() *= -1.0;
            const Eigen::Vector4d numeric = (after.coeffs() - before.coeffs()) / (2 * h);
            QVERIFY2((sample.derivative.coeffs() - numeric).norm() < 1e-5, qPrintable(QString::number(time)));
        }
    }

    void theMethodIsNamedEulerCubic()
    {
        QCOMPARE(parseInterpolationMethod("euler-cubic"), std::optional(InterpolationMethod::EulerCubic));
        QVERIFY(interpolatesAngles(InterpolationMethod::EulerCubic));
        QVERIFY(interpolatesAngles(InterpolationMethod::Euler));
        QVERIFY(!interpolatesAngles(InterpolationMethod::Hermite));
        // Through quaternions, the angles are those the Euler filter unwraps: the keys' own at the keys.
        std::vector<OrientationKey> keys;
        for (const auto& key : kKeys)
            keys.push_back({key.time, quaternionFromEulerAngles(key.angles, EulerConvention{})});
        const auto curve = makeOrientationCurve(InterpolationMethod::EulerCubic, keys);
        for (const auto& key : keys)
            QVERIFY(std::abs(std::abs(curve->sample(key.time).value.coeffs().dot(key.rotation.coeffs())) - 1.0) < 1e-12);
    }
};

QTEST_APPLESS_MAIN(TestEulerCubic)
#include "tst_euler_cubic.moc"
