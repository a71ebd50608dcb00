// The free flight between keys (flight_shooting.h, ballistic_flight.h), checked by what must hold: every
// offered solution meets the end key, solutions are distinct and ordered by kinetic energy, a flight made by
// the forward motion is found again from its two ends, angular momentum and energy stay constant over each
// span, and the centre of mass falls on the parabola through the keys under gravity.

#include "core/mass_properties.h"
#include "core/torque_free.h"
#include "fit/ballistic_flight.h"
#include "fit/flight_shooting.h"

#include "core/core_test_support.h"
#include "core/rigid_body_test_support.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

using namespace gyre;
using namespace gyre::fit;
using gyre::test::angleBetween;
using gyre::test::differencedAngularVelocity;
using gyre::test::momentumOf;
using gyre::test::rotatedInertia;

namespace {

Eigen::Quaterniond randomRotation(std::mt19937_64& rng)
{
    std::normal_distribution<double> normal;
    return Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
}

} // namespace

class TestFlight : public QObject {
    Q_OBJECT

private slots:
    void everySolutionMeetsTheEndKey();
    void findsTheFlightThatMadeTheKeys();
    void conservedOverEverySpan();
    void centreOfMassFollowsTheParabola();
    void choicesPickSolutions();
    void rememberedSpansGiveWhatASolveGives();
    void movingAKeySolvesOnlyItsSpans();
    void refusesBadInput();
};

void TestFlight::everySolutionMeetsTheEndKey()
{
    std::mt19937_64 rng(5);
    for (int trial = 0; trial < 2; ++trial) {
        const FlightSpan span{rotatedInertia({0.4, 0.9, 1.3}, randomRotation(rng)), randomRotation(rng),
                              randomRotation(rng), 0.6 + 0.5 * trial};
        const std::vector<FlightSolution> solutions = solveFlight(span);
        QVERIFY(!solutions.empty());
        QVERIFY(solutions.size() <= kMaxFlightSolutions);
        for (std::size_t i = 0; i < solutions.size(); ++i) {
            const TorqueFreeMotion motion(span.inertia, span.start, solutions[i].startAngularVelocity, span.duration);
            QVERIFY(angleBetween(motion.orientation(0.0), span.start) < 1e-12);
            const double error = angleBetween(motion.orientation(span.duration), span.end);
            QVERIFY2(error <= 1e-10, qPrintable(QStringLiteral("solution %1 misses by %2 rad").arg(i).arg(error)));
            QVERIFY(std::abs(solutions[i].kineticEnergy - motion.kineticEnergy()) <= 1e-12 * motion.kineticEnergy());
            if (i > 0) {
                QVERIFY(solutions[i - 1].kineticEnergy <= solutions[i].kineticEnergy);
                QVERIFY((solutions[i - 1].startAngularVelocity - solutions[i].startAngularVelocity).norm() > 1e-6);
            }
        }
    }
}

void TestFlight::findsTheFlightThatMadeTheKeys()
{
    // A T-handle's flight (moments 1 < 2 < 3, spun about the intermediate axis y with a small disturbance) run
    // forward for 2 s, through one flip of its y axis against L: the keys are its two ends, the hint its
    // start ω a little off, as an artist's keyed motion would be. The solution nearest the hint is the flight.
    const Eigen::Matrix3d inertia = inertiaTensor({1.0, 2.0, 3.0});
    const Eigen::Vector3d omega(0.3, 6.0, 0.3);
    const double duration = 2.0;
    const TorqueFreeMotion made(inertia, Eigen::Quaterniond::Identity(), omega, duration);
    const Eigen::Vector3d along = made.angularMomentum().normalized();
    double least = 1.0;
    for (double t = 0.0; t <= duration; t += 0.01)
        least = std::min(least, (made.orientation(t) * Eigen::Vector3d::UnitY()).dot(along));
    QVERIFY2(least < -0.9, qPrintable(QStringLiteral("the made flight does not flip (%1)").arg(least)));

    const FlightSpan span{inertia, Eigen::Quaterniond::Identity(), made.orientation(duration), duration};
    const Eigen::Vector3d hint = omega + Eigen::Vector3d(0.3, -0.2, 0.1);
    const std::vector<FlightSolution> solutions = solveFlight(span, hint);
    const FlightSolution& nearest = solutions[nearestFlightSolution(solutions, hint)];
    QVERIFY2((nearest.startAngularVelocity - omega).norm() < 1e-6,
             qPrintable(QStringLiteral("nearest solution off by %1 rad/s")
                            .arg((nearest.startAngularVelocity - omega).norm())));
}

void TestFlight::conservedOverEverySpan()
{
    std::mt19937_64 rng(17);
    const Eigen::Matrix3d inertia = rotatedInertia({0.2, 0.5, 0.6}, randomRotation(rng));
    std::vector<FlightKey> keys;
    for (int i = 0; i < 3; ++i)
        keys.push_back({0.7 * i, {randomRotation(rng), Eigen::Vector3d(i, 0.5 * i, 1.0)}});
    const BallisticFlight flight(keys, {inertia, Eigen::Vector3d(0.1, 0.0, -0.05), 9.81, Eigen::Vector3d::UnitZ()});
    QCOMPARE(flight.spans().size(), std::size_t(2));
    for (std::size_t s = 0; s < 2; ++s) {
        const double t0 = keys[s].time, t1 = keys[s + 1].time;
        QVERIFY(angleBetween(flight.at(t0).orientation, keys[s].pose.orientation) < 1e-10);
        QVERIFY(angleBetween(flight.at(t1 - 1e-12).orientation, keys[s + 1].pose.orientation) < 1e-10);
        const double mid = 0.5 * (t0 + t1);
        const auto orientationAt = [&](double t) { return flight.at(t).orientation; };
        const Eigen::Vector3d w0 = differencedAngularVelocity(orientationAt, mid);
        const Eigen::Vector3d l0 = momentumOf(inertia, flight.at(mid).orientation, w0);
        const double e0 = 0.5 * l0.dot(w0);
        for (double t = t0 + 1e-3; t < t1; t += 0.0137) {
            const Eigen::Vector3d w = differencedAngularVelocity(orientationAt, t);
            const Eigen::Vector3d l = momentumOf(inertia, flight.at(t).orientation, w);
            QVERIFY(std::abs(l.norm() - l0.norm()) <= 1e-9 * l0.norm());
            QVERIFY(l.normalized().cross(l0.normalized()).norm() <= 1e-9);
            QVERIFY(std::abs(0.5 * l.dot(w) - e0) <= 1e-9 * e0);
        }
    }
}

void TestFlight::centreOfMassFollowsTheParabola()
{
    std::mt19937_64 rng(29);
    const Eigen::Vector3d centre(0.2, -0.1, 0.3);
    const Eigen::Vector3d up = Eigen::Vector3d(0.0, 1.0, 0.0);
    const std::vector<FlightKey> keys{{0.0, {randomRotation(rng), Eigen::Vector3d(0, 0, 0)}},
                                      {1.0, {randomRotation(rng), Eigen::Vector3d(2, 1, 0)}}};
    const BallisticFlight flight(keys, {inertiaTensor({1.0, 1.5, 2.0}), centre, 3.7, up});
    const auto centreAt = [&](double t) { return flight.at(t).apply(centre); };
    QVERIFY((centreAt(0.0) - keys[0].pose.apply(centre)).norm() < 1e-12);
    QVERIFY((centreAt(1.0 - 1e-13) - keys[1].pose.apply(centre)).norm() < 1e-9);
    const double h = 1e-3;
    for (double t = 0.1; t < 0.95; t += 0.1) {
        const Eigen::Vector3d acceleration = (centreAt(t + h) - 2.0 * centreAt(t) + centreAt(t - h)) / (h * h);
        QVERIFY2((acceleration + 3.7 * up).norm() < 1e-5,
                 qPrintable(QStringLiteral("acceleration %1 %2 %3").arg(acceleration.x()).arg(acceleration.y()).arg(acceleration.z())));
    }
}

void TestFlight::choicesPickSolutions()
{
    std::mt19937_64 rng(41);
    const std::vector<FlightKey> keys{{0.0, {randomRotation(rng), Eigen::Vector3d::Zero()}}, {0.8, {randomRotation(rng), Eigen::Vector3d::Zero()}}};
    const FlightBody body{inertiaTensor({0.5, 1.0, 1.4})};
    const BallisticFlight byDefault(keys, body);
    const std::size_t count = byDefault.spans()[0].solutions.size();
    QVERIFY(count >= 2);
    for (const std::size_t k : {std::size_t(1), count}) {  // the second, and past the last: wraps to the first
        const BallisticFlight chosen(keys, body, {k});
        QCOMPARE(chosen.spans()[0].chosen, k % count);
        const Eigen::Vector3d expected = chosen.spans()[0].solutions[k % count].startAngularVelocity;
        QVERIFY((chosen.spans()[0].motion.angularVelocity(0.0) - expected).norm() < 1e-6 * expected.norm());
    }
}

void TestFlight::rememberedSpansGiveWhatASolveGives()
{
    // A span written with a key negated is the same problem (q and −q are one orientation) under other values, so
    // solveFlight does not find it remembered: it solves it afresh. The span is made by a flight of about a turn
    // and a half, which the fixed seeds (at most one extra turn) do not find but its own ω₀ as the hint does.
    std::mt19937_64 rng(53);
    const Eigen::Matrix3d inertia = rotatedInertia({0.6, 1.1, 1.5}, randomRotation(rng));
    const Eigen::Quaterniond start = randomRotation(rng);
    const Eigen::Vector3d hintA(4.0, -9.0, 6.0);
    const double duration = 0.9;
    const FlightSpan span{inertia, start, TorqueFreeMotion(inertia, start, hintA, duration).orientation(duration),
                          duration};
    const auto negated = [&](bool startNegated, bool endNegated) {
        FlightSpan other = span;
        other.start.coeffs() *= startNegated ? -1.0 : 1.0;
        other.end.coeffs() *= endNegated ? -1.0 : 1.0;
        return other;
    };
    const auto finds = [](const std::vector<FlightSolution>& solutions, const Eigen::Vector3d& omega) {
        return std::any_of(solutions.begin(), solutions.end(),
                           [&](const FlightSolution& s) { return (s.startAngularVelocity - omega).norm() < 1e-6; });
    };
    QVERIFY2(!finds(solveFlight(negated(false, true)), hintA), "the fixed seeds alone find the hint's flight");
    QVERIFY2(finds(solveFlight(span, hintA), hintA), "the hint does not find its own flight");

    // Asked again with another hint, the span's fixed seeds are remembered and hint A's flight is not among them.
    const Eigen::Vector3d hintB(-0.5, 0.2, 0.4);
    const FlightCacheStatistics before = flightCacheStatistics();
    const std::vector<FlightSolution> remembered = solveFlight(span, hintB);
    QCOMPARE(flightCacheStatistics().hits, before.hits + 1);
    const std::vector<FlightSolution> solved = solveFlight(negated(true, true), hintB);
    QCOMPARE(flightCacheStatistics().misses, before.misses + 1);
    QVERIFY(!finds(remembered, hintA));
    QCOMPARE(remembered.size(), solved.size());
    for (std::size_t i = 0; i < solved.size(); ++i) {
        QVERIFY((remembered[i].startAngularVelocity - solved[i].startAngularVelocity).norm() <= 1e-12);
        QCOMPARE(remembered[i].kineticEnergy, solved[i].kineticEnergy);
    }
}

void TestFlight::movingAKeySolvesOnlyItsSpans()
{
    // Five keys, four spans; the middle key turned, as a drag does: the two spans it ends are solved again, the
    // other two found remembered.
    std::mt19937_64 rng(61);
    std::vector<FlightKey> keys;
    for (int i = 0; i < 5; ++i)
        keys.push_back({0.6 * i, {randomRotation(rng), Eigen::Vector3d(0.0, 0.0, 1.0)}});
    const FlightBody body{inertiaTensor({0.5, 1.0, 1.4})};
    const BallisticFlight before(keys, body);
    keys[2].pose.orientation =
        keys[2].pose.orientation * Eigen::Quaterniond(Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitZ()));
    const FlightCacheStatistics counted = flightCacheStatistics();
    const BallisticFlight after(keys, body);
    QCOMPARE(flightCacheStatistics().misses, counted.misses + 2);
    QCOMPARE(flightCacheStatistics().hits, counted.hits + 2);
    // The span before the moved key now ends at it; the first span, whose keys and hint did not move, flies as it
    // did.
    const double justBefore = std::nextafter(1.2, 0.0);
    QVERIFY(angleBetween(after.at(justBefore).orientation, keys[2].pose.orientation) < 1e-9);
    QVERIFY(angleBetween(before.at(justBefore).orientation, keys[2].pose.orientation) > 0.04);
    QVERIFY(angleBetween(after.at(0.3).orientation, before.at(0.3).orientation) == 0.0);
}

void TestFlight::refusesBadInput()
{
    const FlightBody body{inertiaTensor({0.5, 1.0, 1.4})};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, BallisticFlight({{0.0, Pose{}}}, body));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, BallisticFlight({{0.0, Pose{}}, {0.0, Pose{}}}, body));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, BallisticFlight({{0.0, Pose{}}, {1.0, Pose{}}}, {inertiaTensor({1, 1, -1})}));
    FlightBody noUp = body;
    noUp.up = Eigen::Vector3d::Zero();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, BallisticFlight({{0.0, Pose{}}, {1.0, Pose{}}}, noUp));
    const Eigen::Quaterniond notFinite(std::nan(""), 0.0, 0.0, 1.0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             solveFlight({body.inertia, Eigen::Quaterniond::Identity(), notFinite, 1.0}));
}

QTEST_APPLESS_MAIN(TestFlight)
#include "tst_flight.moc"
