// ScrewBender's Split&Tweak polyscrew subdivision (subdivision.h). Pure translations must reproduce
// the linear masks of the paper, implemented independently here (with the ghost points
// 2p₀ − p₁ and 2pₙ₋₁ − pₙ₋₂ at each level for open sequences); poses sampled along one screw stay on
// it, at the parameters the linear masks give; a cyclic circular motion stays on its circle (the
// paper's Fig. 11a) while the decoupled alternative leaves it (Fig. 11b).

#include "core/subdivision.h"

#include "core_test_support.h"

#include <QObject>
#include <QTest>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

using namespace gyre;
using namespace gyre::test;

namespace {

const SubdivisionScheme kSchemes[] = {SubdivisionScheme::FourPoint, SubdivisionScheme::FourPointB, SubdivisionScheme::BSpline,
                                      SubdivisionScheme::Jarek};

QString schemeName(SubdivisionScheme s) { return QString::fromLatin1(subdivisionSchemeName(s).data(), qsizetype(subdivisionSchemeName(s).size())); }

// One level of the linear scheme on points.
std::vector<Eigen::Vector3d> linearStep(const std::vector<Eigen::Vector3d>& p, SubdivisionScheme scheme, bool cyclic)
{
    const long n = long(p.size());
    auto at = [&](long i) -> Eigen::Vector3d {
        if (cyclic)
            return p[std::size_t(((i % n) + n) % n)];
        if (i < 0)
            return 2.0 * p[0] - p[1];
        if (i >= n)
            return 2.0 * p[std::size_t(n - 1)] - p[std::size_t(n - 2)];
        return p[std::size_t(i)];
    };
    auto oldRule = [&](long i) -> Eigen::Vector3d {
        switch (scheme) {
        case SubdivisionScheme::BSpline:
            return (at(i - 1) + 6.0 * at(i) + at(i + 1)) / 8.0;
        case SubdivisionScheme::Jarek:
            return (2.0 * at(i - 1) + 28.0 * at(i) + 2.0 * at(i + 1)) / 32.0;
        default:
            return at(i);
        }
    };
    auto newRule = [&](long i) -> Eigen::Vector3d {
        switch (scheme) {
        case SubdivisionScheme::BSpline:
            return (at(i) + at(i + 1)) / 2.0;
        case SubdivisionScheme::Jarek:
            return (-at(i - 1) + 17.0 * at(i) + 17.0 * at(i + 1) - at(i + 2)) / 32.0;
        default:
            return (-at(i - 1) + 9.0 * at(i) + 9.0 * at(i + 1) - at(i + 2)) / 16.0;
        }
    };
    std::vector<Eigen::Vector3d> q;
    for (long i = 0; i < n; ++i) {
        q.push_back(oldRule(i));
        if (cyclic || i + 1 < n)
            q.push_back(newRule(i));
    }
    return q;
}

std::vector<Eigen::Vector3d> linearSubdivision(std::vector<Eigen::Vector3d> p, SubdivisionScheme scheme, bool cyclic, int levels)
{
    for (int l = 0; l < levels; ++l)
        p = linearStep(p, scheme, cyclic);
    return p;
}

std::vector<Eigen::Vector3d> positionsOf(const std::vector<Pose>& poses)
{
    std::vector<Eigen::Vector3d> p;
    for (const Pose& pose : poses)
        p.push_back(pose.position);
    return p;
}

std::size_t expectedCount(std::size_t n, int levels, bool cyclic)
{
    return cyclic ? n << levels : ((n - 1) << levels) + 1;
}

SubdivisionSettings settingsFor(SubdivisionScheme scheme, int levels, bool cyclic, bool decoupled = false)
{
    SubdivisionSettings s;
    s.scheme = scheme;
    s.levels = levels;
    s.cyclic = cyclic;
    s.decoupled = decoupled;
    return s;
}

QString settingsLabel(const SubdivisionSettings& s)
{
    return QStringLiteral("%1, %2 levels, %3%4").arg(schemeName(s.scheme)).arg(s.levels).arg(s.cyclic ? QStringLiteral("cyclic") : QStringLiteral("open"),
                                                                                         s.decoupled ? QStringLiteral(", decoupled") : QString());
}

// Random poses whose neighbours differ by at most `maxAngle` of rotation.
std::vector<Pose> randomWalk(Random& random, std::size_t n, double maxAngle, double step)
{
    std::vector<Pose> poses;
    Pose p = random.pose(3.0);
    for (std::size_t i = 0; i < n; ++i) {
        poses.push_back(p);
        p.orientation = random.rotationWithAngle(0.0, maxAngle) * p.orientation;
        p.position += random.vector(step);
    }
    return poses;
}

} // namespace

class TestSubdivision : public QObject {
    Q_OBJECT

private slots:
    void schemeNames();
    void linearMasksOfTheTest();
    void pureTranslationsReproduceLinearMasks_data();
    void pureTranslationsReproduceLinearMasks();
    void counts();
    void interpolatingSchemesKeepControlPoses();
    void openSequencesKeepTheirEnds();
    void posesOnOneScrewStayOnIt_data();
    void posesOnOneScrewStayOnIt();
    void circularMotionStaysOnItsCircle_data();
    void circularMotionStaysOnItsCircle();
    void decoupledPositionsFollowLinearMasks();
    void decoupledCircularMotionLeavesTheCircle();
    void zeroLevelsReturnTheInput();
    void invalidLevelsThrow();
    void subdividedPoseCountOverflow();
    void subdividerReuseGivesIdenticalResults();
};

void TestSubdivision::schemeNames()
{
    for (SubdivisionScheme s : kSchemes) {
        const std::optional<SubdivisionScheme> parsed = parseSubdivisionScheme(subdivisionSchemeName(s));
        QVERIFY2(parsed.has_value() && *parsed == s, qPrintable(schemeName(s)));
    }
    QVERIFY(!parseSubdivisionScheme("").has_value());
    QVERIFY(!parseSubdivisionScheme("loop").has_value());
}

void TestSubdivision::linearMasksOfTheTest()
{
    // The test's masks themselves: each reproduces linear sequences (and the four-point ones keep
    // old points), and open sequences keep their ends thanks to the ghost points.
    for (SubdivisionScheme s : kSchemes) {
        std::vector<Eigen::Vector3d> line;
        for (int i = 0; i < 5; ++i)
            line.emplace_back(1.0 + 2.0 * i, -3.0 * i, 0.5);
        const std::vector<Eigen::Vector3d> q = linearStep(line, s, false);
        QCOMPARE(q.size(), std::size_t(9));
        for (std::size_t j = 0; j < q.size(); ++j) {
            const Eigen::Vector3d expected(1.0 + 1.0 * double(j), -1.5 * double(j), 0.5);
            QVERIFY2((q[j] - expected).norm() < 1e-14, qPrintable(schemeName(s)));
        }
        // On a cycle every mask's weights sum to one: a constant sequence stays put.
        const std::vector<Eigen::Vector3d> constant(4, Eigen::Vector3d(1.0, 2.0, 3.0));
        for (const Eigen::Vector3d& c : linearStep(constant, s, true))
            QVERIFY((c - constant[0]).norm() < 1e-15);
    }
    // The four-point odd mask reproduces cubics: x³ sampled at integers gives (i + 1/2)³ at the
    // midpoints.
    std::vector<Eigen::Vector3d> cubic;
    for (int i = 0; i < 8; ++i)
        cubic.emplace_back(double(i * i * i), 0.0, 0.0);
    const std::vector<Eigen::Vector3d> q = linearStep(cubic, SubdivisionScheme::FourPoint, false);
    for (int i = 1; i + 2 < 8; ++i)
        QVERIFY(std::abs(q[std::size_t(2 * i + 1)].x() - std::pow(i + 0.5, 3.0)) < 1e-12);
}

void TestSubdivision::pureTranslationsReproduceLinearMasks_data()
{
    QTest::addColumn<int>("scheme");
    QTest::addColumn<bool>("cyclic");
    for (SubdivisionScheme s : kSchemes) {
        for (bool cyclic : {true, false})
            QTest::newRow(qPrintable(QStringLiteral("%1 %2").arg(schemeName(s), cyclic ? QStringLiteral("cyclic") : QStringLiteral("open"))))
                << int(s) << cyclic;
    }
}

void TestSubdivision::pureTranslationsReproduceLinearMasks()
{
    QFETCH(int, scheme);
    QFETCH(bool, cyclic);
    Random random(100 + std::uint64_t(scheme) * 2 + (cyclic ? 1 : 0));
    for (std::size_t n : {std::size_t(2), std::size_t(3), std::size_t(6)}) {
        if (cyclic && n < 3)
            continue;
        for (bool identity : {true, false}) {
            // All poses with one orientation: every screw between them is a pure translation.
            const Eigen::Quaterniond orientation = identity ? Eigen::Quaterniond::Identity() : random.rotation();
            std::vector<Pose> poses;
            for (std::size_t i = 0; i < n; ++i)
                poses.push_back({orientation, random.vector(10.0)});
            for (int levels : {1, 2, 3, 4}) {
                const SubdivisionSettings settings = settingsFor(SubdivisionScheme(scheme), levels, cyclic);
                const std::vector<Pose> out = subdividePolyscrew(poses, settings);
                const std::vector<Eigen::Vector3d> expected = linearSubdivision(positionsOf(poses), settings.scheme, cyclic, levels);
                const QString label = QStringLiteral("%1, %2 poses, %3 orientation").arg(settingsLabel(settings)).arg(n).arg(identity ? "identity" : "common");
                GYRE_CHECK(out.size() == expected.size(), QStringLiteral("%1: %2 poses, expected %3").arg(label).arg(out.size()).arg(expected.size()));
                for (std::size_t j = 0; j < out.size(); ++j) {
                    GYRE_CHECK((out[j].position - expected[j]).norm() < 1e-12 * (1.0 + expected[j].norm()),
                               QStringLiteral("%1: pose %2 at %3, linear mask gives %4").arg(label).arg(j).arg(str(out[j].position), str(expected[j])));
                    GYRE_CHECK(distanceUpToSign(out[j].orientation, orientation) < 1e-14,
                               QStringLiteral("%1: pose %2 turned to %3").arg(label).arg(j).arg(str(out[j].orientation)));
                }
            }
        }
    }
}

void TestSubdivision::counts()
{
    Random random(110);
    for (SubdivisionScheme s : kSchemes) {
        for (bool cyclic : {true, false}) {
            for (std::size_t n : {std::size_t(2), std::size_t(3), std::size_t(7)}) {
                const std::vector<Pose> poses = randomWalk(random, n, 1.0, 1.0);
                for (int levels : {0, 1, 3}) {
                    const SubdivisionSettings settings = settingsFor(s, levels, cyclic);
                    const std::size_t expected = expectedCount(n, levels, cyclic);
                    const std::optional<std::size_t> predicted = subdividedPoseCount(n, levels, cyclic);
                    QVERIFY2(predicted.has_value() && *predicted == expected, qPrintable(settingsLabel(settings)));
                    QVERIFY2(subdividePolyscrew(poses, settings).size() == expected,
                             qPrintable(QStringLiteral("%1, %2 poses").arg(settingsLabel(settings)).arg(n)));
                }
            }
        }
    }
}

void TestSubdivision::interpolatingSchemesKeepControlPoses()
{
    Random random(111);
    for (SubdivisionScheme s : {SubdivisionScheme::FourPoint, SubdivisionScheme::FourPointB}) {
        for (bool cyclic : {true, false}) {
            for (bool decoupled : {false, true}) {
                const std::vector<Pose> poses = randomWalk(random, 7, 1.0, 2.0);
                for (int levels : {1, 2, 3, 4}) {
                    const SubdivisionSettings settings = settingsFor(s, levels, cyclic, decoupled);
                    const std::vector<Pose> out = subdividePolyscrew(poses, settings);
                    for (std::size_t i = 0; i < poses.size(); ++i) {
                        const Pose& image = out[i << levels];
                        GYRE_CHECK(poseDistance(image, poses[i]) < 1e-12,
                                   QStringLiteral("%1: pose %2 became %3, control %4").arg(settingsLabel(settings)).arg(i << levels).arg(str(image), str(poses[i])));
                    }
                }
            }
        }
    }
}

void TestSubdivision::openSequencesKeepTheirEnds()
{
    Random random(112);
    for (SubdivisionScheme s : kSchemes) {
        for (bool decoupled : {false, true}) {
            for (std::size_t n : {std::size_t(2), std::size_t(3), std::size_t(6)}) {
                const std::vector<Pose> poses = randomWalk(random, n, 1.2, 2.0);
                for (int levels : {1, 2, 4}) {
                    const SubdivisionSettings settings = settingsFor(s, levels, false, decoupled);
                    const std::vector<Pose> out = subdividePolyscrew(poses, settings);
                    GYRE_CHECK(poseDistance(out.front(), poses.front()) < 1e-12 && poseDistance(out.back(), poses.back()) < 1e-12,
                               QStringLiteral("%1, %2 poses: ends %3 … %4, control %5 … %6").arg(settingsLabel(settings)).arg(n)
                                   .arg(str(out.front()), str(out.back()), str(poses.front()), str(poses.back())));
                }
            }
        }
    }
}

void TestSubdivision::posesOnOneScrewStayOnIt_data()
{
    QTest::addColumn<int>("scheme");
    for (SubdivisionScheme s : kSchemes)
        QTest::newRow(qPrintable(schemeName(s))) << int(s);
}

void TestSubdivision::posesOnOneScrewStayOnIt()
{
    // Lₖ = Mᵏ·L₀ for a screw motion M (angle r about an axis through C with direction S, slide d).
    // Every screw between such poses is part of the same screw, so every subdivided pose is
    // M^τ·L₀; and since the linear masks reproduce uniform sequences, pose j has τ = j/2^L.
    // (Open sequences: a screw with a slide does not close a cycle; the circle test is the cyclic case.)
    QFETCH(int, scheme);
    Random random(120 + std::uint64_t(scheme));
    for (int trial = 0; trial < 4; ++trial) {
        const Eigen::Vector3d centre = random.vector(4.0);
        const Eigen::Vector3d axis = random.unitVector();
        const double angle = random.uniform(0.15, 0.45); // three steps stay below π for four-point B
        const double slide = trial == 3 ? 0.0 : random.uniform(-1.0, 1.0);
        const Pose start = random.pose(4.0);
        const std::size_t n = 6;
        std::vector<Pose> poses;
        for (std::size_t k = 0; k < n; ++k)
            poses.push_back(helicalMotion(start, centre, axis, double(k) * angle, double(k) * slide));
        for (int levels : {1, 2, 3, 4}) {
            const SubdivisionSettings settings = settingsFor(SubdivisionScheme(scheme), levels, false);
            const std::vector<Pose> out = subdividePolyscrew(poses, settings);
            QCOMPARE(out.size(), expectedCount(n, levels, false));
            for (std::size_t j = 0; j < out.size(); ++j) {
                // Project: τ from the rotation X·L₀⁻¹ about S, then compare the whole pose.
                Eigen::Quaterniond rel = out[j].orientation * start.orientation.conjugate();
                if (rel.w() < 0.0)
                    rel = negated(rel);
                const double tau = 2.0 * std::atan2(rel.vec().dot(axis), rel.w()) / angle;
                const Pose onScrew = helicalMotion(start, centre, axis, tau * angle, tau * slide);
                const QString label = QStringLiteral("%1 trial %2 pose %3").arg(settingsLabel(settings)).arg(trial).arg(j);
                GYRE_CHECK(poseDistance(out[j], onScrew) < 1e-10,
                           QStringLiteral("%1: %2 is off the screw (nearest %3, τ %4)").arg(label, str(out[j]), str(onScrew), str(tau)));
                const double expectedTau = double(j) / double(std::size_t(1) << levels);
                GYRE_CHECK(std::abs(tau - expectedTau) < 1e-10, QStringLiteral("%1: τ %2, expected %3").arg(label, str(tau), str(expectedTau)));
            }
        }
    }
}

void TestSubdivision::circularMotionStaysOnItsCircle_data()
{
    QTest::addColumn<int>("scheme");
    QTest::addColumn<int>("n");
    for (SubdivisionScheme s : kSchemes) {
        for (int n : {4, 8}) {
            // Four-point B forms s(L_a, 1/2, L_d) across three steps: 270° for a square, whose short
            // arc runs the other way (the paper's flip); it is only expected to hold for finer cycles.
            if (s == SubdivisionScheme::FourPointB && n == 4)
                continue;
            QTest::newRow(qPrintable(QStringLiteral("%1 n=%2").arg(schemeName(s)).arg(n))) << int(s) << n;
        }
    }
}

void TestSubdivision::circularMotionStaysOnItsCircle()
{
    // n poses turned about one fixed axis (through a centre off the origin) by 2π/n each, the body
    // off the axis: every subdivided pose is the first one turned about that axis, by 2πj/(n·2^L).
    QFETCH(int, scheme);
    QFETCH(int, n);
    Random random(130 + std::uint64_t(scheme) * 10 + std::uint64_t(n));
    for (int trial = 0; trial < 2; ++trial) {
        const Eigen::Vector3d centre = random.vector(5.0) + Eigen::Vector3d(3.0, 0.0, 0.0);
        const Eigen::Vector3d axis = random.unitVector();
        Pose start;
        start.orientation = random.rotation();
        start.position = centre + 2.5 * axis.unitOrthogonal() + random.uniform(-1.0, 1.0) * axis;
        std::vector<Pose> poses;
        for (int k = 0; k < n; ++k)
            poses.push_back(helicalMotion(start, centre, axis, 2.0 * kPi * k / n, 0.0));
        for (int levels : {1, 2, 3, 4}) {
            const SubdivisionSettings settings = settingsFor(SubdivisionScheme(scheme), levels, true);
            const std::vector<Pose> out = subdividePolyscrew(poses, settings);
            QCOMPARE(out.size(), expectedCount(std::size_t(n), levels, true));
            for (std::size_t j = 0; j < out.size(); ++j) {
                const Eigen::Quaterniond rel = out[j].orientation * start.orientation.conjugate();
                const double theta = 2.0 * std::atan2(rel.vec().dot(axis), rel.w());
                const Pose onCircle = helicalMotion(start, centre, axis, theta, 0.0);
                const QString label = QStringLiteral("%1 trial %2 pose %3").arg(settingsLabel(settings)).arg(trial).arg(j);
                GYRE_CHECK(poseDistance(out[j], onCircle) < 1e-10,
                           QStringLiteral("%1: %2 is off the circle (nearest %3)").arg(label, str(out[j]), str(onCircle)));
                const double expected = 2.0 * kPi * double(j) / double(std::size_t(n) << levels);
                GYRE_CHECK(std::abs(std::remainder(theta - expected, 2.0 * kPi)) < 1e-10,
                           QStringLiteral("%1: turned by %2, expected %3").arg(label, str(theta), str(expected)));
            }
        }
    }
}

void TestSubdivision::decoupledPositionsFollowLinearMasks()
{
    Random random(140);
    for (SubdivisionScheme s : kSchemes) {
        for (bool cyclic : {true, false}) {
            const std::vector<Pose> poses = randomWalk(random, 6, 1.5, 3.0);
            std::vector<Pose> atOrigin = poses;
            for (Pose& p : atOrigin)
                p.position.setZero();
            for (int levels : {1, 2, 3}) {
                const SubdivisionSettings settings = settingsFor(s, levels, cyclic, true);
                const std::vector<Pose> out = subdividePolyscrew(poses, settings);
                const std::vector<Eigen::Vector3d> expected = linearSubdivision(positionsOf(poses), s, cyclic, levels);
                GYRE_CHECK(out.size() == expected.size(), settingsLabel(settings));
                // Orientations: the same Split&Tweak on rotations alone, which is what the coupled
                // scheme does when every position is at the origin (each screw is then a slerp).
                const std::vector<Pose> rotationsOnly = subdividePolyscrew(atOrigin, settingsFor(s, levels, cyclic, false));
                for (std::size_t j = 0; j < out.size(); ++j) {
                    GYRE_CHECK((out[j].position - expected[j]).norm() < 1e-12 * (1.0 + expected[j].norm()),
                               QStringLiteral("%1: pose %2 at %3, linear mask gives %4").arg(settingsLabel(settings)).arg(j).arg(str(out[j].position), str(expected[j])));
                    GYRE_CHECK(rotationsOnly[j].position.norm() < 1e-14, QStringLiteral("%1: rotations about the origin moved pose %2").arg(settingsLabel(settings)).arg(j));
                    GYRE_CHECK(distanceUpToSign(out[j].orientation, rotationsOnly[j].orientation) < 1e-12,
                               QStringLiteral("%1: pose %2 orientation %3, expected %4").arg(settingsLabel(settings)).arg(j).arg(str(out[j].orientation), str(rotationsOnly[j].orientation)));
                }
            }
        }
    }
}

void TestSubdivision::decoupledCircularMotionLeavesTheCircle()
{
    // The paper's Fig. 11b: decoupled four-point smoothing of a circular motion of four poses does
    // not keep the trajectory on the circle. The linear four-point rule puts the new point between
    // two corners of the square at 10/16·√2 ≈ 0.884 of the radius.
    Random random(150);
    const Eigen::Vector3d centre(2.0, -1.0, 3.0);
    const Eigen::Vector3d axis = random.unitVector();
    const double radius = 2.5;
    Pose start;
    start.orientation = random.rotation();
    start.position = centre + radius * axis.unitOrthogonal();
    std::vector<Pose> poses;
    for (int k = 0; k < 4; ++k)
        poses.push_back(helicalMotion(start, centre, axis, kPi / 2.0 * k, 0.0));
    for (int levels : {1, 3}) {
        double coupledDeviation = 0.0;
        double decoupledDeviation = 0.0;
        for (bool decoupled : {false, true}) {
            const std::vector<Pose> out = subdividePolyscrew(poses, settingsFor(SubdivisionScheme::FourPoint, levels, true, decoupled));
            for (const Pose& p : out) {
                const Eigen::Vector3d rel = p.position - centre;
                const double deviation = std::abs((rel - rel.dot(axis) * axis).norm() - radius) + std::abs(rel.dot(axis));
                (decoupled ? decoupledDeviation : coupledDeviation) = std::max(decoupled ? decoupledDeviation : coupledDeviation, deviation);
            }
        }
        QVERIFY2(coupledDeviation < 1e-10, qPrintable(QStringLiteral("coupled: %1").arg(str(coupledDeviation))));
        QVERIFY2(decoupledDeviation > 0.05 * radius,
                 qPrintable(QStringLiteral("decoupled four-point stays within %1 of the circle (radius %2)").arg(str(decoupledDeviation), str(radius))));
        if (levels == 1)
            QVERIFY2(std::abs(decoupledDeviation - (1.0 - 10.0 / 16.0 * std::sqrt(2.0)) * radius) < 1e-12,
                     qPrintable(QStringLiteral("decoupled deviation %1").arg(str(decoupledDeviation))));
    }
}

void TestSubdivision::zeroLevelsReturnTheInput()
{
    Random random(160);
    const std::vector<Pose> poses = randomWalk(random, 5, 1.0, 1.0);
    for (SubdivisionScheme s : kSchemes) {
        for (bool cyclic : {true, false}) {
            const std::vector<Pose> out = subdividePolyscrew(poses, settingsFor(s, 0, cyclic));
            QCOMPARE(out.size(), poses.size());
            for (std::size_t i = 0; i < poses.size(); ++i)
                QVERIFY(poseDistance(out[i], poses[i]) == 0.0);
        }
    }
}

void TestSubdivision::invalidLevelsThrow()
{
    Random random(161);
    const std::vector<Pose> poses = randomWalk(random, 4, 1.0, 1.0);
    PolyscrewSubdivider subdivider;
    for (int levels : {-1, -100}) {
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, subdividePolyscrew(poses, settingsFor(SubdivisionScheme::BSpline, levels, true)));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, subdivider.subdivide(poses, settingsFor(SubdivisionScheme::Jarek, levels, false)));
    }
    // A result that does not fit in std::size_t.
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, subdividePolyscrew(poses, settingsFor(SubdivisionScheme::FourPoint, 64, true)));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, subdivider.subdivide(poses, settingsFor(SubdivisionScheme::FourPoint, 1000, false)));
    // The subdivider still works after refusing.
    QCOMPARE(subdivider.subdivide(poses, settingsFor(SubdivisionScheme::FourPoint, 2, true)).size(), std::size_t(16));
}

void TestSubdivision::subdividedPoseCountOverflow()
{
    constexpr std::size_t max = std::numeric_limits<std::size_t>::max();
    constexpr int bits = std::numeric_limits<std::size_t>::digits;
    QCOMPARE(subdividedPoseCount(5, 0, true), std::optional<std::size_t>(5));
    QCOMPARE(subdividedPoseCount(5, 0, false), std::optional<std::size_t>(5));
    QCOMPARE(subdividedPoseCount(max, 0, true), std::optional<std::size_t>(max));
    QCOMPARE(subdividedPoseCount(1, bits - 1, true), std::optional<std::size_t>(std::size_t(1) << (bits - 1)));
    QCOMPARE(subdividedPoseCount(3, bits - 2, true), std::optional<std::size_t>(std::size_t(3) << (bits - 2)));
    QCOMPARE(subdividedPoseCount(2, bits - 1, false), std::optional<std::size_t>((std::size_t(1) << (bits - 1)) + 1));
    QVERIFY(!subdividedPoseCount(3, bits - 1, true).has_value());
    QVERIFY(!subdividedPoseCount(1, bits, true).has_value());
    QVERIFY(!subdividedPoseCount(2, bits, true).has_value());
    QVERIFY(!subdividedPoseCount(3, 1000, true).has_value());
    QVERIFY(!subdividedPoseCount(max / 2 + 1, 1, true).has_value());
    QVERIFY(!subdividedPoseCount(3, bits - 1, false).has_value()); // 2·2^(bits−1) + 1
    QVERIFY(!subdividedPoseCount(max, 1, false).has_value());
    const std::size_t justFits = (max >> 1) + 1; // 2^(bits−1); (justFits − 1)·2 + 1 = max
    QCOMPARE(subdividedPoseCount(justFits, 1, false), std::optional<std::size_t>(max));
}

void TestSubdivision::subdividerReuseGivesIdenticalResults()
{
    Random random(170);
    PolyscrewSubdivider subdivider;
    struct Job {
        std::vector<Pose> poses;
        SubdivisionSettings settings;
    };
    std::vector<Job> jobs;
    // Large, then small, then large again, with every scheme and mode, so that the buffers grow,
    // shrink in use and are reused.
    const std::size_t sizes[] = {9, 3, 12, 2, 5};
    int k = 0;
    for (std::size_t n : sizes) {
        for (SubdivisionScheme s : kSchemes) {
            const bool cyclic = (k % 2) == 0 && n >= 3;
            jobs.push_back({randomWalk(random, n, 1.2, 2.0), settingsFor(s, 1 + k % 4, cyclic, k % 3 == 2)});
            ++k;
        }
    }
    for (int pass = 0; pass < 2; ++pass) {
        for (std::size_t i = 0; i < jobs.size(); ++i) {
            const Job& job = jobs[i];
            const std::vector<Pose>& reused = subdivider.subdivide(job.poses, job.settings);
            const std::vector<Pose> fresh = subdividePolyscrew(job.poses, job.settings);
            GYRE_CHECK(reused.size() == fresh.size(), QStringLiteral("pass %1 job %2 (%3)").arg(pass).arg(i).arg(settingsLabel(job.settings)));
            for (std::size_t j = 0; j < fresh.size(); ++j) {
                GYRE_CHECK(reused[j].orientation.coeffs() == fresh[j].orientation.coeffs() && reused[j].position == fresh[j].position,
                           QStringLiteral("pass %1 job %2 (%3): pose %4 differs: %5 vs %6").arg(pass).arg(i).arg(settingsLabel(job.settings)).arg(j)
                               .arg(str(reused[j]), str(fresh[j])));
            }
        }
    }
}

QTEST_APPLESS_MAIN(TestSubdivision)
#include "tst_subdivision.moc"
