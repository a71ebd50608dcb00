// Positions through timed keys (position_curve.h): the Hermite basis against its defining properties
// and finite differences, and both curve shapes against constructions written here.

#include "core/position_curve.h"

#include "core_test_support.h"

#include <QObject>
#include <QTest>

#include <stdexcept>
#include <vector>

using namespace gyre;
using namespace gyre::test;

namespace {

std::vector<PositionKey> randomKeys(Random& random, int count)
{
    std::vector<PositionKey> keys;
    double time = random.uniform(-1.0, 1.0);
    for (int i = 0; i < count; ++i) {
        keys.push_back({time, random.vector(5.0)});
        time += random.uniform(0.1, 2.0); // uneven spacing
    }
    return keys;
}

} // namespace

class TestPositionCurve : public QObject {
    Q_OBJECT

private slots:
    void hermiteBasisEndConditions();
    void hermiteBasisDerivativesMatchFiniteDifferences();
    void linearCurveIsPiecewiseLinear();
    void cubicCurvePassesThroughKeysWithCentralSlopes();
    void cubicCurveReproducesStraightMotion();
    void holdsOutsideTheKeys();
    void velocityIsTheDerivativeOfThePosition();
    void rejectsBadKeys();
};

void TestPositionCurve::hermiteBasisEndConditions()
{
    // h₀₀, h₀₁ pick the end values; h₁₀, h₁₁ the end slopes.
    const HermiteBasis start = hermiteBasis(0.0);
    const HermiteBasis end = hermiteBasis(1.0);
    const std::array<double, 4> startValue{1, 0, 0, 0}, endValue{0, 0, 1, 0};
    const std::array<double, 4> startSlope{0, 1, 0, 0}, endSlope{0, 0, 0, 1};
    QCOMPARE(start.value, startValue);
    QCOMPARE(end.value, endValue);
    QCOMPARE(start.first, startSlope);
    QCOMPARE(end.first, endSlope);
    for (double u = 0.0; u <= 1.0; u += 0.125) {
        const HermiteBasis b = hermiteBasis(u);
        QVERIFY(std::abs(b.value[0] + b.value[2] - 1.0) < 1e-15); // a constant stays constant
    }
}

void TestPositionCurve::hermiteBasisDerivativesMatchFiniteDifferences()
{
    const double h = 1e-5;
    for (double u = 0.05; u < 1.0; u += 0.1) {
        const HermiteBasis b = hermiteBasis(u);
        const HermiteBasis after = hermiteBasis(u + h);
        const HermiteBasis before = hermiteBasis(u - h);
        for (std::size_t n = 0; n < 4; ++n) {
            QVERIFY(std::abs((after.value[n] - before.value[n]) / (2 * h) - b.first[n]) < 1e-9);
            QVERIFY(std::abs((after.first[n] - before.first[n]) / (2 * h) - b.second[n]) < 1e-9);
        }
    }
}

void TestPositionCurve::linearCurveIsPiecewiseLinear()
{
    Random random(41);
    const std::vector<PositionKey> keys = randomKeys(random, 6);
    const PositionCurve curve(keys, PositionCurve::Shape::Linear);
    for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
        for (double u : {0.0, 0.3, 0.5, 0.9}) {
            const double t = keys[i].time + u * (keys[i + 1].time - keys[i].time);
            const Eigen::Vector3d expected = keys[i].position + u * (keys[i + 1].position - keys[i].position);
            GYRE_CHECK((curve.at(t) - expected).norm() < 1e-12, str(t));
        }
    }
}

void TestPositionCurve::cubicCurvePassesThroughKeysWithCentralSlopes()
{
    Random random(42);
    const std::vector<PositionKey> keys = randomKeys(random, 7);
    const PositionCurve curve(keys, PositionCurve::Shape::Cubic);
    const double h = 1e-6;
    for (std::size_t i = 0; i < keys.size(); ++i) {
        GYRE_CHECK((curve.at(keys[i].time) - keys[i].position).norm() < 1e-12, str(keys[i].time));
        if (i == 0 || i + 1 == keys.size())
            continue;
        // Continuous slope at an interior key, equal to (pᵢ₊₁ − pᵢ₋₁)/(tᵢ₊₁ − tᵢ₋₁).
        const Eigen::Vector3d slope =
            (keys[i + 1].position - keys[i - 1].position) / (keys[i + 1].time - keys[i - 1].time);
        const Eigen::Vector3d left = (curve.at(keys[i].time) - curve.at(keys[i].time - h)) / h;
        const Eigen::Vector3d right = (curve.at(keys[i].time + h) - curve.at(keys[i].time)) / h;
        GYRE_CHECK((left - slope).norm() < 1e-4 && (right - slope).norm() < 1e-4,
                   str(slope) + " " + str(left) + " " + str(right));
    }
}

void TestPositionCurve::cubicCurveReproducesStraightMotion()
{
    // For p(t) = a + b·t every slope estimate is exactly b, and the cubic is the line itself.
    Random random(43);
    const Eigen::Vector3d a = random.vector(3.0);
    const Eigen::Vector3d b = random.vector(2.0);
    std::vector<PositionKey> keys;
    for (double t : {0.0, 0.4, 1.5, 1.7, 3.0})
        keys.push_back({t, a + b * t});
    const PositionCurve curve(keys, PositionCurve::Shape::Cubic);
    for (double t = 0.0; t <= 3.0; t += 0.07)
        GYRE_CHECK((curve.at(t) - (a + b * t)).norm() < 1e-12, str(t));
}

void TestPositionCurve::holdsOutsideTheKeys()
{
    const std::vector<PositionKey> keys{{1.0, {1, 2, 3}}, {2.0, {4, 5, 6}}};
    for (auto shape : {PositionCurve::Shape::Linear, PositionCurve::Shape::Cubic}) {
        const PositionCurve curve(keys, shape);
        QCOMPARE(curve.at(-5.0), keys.front().position);
        QCOMPARE(curve.at(7.0), keys.back().position);
    }
}

// velocity() against central differences of at() inside the spans, both shapes; zero outside the keys.
void TestPositionCurve::velocityIsTheDerivativeOfThePosition()
{
    Random random(11);
    const std::vector<PositionKey> keys = randomKeys(random, 7);
    for (auto shape : {PositionCurve::Shape::Linear, PositionCurve::Shape::Cubic}) {
        const PositionCurve curve(keys, shape);
        for (std::size_t i = 0; i + 1 < keys.size(); ++i)
            for (const double u : {0.01, 0.3, 0.5, 0.77, 0.99}) {
                const double t = keys[i].time + u * (keys[i + 1].time - keys[i].time);
                const double h = 1e-6;
                const Eigen::Vector3d difference = (curve.at(t + h) - curve.at(t - h)) / (2 * h);
                GYRE_CHECK((curve.velocity(t) - difference).norm() < 1e-6 * (1 + difference.norm()),
                           QStringLiteral("span %1, u = %2").arg(i).arg(u));
            }
        QCOMPARE(curve.velocity(keys.front().time - 1.0), Eigen::Vector3d::Zero());
        QCOMPARE(curve.velocity(keys.back().time + 1.0), Eigen::Vector3d::Zero());
    }
    // At a key the cubic's velocity is its central slope (pᵢ₊₁ − pᵢ₋₁)/(tᵢ₊₁ − tᵢ₋₁), from either span.
    const PositionCurve cubic(keys, PositionCurve::Shape::Cubic);
    const Eigen::Vector3d slope = (keys[3].position - keys[1].position) / (keys[3].time - keys[1].time);
    QVERIFY((cubic.velocity(keys[2].time) - slope).norm() < 1e-12 * (1 + slope.norm()));
}

void TestPositionCurve::rejectsBadKeys()
{
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, PositionCurve({}, PositionCurve::Shape::Linear));
    const std::vector<PositionKey> repeated{{1.0, {0, 0, 0}}, {1.0, {1, 0, 0}}};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, PositionCurve(repeated, PositionCurve::Shape::Cubic));
}

QTEST_APPLESS_MAIN(TestPositionCurve)
#include "tst_position_curve.moc"
