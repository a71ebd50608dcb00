// The screw's fast sine, cosine and arctangent (fast_trig.h) against the correctly rounded standard
// library. The header promises an absolute error of a few units of 2⁻⁵³ for sin and cos with
// |x| ≤ 1024, and a few ulp for the angle of a point of the unit circle. Relative precision is checked where
// the screw relies on it: sin x for tiny x (a tiny rotation), whose ratio to sin a sets the motion.

#include "core/fast_trig.h"

#include "core_test_support.h"

#include <QObject>
#include <QTest>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

using namespace gyre;
using namespace gyre::test;

namespace {

constexpr double kFewUlp = 4.0;

// Distance between two doubles in units in the last place of the reference value b (at least the
// smallest subnormal).
double ulpError(double a, double b)
{
    if (a == b)
        return 0.0;
    if (!std::isfinite(a) || !std::isfinite(b))
        return std::numeric_limits<double>::infinity();
    const double ulp = std::max(std::nextafter(std::abs(b), std::numeric_limits<double>::infinity()) - std::abs(b),
                                std::numeric_limits<double>::denorm_min());
    return std::abs(a - b) / ulp;
}

std::vector<double> sinCosArguments()
{
    Random random(300);
    std::vector<double> xs = {0.0, -0.0, 1e-300, 1e-20, 1e-10, 1e-5, 0.1, 0.5, 1.0, 2.0, 3.0, 10.0, 100.0, 1e4, 1e6, 1048576.0};
    for (int k = -16; k <= 16; ++k) {
        const double multiple = k * (kPi / 4.0);
        xs.push_back(multiple);
        xs.push_back(std::nextafter(multiple, 1e300));
        xs.push_back(std::nextafter(multiple, -1e300));
        xs.push_back(multiple + 1e-9);
        xs.push_back(multiple - 1e-7);
    }
    for (int i = 0; i < 20000; ++i)
        xs.push_back(random.uniform(-2.0 * kPi, 2.0 * kPi));
    for (int i = 0; i < 5000; ++i)
        xs.push_back(random.uniform(-1048576.0, 1048576.0));
    for (int i = 0; i < 2000; ++i)
        xs.push_back(std::pow(10.0, random.uniform(-12.0, 0.0)) * (random.uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0));
    const std::size_t count = xs.size();
    for (std::size_t i = 0; i < count; ++i)
        xs.push_back(-xs[i]);
    return xs;
}

} // namespace

class TestFastTrig : public QObject {
    Q_OBJECT

private slots:
    void sinCosAbsoluteErrorIsRounding();
    void sinCosWithinAFewUlpNearZero();
    void sinCosBeyondTheTableRange();
    void angleOnUnitCircleWithinAFewUlp();
    void preciseAngleWithinAFewUnitsOf2ToThe60();
};

void TestFastTrig::sinCosAbsoluteErrorIsRounding()
{
    // What the screw needs: sin and cos of half-angles within a few rounding errors of 1.
    double worst = 0.0;
    double worstAt = 0.0;
    for (double x : sinCosArguments()) {
        const SinCos sc = fastSinCos(x);
        const double error = std::max(std::abs(sc.sin - std::sin(x)), std::abs(sc.cos - std::cos(x)));
        if (error > worst) {
            worst = error;
            worstAt = x;
        }
    }
    qInfo("worst absolute error %.3g at x = %.17g", worst, worstAt);
    QVERIFY2(worst <= kFewUlp * std::numeric_limits<double>::epsilon() / 2.0, qPrintable(QStringLiteral("x = %1: error %2").arg(str(worstAt), str(worst))));
}

void TestFastTrig::sinCosWithinAFewUlpNearZero()
{
    // Below π/256 no table entry is involved, so sin x keeps its relative precision as x → 0.
    double worstSin = 0.0;
    double worstCos = 0.0;
    double worstAt = 0.0;
    for (double x : sinCosArguments()) {
        if (!(std::abs(x) < kPi / 256.0))
            continue;
        const SinCos sc = fastSinCos(x);
        const double es = ulpError(sc.sin, std::sin(x));
        const double ec = ulpError(sc.cos, std::cos(x));
        if (std::max(es, ec) > std::max(worstSin, worstCos))
            worstAt = x;
        worstSin = std::max(worstSin, es);
        worstCos = std::max(worstCos, ec);
    }
    qInfo("near zero: worst sin error %.3g ulp, worst cos error %.3g ulp, at x = %.17g", worstSin, worstCos, worstAt);
    QVERIFY2(worstSin <= kFewUlp && worstCos <= kFewUlp,
             qPrintable(QStringLiteral("x = %1: sin %2 ulp, cos %3 ulp").arg(str(worstAt), str(worstSin), str(worstCos))));
}

void TestFastTrig::sinCosBeyondTheTableRange()
{
    // Beyond 1024 it defers to the standard library.
    for (double x : {1024.5, -1100.0, 1048577.5, 3e6, -7.25e9, 1e15, 1e300}) {
        const SinCos sc = fastSinCos(x);
        QVERIFY2(ulpError(sc.sin, std::sin(x)) <= kFewUlp && ulpError(sc.cos, std::cos(x)) <= kFewUlp, qPrintable(str(x)));
    }
}

void TestFastTrig::angleOnUnitCircleWithinAFewUlp()
{
    // Points (cos a, sin a) as a screw's relative quaternion gives them: on the unit circle up to
    // rounding, in the first quadrant. The reference is atan2 of the very same two doubles.
    Random random(301);
    std::vector<double> angles = {0.0, 1e-300, 1e-100, 1e-20, 1e-12, 1e-8, 1e-4, kPi / 4.0, kPi / 2.0};
    for (int i = 0; i < 50000; ++i)
        angles.push_back(random.uniform(0.0, kPi / 2.0));
    for (int i = 0; i < 5000; ++i) {
        angles.push_back(std::pow(10.0, random.uniform(-15.0, 0.0)));                   // tiny rotations
        angles.push_back(kPi / 2.0 - std::pow(10.0, random.uniform(-15.0, 0.0)));       // half turns
        angles.push_back(kPi / 4.0 + random.uniform(-1e-6, 1e-6));                      // where it changes axis
        angles.push_back(std::round(random.uniform(0.0, 64.0)) * kPi / 128.0 + random.uniform(-1e-9, 1e-9));
    }
    // A point off the circle by a relative drift δ moves the result by about δ·a (the angle is read
    // from one coordinate), which the allowance adds to the few ulp of rounding.
    double worst = 0.0;
    double worstCos = 1.0;
    double worstSin = 0.0;
    for (double a : angles) {
        for (double drift : {0.0, 4e-16, -4e-16}) {
            const double c = (1.0 + drift) * std::cos(a);
            const double s = (1.0 + drift) * std::sin(a);
            const double reference = std::atan2(s, c);
            const double ulp = std::nextafter(reference, 4.0) - reference;
            const double allowance = std::abs(drift * reference) / ulp;
            const double e = ulpError(fastAngleOnUnitCircle(c, s), reference) - allowance;
            if (e > worst) {
                worst = e;
                worstCos = c;
                worstSin = s;
            }
        }
    }
    qInfo("worst angle error %.3g ulp beyond the drift allowance at (cos, sin) = (%.17g, %.17g)", worst, worstCos, worstSin);
    QVERIFY2(worst <= kFewUlp, qPrintable(QStringLiteral("angle of (%1, %2): fast %3, std %4 (%5 ulp)")
                                              .arg(str(worstCos), str(worstSin), str(fastAngleOnUnitCircle(worstCos, worstSin)),
                                                   str(std::atan2(worstSin, worstCos)), str(worst))));
}

void TestFastTrig::preciseAngleWithinAFewUnitsOf2ToThe60()
{
    // Points of lengths from 1e-12 to √2 in the first quadrant, as an Euler decomposition's quaternion
    // pairs give them; the reference is the long double atan2 of the very same two doubles. The table angle and
    // its correction are added in long double, unrounded, as the Euler decomposition adds them.
    constexpr long double kBound = 4e-18L; // rad: a few units of 2⁻⁶⁰, as fast_trig.h states
    Random random(302);
    std::vector<double> angles = {0.0, 1e-300, 1e-20, 1e-8, kPi / 4.0, kPi / 2.0};
    for (int i = 0; i < 50000; ++i)
        angles.push_back(random.uniform(0.0, kPi / 2.0));
    for (int i = 0; i < 5000; ++i) {
        angles.push_back(std::pow(10.0, random.uniform(-15.0, 0.0)));
        angles.push_back(kPi / 2.0 - std::pow(10.0, random.uniform(-15.0, 0.0)));
        angles.push_back(kPi / 4.0 + random.uniform(-1e-6, 1e-6));
        angles.push_back(std::asin(std::round(random.uniform(0.0, 190.0)) / 256.0) + random.uniform(-1e-9, 1e-9)); // bin edges
    }
    long double worst = 0.0L;
    double worstX = 1.0;
    double worstY = 0.0;
    double largestCorrection = 0.0;
    for (double a : angles) {
        for (double length : {1.0, std::pow(10.0, random.uniform(-12.0, 0.2)), std::sqrt(2.0)}) {
            const double x = length * std::cos(a);
            const double y = length * std::sin(a);
            const TableAngleSum angle = preciseAngleInFirstQuadrant(x, y, std::sqrt(x * x + y * y));
            const long double error = std::abs(static_cast<long double>(angle.tableAngle) + angle.correction -
                                               std::atan2(static_cast<long double>(y), static_cast<long double>(x)));
            largestCorrection = std::max(largestCorrection, std::abs(angle.correction));
            if (error > worst) {
                worst = error;
                worstX = x;
                worstY = y;
            }
        }
    }
    qInfo("worst precise angle error %.3Lg rad at (%.17g, %.17g); largest correction %.3g", worst, worstX, worstY, largestCorrection);
    QVERIFY2(worst <= kBound, qPrintable(QStringLiteral("angle of (%1, %2) off by %3").arg(str(worstX), str(worstY)).arg(static_cast<double>(worst))));
    QVERIFY(largestCorrection < 0.006);
}

QTEST_APPLESS_MAIN(TestFastTrig)
#include "tst_fast_trig.moc"
