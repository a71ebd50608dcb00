// The time map of a keyed polyscrew (key_time_map.h) against a cubic per span solved here from its
// four conditions, and its continuity, monotony, inverse and cycle.

#include "core/key_time_map.h"

#include "core_test_support.h"

#include <Eigen/Dense>
#include <QObject>
#include <QTest>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

using namespace gyre;
using namespace gyre::test;

namespace {

std::vector<double> unevenTimes(Random& random, int count)
{
    std::vector<double> times;
    double time = random.uniform(-2.0, 2.0);
    for (int i = 0; i < count; ++i) {
        times.push_back(time);
        time += random.uniform(0.05, 3.0);
    }
    return times;
}

// The slope at knot i of `knots` (a cycle's closing time appended when cyclic): the secant over the
// neighbouring spans, the one span's at an open end, the closing span as the neighbour of a cycle's ends.
double slopeAt(const std::vector<double>& knots, std::size_t i, bool cyclic)
{
    const std::size_t last = knots.size() - 1;
    if (i > 0 && i < last)
        return 2.0 / (knots[i + 1] - knots[i - 1]);
    if (cyclic)
        return 2.0 / ((knots[last] - knots[last - 1]) + (knots[1] - knots[0]));
    return i == 0 ? 1.0 / (knots[1] - knots[0]) : 1.0 / (knots[last] - knots[last - 1]);
}

// p on span i as c₀ + c₁t + c₂t² + c₃t³, solved from p(tᵢ) = i, p(tᵢ₊₁) = i + 1 and the slopes.
Eigen::Vector4d spanCubic(const std::vector<double>& knots, std::size_t i, bool cyclic)
{
    Eigen::Matrix4d conditions;
    Eigen::Vector4d values;
    for (int end = 0; end < 2; ++end) {
        const double t = knots[i + static_cast<std::size_t>(end)];
        conditions.row(2 * end) << 1, t, t * t, t * t * t;
        conditions.row(2 * end + 1) << 0, 1, 2 * t, 3 * t * t;
        values[2 * end] = static_cast<double>(i) + end;
        values[2 * end + 1] = slopeAt(knots, i + static_cast<std::size_t>(end), cyclic);
    }
    return conditions.fullPivLu().solve(values);
}

double cubicAt(const Eigen::Vector4d& c, double t) { return c[0] + t * (c[1] + t * (c[2] + t * c[3])); }

} // namespace

class TestKeyTimeMap : public QObject {
    Q_OBJECT

private slots:
    void matchesTheCubicOfEachSpan();
    void isContinuousInSlopeAcrossKeys();
    void increasesStrictlyEvenWithVeryUnevenSpans();
    void timeAtInvertsParameterAt();
    void equalSpansMapLinearly();
    void cycleClosesWithTheMeanSpanAndRepeats();
    void holdsOutsideAnOpenTrack();
    void rejectsBadTimes();
};

void TestKeyTimeMap::matchesTheCubicOfEachSpan()
{
    Random random(3);
    for (const bool cyclic : {false, true}) {
        const std::vector<double> times = unevenTimes(random, 7);
        const KeyTimeMap map(times, cyclic);
        std::vector<double> knots = times;
        if (cyclic)
            knots.push_back(times.back() + (times.back() - times.front()) / 6.0);
        for (std::size_t i = 0; i + 1 < knots.size(); ++i) {
            const Eigen::Vector4d cubic = spanCubic(knots, i, cyclic);
            for (double u = 0.0; u < 1.0; u += 0.0625) {
                const double t = knots[i] + u * (knots[i + 1] - knots[i]);
                GYRE_CHECK(std::abs(map.parameterAt(t) - cubicAt(cubic, t)) < 1e-9,
                           QStringLiteral("span %1 u %2: %3 against %4")
                               .arg(i)
                               .arg(u)
                               .arg(map.parameterAt(t))
                               .arg(cubicAt(cubic, t)));
            }
        }
    }
}

// The slope just before and just after every key agree, although the spans around it differ up to 60×.
void TestKeyTimeMap::isContinuousInSlopeAcrossKeys()
{
    Random random(5);
    for (const bool cyclic : {false, true}) {
        const std::vector<double> times = unevenTimes(random, 8);
        const KeyTimeMap map(times, cyclic);
        const double h = 1e-7;
        for (std::size_t i = cyclic ? 0 : 1; i + 1 < times.size(); ++i) {
            const double before = (map.parameterAt(times[i] - h) - map.parameterAt(times[i] - 2 * h)) / h;
            const double after = (map.parameterAt(times[i] + 2 * h) - map.parameterAt(times[i] + h)) / h;
            GYRE_CHECK(std::abs(before - after) < 1e-4 * after,
                       QStringLiteral("key %1: %2 before, %3 after").arg(i).arg(before).arg(after));
            QVERIFY(std::abs(map.rateAt(times[i]) - after) < 1e-4 * after);
        }
    }
}

void TestKeyTimeMap::increasesStrictlyEvenWithVeryUnevenSpans()
{
    for (const bool cyclic : {false, true}) {
        const KeyTimeMap map({0.0, 0.001, 10.0, 10.002, 30.0}, cyclic);
        double previous = -1.0;
        for (double t = 0.0; t < map.period(); t += 1e-4) {
            const double p = map.parameterAt(t);
            QVERIFY2(p > previous, qPrintable(QString::number(t)));
            QVERIFY(map.rateAt(t) > 0.0);
            previous = p;
        }
    }
}

void TestKeyTimeMap::timeAtInvertsParameterAt()
{
    Random random(7);
    for (const bool cyclic : {false, true}) {
        const std::vector<double> times = unevenTimes(random, 6);
        const KeyTimeMap map(times, cyclic);
        const double spans = cyclic ? 6.0 : 5.0;
        for (double p = 0.0; p < spans; p += 0.01) {
            const double t = map.timeAt(p);
            QVERIFY2(std::abs(map.parameterAt(t) - p) < 1e-12, qPrintable(QString::number(p)));
        }
        for (std::size_t i = 0; i < times.size(); ++i)
            QVERIFY(std::abs(map.timeAt(static_cast<double>(i)) - times[i]) < 1e-12);
    }
}

void TestKeyTimeMap::equalSpansMapLinearly()
{
    for (const bool cyclic : {false, true}) {
        const KeyTimeMap map({1.0, 1.5, 2.0, 2.5}, cyclic);
        for (double t = 1.0; t < 2.5; t += 0.01)
            QVERIFY(std::abs(map.parameterAt(t) - (t - 1.0) / 0.5) < 1e-12);
    }
}

// Keys at 1, 1.5, 3, 4: the closing span lasts the mean span, 1 s; the period is 4 s.
void TestKeyTimeMap::cycleClosesWithTheMeanSpanAndRepeats()
{
    const KeyTimeMap map({1.0, 1.5, 3.0, 4.0}, true);
    QCOMPARE(map.period(), 4.0);
    QVERIFY(std::abs(map.parameterAt(5.0)) < 1e-12);
    QVERIFY(std::abs(map.parameterAt(4.999999) - 4.0) < 1e-5);
    for (const double time : {1.2, 2.0, 3.7, 4.6})
        for (const double periods : {-2.0, 1.0, 3.0})
            QVERIFY(std::abs(map.parameterAt(time + 4.0 * periods) - map.parameterAt(time)) < 1e-9);
}

void TestKeyTimeMap::holdsOutsideAnOpenTrack()
{
    const KeyTimeMap map({1.0, 2.0, 4.0}, false);
    QCOMPARE(map.parameterAt(-3.0), 0.0);
    QCOMPARE(map.parameterAt(9.0), 2.0);
    QCOMPARE(map.rateAt(-3.0), 0.0);
    QCOMPARE(map.rateAt(9.0), 0.0);
    const KeyTimeMap single({2.0}, false);
    QCOMPARE(single.parameterAt(7.0), 0.0);
    QCOMPARE(single.timeAt(0.0), 2.0);
}

void TestKeyTimeMap::rejectsBadTimes()
{
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, KeyTimeMap({}, false));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, KeyTimeMap({1.0, 1.0}, false));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, KeyTimeMap({2.0, 1.0}, true));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             KeyTimeMap({0.0, std::numeric_limits<double>::quiet_NaN()}, false));
}

QTEST_APPLESS_MAIN(TestKeyTimeMap)
#include "tst_key_time_map.moc"
