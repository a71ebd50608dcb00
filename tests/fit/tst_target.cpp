// The fit's targets: ω samples, the sketch (direction on the sphere times magnitude), spreading a
// direction curve by arc length, and a pattern repeated along it. Expected values come from
// elementary geometry written here.

#include "fit/angular_velocity_target.h"

#include <Eigen/Geometry>
#include <QTest>

#include <cmath>
#include <random>
#include <vector>
#include <numbers>

using namespace gyre::fit;

namespace {

Eigen::Vector3d unitAt(double longitude, double latitude)
{
    return {std::cos(latitude) * std::cos(longitude), std::cos(latitude) * std::sin(longitude), std::sin(latitude)};
}

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
}

} // namespace

class TestFitTarget : public QObject {
    Q_OBJECT

private slots:
    void samplesAreLinearBetweenThemselves();
    void sketchIsMagnitudeTimesDirectionAlongGreatArcs();
    void sketchRefusesWhatHasNoMeaning();
    void spreadFollowsArcLength();
    void patternRepeatsAlongTheCurve();
    void readerGivesTheTargetsValues();
};

void TestFitTarget::samplesAreLinearBetweenThemselves()
{
    const AngularVelocityTarget target =
        AngularVelocityTarget::fromSamples({{0.0, {1.0, 0.0, 0.0}}, {2.0, {3.0, -2.0, 4.0}}});
    QCOMPARE(target.startTime(), 0.0);
    QCOMPARE(target.endTime(), 2.0);
    QVERIFY((target.at(0.5) - Eigen::Vector3d(1.5, -0.5, 1.0)).norm() < 1e-15);
    QVERIFY((target.at(-1.0) - Eigen::Vector3d(1.0, 0.0, 0.0)).norm() < 1e-15);  // clamped
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, AngularVelocityTarget::fromSamples({{0.0, {1, 0, 0}}}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             AngularVelocityTarget::fromSamples({{1.0, {1, 0, 0}}, {1.0, {1, 0, 0}}}));
}

void TestFitTarget::sketchIsMagnitudeTimesDirectionAlongGreatArcs()
{
    // A quarter turn of direction from x to y over [0, 1], magnitude 2 → 4 over [0, 2].
    const AngularVelocityTarget target = AngularVelocityTarget::fromSketch(
        {{0.0, Eigen::Vector3d::UnitX()}, {1.0, Eigen::Vector3d::UnitY()}}, {{0.0, 2.0}, {2.0, 4.0}});
    QCOMPARE(target.startTime(), 0.0);
    QCOMPARE(target.endTime(), 1.0);  // the overlap of the two curves
    for (const double t : {0.0, 0.2, 0.5, 0.9, 1.0}) {
        const Eigen::Vector3d omega = target.at(t);
        const double magnitude = 2.0 + t;
        const Eigen::Vector3d direction(std::cos(t * std::numbers::pi / 2), std::sin(t * std::numbers::pi / 2), 0.0);
        QVERIFY2((omega - magnitude * direction).norm() < 1e-14, qPrintable(QString::number(t)));
    }
}

void TestFitTarget::sketchRefusesWhatHasNoMeaning()
{
    const std::vector<TimedScalar> magnitude{{0.0, 1.0}, {1.0, 1.0}};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,  // opposite directions: no single arc
                             AngularVelocityTarget::fromSketch({{0.0, {0, 0, 1}}, {1.0, {0, 0, -1}}}, magnitude));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,  // zero direction
                             AngularVelocityTarget::fromSketch({{0.0, {0, 0, 0}}, {1.0, {0, 0, 1}}}, magnitude));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,  // a magnitude of zero has no direction
                             AngularVelocityTarget::fromSketch({{0.0, {0, 0, 1}}, {1.0, {0, 1, 0}}},
                                                               {{0.0, 1.0}, {1.0, 0.0}}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,  // no overlap in time
                             AngularVelocityTarget::fromSketch({{0.0, {0, 0, 1}}, {1.0, {0, 1, 0}}},
                                                               {{2.0, 1.0}, {3.0, 1.0}}));
}

void TestFitTarget::spreadFollowsArcLength()
{
    const std::vector<Eigen::Vector3d> points{unitAt(0.0, 0.0), unitAt(0.3, 0.0), unitAt(0.3, 0.0),
                                              unitAt(0.3, 0.9)};
    const std::vector<TimedVector> timed = spreadByArcLength(points, 1.0, 2.2);
    QCOMPARE(timed.size(), std::size_t{3});  // the repeated point is dropped
    QCOMPARE(timed.front().time, 1.0);
    QCOMPARE(timed.back().time, 2.2);
    QVERIFY(std::abs(timed[1].time - (1.0 + 1.2 * 0.3 / 1.2)) < 1e-14);  // 0.3 of 1.2 radians
    const std::vector<TimedVector> still = spreadByArcLength({unitAt(1.0, 0.2)}, 0.0, 3.0);
    QCOMPARE(still.size(), std::size_t{2});
    QCOMPARE(still.back().time, 3.0);
    QVERIFY((still.back().value - unitAt(1.0, 0.2)).norm() < 1e-15);
}

void TestFitTarget::patternRepeatsAlongTheCurve()
{
    // Along the equator from longitude 0 to 1.2 rad over [0, 6] s, a triangle of width 2 and height
    // 0.5 (pattern units) repeated 3 times: each repetition spans 0.4 rad, so the scale is 0.2 rad per
    // unit and the peaks stand 0.1 rad off the equator, at longitudes 0.2, 0.6 and 1.0.
    const std::vector<TimedVector> equator{{0.0, unitAt(0.0, 0.0)}, {6.0, unitAt(1.2, 0.0)}};
    const std::vector<Eigen::Vector2d> triangle{{0.0, 0.0}, {1.0, 0.5}, {2.0, 0.0}};
    const std::vector<TimedVector> patterned = applyPattern(equator, triangle, 3);
    QCOMPARE(patterned.size(), std::size_t{7});
    for (std::size_t i = 0; i < patterned.size(); ++i) {
        QVERIFY(std::abs(patterned[i].value.norm() - 1.0) < 1e-14);
        if (i > 0)
            QVERIFY(patterned[i].time > patterned[i - 1].time);
        const double latitude = std::asin(patterned[i].value.z());
        const double longitude = std::atan2(patterned[i].value.y(), patterned[i].value.x());
        QVERIFY2(std::abs(longitude - 0.2 * static_cast<double>(i)) < 1e-12, qPrintable(QString::number(i)));
        const double expectedLatitude = i % 2 == 1 ? 0.1 : 0.0;  // the equator's left is north
        QVERIFY2(std::abs(latitude - expectedLatitude) < 1e-12, qPrintable(QString::number(latitude)));
        // Time advances with the pattern's drawn length, here evenly: 1 s per stroke of the triangle.
        QVERIFY(std::abs(patterned[i].time - static_cast<double>(i)) < 1e-12);
    }
    QVERIFY(angleBetween(patterned.back().value, unitAt(1.2, 0.0)) < 1e-12);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, applyPattern(equator, {{0.0, 0.0}, {0.0, 1.0}}, 2));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, applyPattern(equator, triangle, 0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, applyPattern({{0.0, unitAt(0.0, 0.0)}}, triangle, 2));
    // An arc of no length inside the curve borrows its neighbour's sideways direction.
    const std::vector<TimedVector> withPause{
        {0.0, unitAt(0.0, 0.0)}, {1.0, unitAt(0.0, 0.0)}, {6.0, unitAt(1.2, 0.0)}};
    for (const TimedVector& point : applyPattern(withPause, triangle, 3))
        QVERIFY(point.value.allFinite() && std::abs(point.value.norm() - 1.0) < 1e-14);
}

// The fit reads the target through a Reader, in order; its values must be at()'s to the bit, for
// sampled and sketched targets, read forward in small and large steps and backward.
void TestFitTarget::readerGivesTheTargetsValues()
{
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> gap(0.001, 0.02);
    std::normal_distribution<double> normal;
    std::vector<TimedVector> samples{{0.0, {1.0, 0.0, 0.0}}};
    std::vector<TimedScalar> magnitudes{{0.0, 1.0}};
    while (samples.back().time < 20.0) {
        const Eigen::Vector3d previous = samples.back().value;
        samples.push_back({samples.back().time + gap(rng),
                           (previous + 0.05 * Eigen::Vector3d(normal(rng), normal(rng), normal(rng))).normalized()});
        magnitudes.push_back({magnitudes.back().time + 3.0 * gap(rng), 1.0 + std::abs(normal(rng))});
    }
    const AngularVelocityTarget sampled = AngularVelocityTarget::fromSamples(samples);
    const AngularVelocityTarget sketched = AngularVelocityTarget::fromSketch(samples, magnitudes);
    for (const AngularVelocityTarget* target : {&sampled, &sketched}) {
        AngularVelocityTarget::Reader reader(*target);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        double time = -1.0;
        for (int i = 0; i < 20000; ++i) {
            const double choice = unit(rng);
            time += choice < 0.8 ? 0.004 * unit(rng) : choice < 0.9 ? 2.0 * unit(rng) : -1.0 * unit(rng);
            if (time > 21.0)
                time = -0.5;
            const Eigen::Vector3d expected = target->at(time);
            QCOMPARE(reader.at(time), expected);
        }
    }
}

QTEST_GUILESS_MAIN(TestFitTarget)
#include "tst_target.moc"
