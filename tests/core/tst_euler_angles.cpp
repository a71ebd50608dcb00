// Three-angle sequences (euler_angles.h, euler_filter.h), all 12 orders × intrinsic/extrinsic, against rotations
// composed in the test from elementary rotation matrices: intrinsic ijk is R_i(e1)·R_j(e2)·R_k(e3),
// extrinsic ijk is R_k(e3)·R_j(e2)·R_i(e1). Round trips for random rotations and at and near gimbal
// lock, the documented angle ranges, the gimbal-lock distance, the Euler filter and the choice of
// the nearest equivalent triple.

#include "core/euler_angles.h"
#include "core/euler_filter.h"

#include "core_test_support.h"

#include <QObject>
#include <QTest>

#include <set>
#include <string>
#include <vector>

using namespace gyre;
using namespace gyre::test;

namespace {

QString nameOf(const EulerConvention& c) { return QString::fromStdString(c.name()); }

// The rotation matrix of a triple, composed from elementary rotations in the test.
Eigen::Matrix3d composedMatrix(const Eigen::Vector3d& e, const EulerConvention& c)
{
    const auto& a = c.axes;
    if (c.frame == AngleFrame::Intrinsic)
        return elementaryRotation(a[0], e[0]) * elementaryRotation(a[1], e[1]) * elementaryRotation(a[2], e[2]);
    return elementaryRotation(a[2], e[2]) * elementaryRotation(a[1], e[1]) * elementaryRotation(a[0], e[0]);
}

// The same rotation as a quaternion, composed from elementary axis-angle quaternions.
Eigen::Quaterniond composedQuaternion(const Eigen::Vector3d& e, const EulerConvention& c)
{
    const auto& a = c.axes;
    auto unit = [](int axis) { return Eigen::Vector3d::Unit(axis); };
    const Eigen::Quaterniond q1 = axisAngleQuaternion(unit(a[0]), e[0]);
    const Eigen::Quaterniond q2 = axisAngleQuaternion(unit(a[1]), e[1]);
    const Eigen::Quaterniond q3 = axisAngleQuaternion(unit(a[2]), e[2]);
    return c.frame == AngleFrame::Intrinsic ? q1 * q2 * q3 : q3 * q2 * q1;
}

// The other solution family: the middle angle mirrored, the outer angles turned by π.
Eigen::Vector3d mirrored(const Eigen::Vector3d& e, const EulerConvention& c)
{
    const double middle = c.isProperEuler() ? -e[1] : kPi - e[1];
    return Eigen::Vector3d(e[0] + kPi, middle, e[2] + kPi);
}

double wrapped(double x) { return std::remainder(x, 2.0 * kPi); } // in [−π, π]

// The matrix entry that is ±sin e2 (Tait-Bryan) or cos e2 (proper Euler): it reaches ±1 exactly at
// gimbal lock.
double lockIndicator(const Eigen::Matrix3d& m, const EulerConvention& c)
{
    const int i = c.axes[0];
    const int k = c.axes[2];
    if (c.isProperEuler())
        return m(i, i);
    return c.frame == AngleFrame::Intrinsic ? m(i, k) : m(k, i);
}

bool middleInRange(double middle, const EulerConvention& c)
{
    return c.isProperEuler() ? (middle >= 0.0 && middle <= kPi) : (middle >= -kPi / 2.0 && middle <= kPi / 2.0);
}

bool outerInRange(double e) { return e > -kPi && e <= kPi; }

double expectedLockDistance(double middle, const EulerConvention& c)
{
    return c.isProperEuler() ? std::min(middle, kPi - middle) : kPi / 2.0 - std::abs(middle);
}

// The decomposition as written before the core's fast arctangent, with the standard library's atan2
// and hypot: the intrinsic half angles from the two quaternion pairs that carry e1 ± e3, the middle
// angle from their lengths, the same lock rule (below 1e-12 the undetermined half angle follows the
// other, so that e3 = 0 for intrinsic and e1 = 0 for extrinsic), extrinsic ijk as intrinsic kji
// reversed. Returns e1, e2, e3 and the gimbal-lock distance.
Eigen::Vector4d atan2Angles(const Eigen::Quaterniond& given, const EulerConvention& c)
{
    const Eigen::Quaterniond q = given.normalized();
    const bool intrinsic = c.frame == AngleFrame::Intrinsic;
    const int i = intrinsic ? c.axes[0] : c.axes[2];
    const int j = c.axes[1];
    const double epsilon = (j - i + 3) % 3 == 1 ? 1.0 : -1.0;
    const double w = q.w();
    const double x = q.vec()[i];
    const double y = q.vec()[j];
    const double z = epsilon * q.vec()[c.isProperEuler() ? 3 - i - j : (intrinsic ? c.axes[2] : c.axes[0])];
    // The pairs (cos, sin) of the half-sum and half-difference.
    const Eigen::Vector2d sumPair = c.isProperEuler() ? Eigen::Vector2d(w, x) : Eigen::Vector2d(w + y, x + z);
    const Eigen::Vector2d differencePair = c.isProperEuler() ? Eigen::Vector2d(y, z) : Eigen::Vector2d(w - y, x - z);
    double sum = std::atan2(sumPair.y(), sumPair.x());
    double difference = std::atan2(differencePair.y(), differencePair.x());
    const double sign = intrinsic ? 1.0 : -1.0;
    if (std::hypot(differencePair.x(), differencePair.y()) < 1e-12)
        difference = sign * sum;
    else if (std::hypot(sumPair.x(), sumPair.y()) < 1e-12)
        sum = sign * difference;
    const double lengths = std::atan2(std::hypot(differencePair.x(), differencePair.y()), std::hypot(sumPair.x(), sumPair.y()));
    const double middle = c.isProperEuler() ? 2.0 * lengths : kPi / 2.0 - 2.0 * lengths;
    const double third = c.isProperEuler() ? sum - difference : epsilon * (sum - difference);
    Eigen::Vector4d result(sum + difference, middle, third, expectedLockDistance(middle, c));
    if (!intrinsic)
        std::swap(result[0], result[2]);
    return result;
}

double matrixDistance(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) { return (a - b).cwiseAbs().maxCoeff(); }

QString anglesStr(const Eigen::Vector3d& e) { return str(e); }

} // namespace

class TestEulerAngles : public QObject {
    Q_OBJECT

private slots:
    void conventions();
    void parseRejectsInvalidOrders();
    void quaternionMatchesElementaryRotations();
    void roundTripRandomRotations();
    void canonicalAnglesAreRecovered();
    void nearGimbalLock();
    void exactGimbalLock();
    void unwrappedSequenceCrossingHalfTurn();
    void nearestEquivalentAngles();
    void storedAnglesFilteredBackToARamp();
    void wrapAngle();
    void withinRoundingOfTheAtan2Formulas();
};

void TestEulerAngles::conventions()
{
    const std::vector<EulerConvention> all = EulerConvention::all();
    QCOMPARE(all.size(), std::size_t(24));
    std::set<std::string> names;
    int proper = 0;
    int intrinsic = 0;
    for (const EulerConvention& c : all) {
        names.insert(c.name());
        for (int axis : c.axes)
            QVERIFY(axis >= 0 && axis <= 2);
        QVERIFY2(c.axes[0] != c.axes[1] && c.axes[1] != c.axes[2], qPrintable(nameOf(c)));
        const bool isProper = c.axes[0] == c.axes[2];
        QCOMPARE(c.isProperEuler(), isProper);
        proper += isProper ? 1 : 0;
        intrinsic += c.frame == AngleFrame::Intrinsic ? 1 : 0;
        std::string order;
        for (int axis : c.axes)
            order += char('x' + axis);
        QCOMPARE(c.order(), order);
        QCOMPARE(c.name(), std::string(c.frame == AngleFrame::Intrinsic ? "intrinsic " : "extrinsic ") + order);
        const std::optional<EulerConvention> parsed = EulerConvention::parse(order, c.frame);
        QVERIFY2(parsed.has_value() && *parsed == c, qPrintable(nameOf(c)));
    }
    QCOMPARE(names.size(), std::size_t(24));
    QCOMPARE(proper, 12);
    QCOMPARE(intrinsic, 12);

    const std::optional<EulerConvention> upper = EulerConvention::parse("ZXZ", AngleFrame::Intrinsic);
    QVERIFY(upper.has_value());
    QVERIFY((upper->axes == std::array<int, 3>{2, 0, 2}));
    QVERIFY(upper->frame == AngleFrame::Intrinsic);
    QVERIFY(upper->isProperEuler());
}

void TestEulerAngles::parseRejectsInvalidOrders()
{
    for (const char* bad : {"", "x", "xy", "xyzx", "xxy", "xyy", "zzz", "abc", "xyw", "x z", "xy-"}) {
        QVERIFY2(!EulerConvention::parse(bad, AngleFrame::Extrinsic).has_value(), bad);
        QVERIFY2(!EulerConvention::parse(bad, AngleFrame::Intrinsic).has_value(), bad);
    }
}

void TestEulerAngles::quaternionMatchesElementaryRotations()
{
    Random random(31);
    for (const EulerConvention& c : EulerConvention::all()) {
        for (int i = 0; i < 100; ++i) {
            const Eigen::Vector3d e(random.uniform(-2.0 * kPi, 2.0 * kPi), random.uniform(-2.0 * kPi, 2.0 * kPi),
                                    random.uniform(-2.0 * kPi, 2.0 * kPi));
            const Eigen::Quaterniond q = quaternionFromEulerAngles(e, c);
            GYRE_CHECK(std::abs(q.norm() - 1.0) < 1e-15 * 4, QStringLiteral("%1 %2: not unit").arg(nameOf(c), anglesStr(e)));
            const double error = matrixDistance(q.toRotationMatrix(), composedMatrix(e, c));
            GYRE_CHECK(error < 1e-14, QStringLiteral("%1 %2: differs from the composed rotation by %3\n   got %4")
                                          .arg(nameOf(c), anglesStr(e), str(error), str(q)));
        }
        // Each angle alone is a rotation about its own axis.
        for (int slot = 0; slot < 3; ++slot) {
            Eigen::Vector3d e = Eigen::Vector3d::Zero();
            e[slot] = 0.7;
            const Eigen::Quaterniond q = quaternionFromEulerAngles(e, c);
            const Eigen::Quaterniond expected = axisAngleQuaternion(Eigen::Vector3d::Unit(c.axes[std::size_t(slot)]), 0.7);
            GYRE_CHECK(distanceUpToSign(q, expected) < 1e-15 * 4, QStringLiteral("%1: angle %2 alone gives %3").arg(nameOf(c)).arg(slot + 1).arg(str(q)));
        }
    }
}

void TestEulerAngles::roundTripRandomRotations()
{
    Random random(32);
    for (const EulerConvention& c : EulerConvention::all()) {
        for (int i = 0; i < 150; ++i) {
            const Eigen::Quaterniond q = random.rotation();
            const EulerAngles result = eulerAnglesFromQuaternion(q, c);
            const Eigen::Vector3d& e = result.angles;
            GYRE_CHECK(outerInRange(e[0]) && outerInRange(e[2]) && middleInRange(e[1], c),
                       QStringLiteral("%1, q %2: angles %3 out of range").arg(nameOf(c), str(q), anglesStr(e)));
            const double error = matrixDistance(composedMatrix(e, c), q.toRotationMatrix());
            GYRE_CHECK(error < 1e-12, QStringLiteral("%1, q %2: angles %3 rebuild with error %4").arg(nameOf(c), str(q), anglesStr(e), str(error)));
            const Eigen::Quaterniond rebuilt = quaternionFromEulerAngles(e, c);
            GYRE_CHECK(distanceUpToSign(rebuilt, q) < 1e-12, QStringLiteral("%1, q %2: rebuilt %3").arg(nameOf(c), str(q), str(rebuilt)));
            GYRE_CHECK(std::abs(result.gimbalLockDistance - expectedLockDistance(e[1], c)) < 1e-14,
                       QStringLiteral("%1, angles %2: gimbalLockDistance %3").arg(nameOf(c), anglesStr(e), str(result.gimbalLockDistance)));
            // −q is the same rotation and gets the same angles.
            const Eigen::Vector3d fromNegated = eulerAnglesFromQuaternion(negated(q), c).angles;
            GYRE_CHECK(matrixDistance(composedMatrix(fromNegated, c), q.toRotationMatrix()) < 1e-12,
                       QStringLiteral("%1, −q %2: angles %3").arg(nameOf(c), str(q), anglesStr(fromNegated)));
        }
    }
}

void TestEulerAngles::canonicalAnglesAreRecovered()
{
    // Away from gimbal lock a rotation has exactly one triple in the documented ranges.
    Random random(33);
    for (const EulerConvention& c : EulerConvention::all()) {
        for (int i = 0; i < 200; ++i) {
            const double margin = 0.02;
            const double middle = c.isProperEuler() ? random.uniform(margin, kPi - margin)
                                                    : random.uniform(-kPi / 2.0 + margin, kPi / 2.0 - margin);
            const Eigen::Vector3d e(random.uniform(-kPi, kPi), middle, random.uniform(-kPi, kPi));
            const EulerAngles result = eulerAnglesFromQuaternion(composedQuaternion(e, c), c);
            const Eigen::Vector3d diff(wrapped(result.angles[0] - e[0]), result.angles[1] - e[1], wrapped(result.angles[2] - e[2]));
            GYRE_CHECK(diff.cwiseAbs().maxCoeff() < 1e-12,
                       QStringLiteral("%1: built from %2, got %3").arg(nameOf(c), anglesStr(e), anglesStr(result.angles)));
            GYRE_CHECK(std::abs(result.gimbalLockDistance - expectedLockDistance(middle, c)) < 1e-12,
                       QStringLiteral("%1: built from %2, gimbalLockDistance %3, expected %4")
                           .arg(nameOf(c), anglesStr(e), str(result.gimbalLockDistance), str(expectedLockDistance(middle, c))));
        }
    }
}

void TestEulerAngles::nearGimbalLock()
{
    Random random(34);
    for (const EulerConvention& c : EulerConvention::all()) {
        const std::vector<double> locks = c.isProperEuler() ? std::vector<double>{0.0, kPi} : std::vector<double>{kPi / 2.0, -kPi / 2.0};
        for (double lock : locks) {
            for (double delta : {0.0, 1e-12, 1e-9, 1e-6, 1e-3}) {
                for (double side : {-1.0, 1.0}) {
                    for (int i = 0; i < 6; ++i) {
                        const Eigen::Vector3d e(random.uniform(-kPi, kPi), lock + side * delta, random.uniform(-kPi, kPi));
                        const Eigen::Quaterniond q = composedQuaternion(e, c);
                        const EulerAngles result = eulerAnglesFromQuaternion(q, c);
                        const Eigen::Vector3d& got = result.angles;
                        const QString context = QStringLiteral("%1, built from %2 (lock %3, δ %4)").arg(nameOf(c), anglesStr(e), str(lock), str(side * delta));
                        GYRE_CHECK(outerInRange(got[0]) && outerInRange(got[2]) && middleInRange(got[1], c),
                                   QStringLiteral("%1: angles %2 out of range").arg(context, anglesStr(got)));
                        // Within about 1e-12 rad of lock the split between e1 and e3 is a
                        // convention (the core snaps to e3 = 0 there), which may cost up to ~δ.
                        const double tolerance = delta > 0.0 && delta <= 2e-12 ? 4e-12 : 1e-12;
                        const double error = matrixDistance(composedMatrix(got, c), q.toRotationMatrix());
                        GYRE_CHECK(error < tolerance, QStringLiteral("%1: angles %2 rebuild with error %3").arg(context, anglesStr(got), str(error)));
                        const Eigen::Quaterniond rebuilt = quaternionFromEulerAngles(got, c);
                        GYRE_CHECK(distanceUpToSign(rebuilt, q) < tolerance,
                                   QStringLiteral("%1: angles %2 rebuild %3, expected %4").arg(context, anglesStr(got), str(rebuilt), str(q)));
                        GYRE_CHECK(std::abs(result.gimbalLockDistance - delta) < 1e-12,
                                   QStringLiteral("%1: gimbalLockDistance %2, expected %3 (angles %4)")
                                       .arg(context, str(result.gimbalLockDistance), str(delta), anglesStr(got)));
                        GYRE_CHECK(std::abs(result.gimbalLockDistance - expectedLockDistance(got[1], c)) < 1e-14,
                                   QStringLiteral("%1: gimbalLockDistance %2 disagrees with the middle angle %3")
                                       .arg(context, str(result.gimbalLockDistance), str(got[1])));
                    }
                }
            }
        }
    }
}

void TestEulerAngles::exactGimbalLock()
{
    // Rotations whose quaternions are exact in binary (components 0, ±1/2, ±1: the 12 rotations of the
    // tetrahedral group) are exactly at lock or exactly not. At lock, e3 is 0 and e1 carries the turn.
    std::vector<Eigen::Quaterniond> exact = {Eigen::Quaterniond(1, 0, 0, 0), Eigen::Quaterniond(0, 1, 0, 0),
                                             Eigen::Quaterniond(0, 0, 1, 0), Eigen::Quaterniond(0, 0, 0, 1)};
    for (int signs = 0; signs < 8; ++signs)
        exact.emplace_back(0.5, (signs & 1) ? -0.5 : 0.5, (signs & 2) ? -0.5 : 0.5, (signs & 4) ? -0.5 : 0.5);
    int locked = 0;
    for (const EulerConvention& c : EulerConvention::all()) {
        for (const Eigen::Quaterniond& q : exact) {
            const Eigen::Matrix3d m = q.toRotationMatrix();
            const EulerAngles result = eulerAnglesFromQuaternion(q, c);
            const Eigen::Vector3d& got = result.angles;
            const QString context = QStringLiteral("%1, q %2: angles %3").arg(nameOf(c), str(q), anglesStr(got));
            GYRE_CHECK(matrixDistance(composedMatrix(got, c), m) < 1e-14, QStringLiteral("%1 do not rebuild q").arg(context));
            GYRE_CHECK(outerInRange(got[0]) && outerInRange(got[2]) && middleInRange(got[1], c), QStringLiteral("%1 out of range").arg(context));
            if (std::abs(lockIndicator(m, c)) == 1.0) {
                ++locked;
                GYRE_CHECK(result.gimbalLockDistance < 1e-15, QStringLiteral("%1: at lock, distance %2").arg(context, str(result.gimbalLockDistance)));
                GYRE_CHECK(std::abs(got[2]) < 1e-15, QStringLiteral("%1: at exact lock e3 should be 0").arg(context));
            }
        }
        // Proper Euler with the middle angle exactly 0: a single turn about the first axis, all in e1.
        if (c.isProperEuler()) {
            for (double angle : {0.3, -2.0, 3.0, kPi}) {
                const Eigen::Quaterniond q = axisAngleQuaternion(Eigen::Vector3d::Unit(c.axes[0]), angle);
                const EulerAngles result = eulerAnglesFromQuaternion(q, c);
                const Eigen::Vector3d& got = result.angles;
                GYRE_CHECK(std::abs(got[1]) < 1e-15 && std::abs(got[2]) < 1e-15 && std::abs(wrapped(got[0] - angle)) < 1e-14,
                           QStringLiteral("%1: turn %2 about the first axis gives %3").arg(nameOf(c), str(angle), anglesStr(got)));
                GYRE_CHECK(result.gimbalLockDistance < 1e-15, QStringLiteral("%1: distance %2").arg(nameOf(c), str(result.gimbalLockDistance)));
            }
        }
    }
    QVERIFY2(locked >= 24, qPrintable(QStringLiteral("only %1 exact locks were exercised").arg(locked)));
}

void TestEulerAngles::unwrappedSequenceCrossingHalfTurn()
{
    for (const EulerConvention& c : EulerConvention::all()) {
        // A smooth path of angles whose outer angles cross ±180° several times, away from lock.
        const int frames = 240;
        std::vector<Eigen::Vector3d> path;
        std::vector<Eigen::Quaterniond> rotations;
        double maxStep = 0.0;
        for (int k = 0; k < frames; ++k) {
            const double middle = c.isProperEuler() ? 1.4 + 0.8 * std::sin(0.03 * k) : 0.2 + 0.6 * std::sin(0.03 * k);
            const Eigen::Vector3d e(-2.5 + 0.055 * k, middle, 2.8 - 0.043 * k);
            if (!path.empty())
                maxStep = std::max(maxStep, (e - path.back()).cwiseAbs().maxCoeff());
            path.push_back(e);
            rotations.push_back(composedQuaternion(e, c));
        }
        const std::vector<Eigen::Vector3d> unwrapped = unwrappedEulerAngles(rotations, c);
        QCOMPARE(unwrapped.size(), rotations.size());
        for (int k = 0; k < frames; ++k) {
            const std::size_t i = std::size_t(k);
            GYRE_CHECK(matrixDistance(composedMatrix(unwrapped[i], c), rotations[i].toRotationMatrix()) < 1e-12,
                       QStringLiteral("%1 frame %2: %3 does not rebuild the rotation").arg(nameOf(c)).arg(k).arg(anglesStr(unwrapped[i])));
            if (k > 0) {
                const double jump = (unwrapped[i] - unwrapped[i - 1]).cwiseAbs().maxCoeff();
                GYRE_CHECK(jump <= maxStep + 1e-9, QStringLiteral("%1 frame %2: jump %3 from %4 to %5 (largest per-frame change %6)")
                                                     .arg(nameOf(c)).arg(k).arg(str(jump), anglesStr(unwrapped[i - 1]), anglesStr(unwrapped[i]), str(maxStep)));
            }
        }
        // Without 2π jumps the outer angles change in total exactly as much as the path's (either
        // solution family turns its outer angles alike).
        const Eigen::Vector3d total = unwrapped.back() - unwrapped.front();
        const Eigen::Vector3d expected = path.back() - path.front();
        GYRE_CHECK(std::abs(total[0] - expected[0]) < 1e-9 && std::abs(total[2] - expected[2]) < 1e-9,
                   QStringLiteral("%1: total change %2, expected %3").arg(nameOf(c), anglesStr(total), anglesStr(expected)));
    }
}

void TestEulerAngles::nearestEquivalentAngles()
{
    Random random(35);
    for (const EulerConvention& c : EulerConvention::all()) {
        // The documented second solution is a solution (a check on the test itself).
        const Eigen::Vector3d sample(0.4, c.isProperEuler() ? 1.1 : 0.3, -2.2);
        QVERIFY2(matrixDistance(composedMatrix(mirrored(sample, c), c), composedMatrix(sample, c)) < 1e-14, qPrintable(nameOf(c)));

        for (int i = 0; i < 100; ++i) {
            const Eigen::Vector3d a = i < 50 ? eulerAnglesFromQuaternion(random.rotation(), c).angles : random.vector(7.0);
            const Eigen::Vector3d previous = random.vector(8.0);
            const Eigen::Vector3d r = gyre::nearestEquivalentAngles(a, previous, c);
            const QString context = QStringLiteral("%1: angles %2, previous %3, got %4").arg(nameOf(c), anglesStr(a), anglesStr(previous), anglesStr(r));
            GYRE_CHECK(matrixDistance(composedMatrix(r, c), composedMatrix(a, c)) < 1e-12, QStringLiteral("%1: not the same rotation").arg(context));
            GYRE_CHECK((r - previous).norm() <= (a - previous).norm() + 1e-12, QStringLiteral("%1: farther than the input").arg(context));
            GYRE_CHECK((r - previous).cwiseAbs().maxCoeff() <= kPi + 1e-12, QStringLiteral("%1: an angle is more than π from previous").arg(context));
        }
        // Unambiguous targets: near a 2π-shifted copy of either solution, that copy is returned.
        for (int i = 0; i < 40; ++i) {
            const double margin = 0.3;
            const double middle = c.isProperEuler() ? random.uniform(margin, kPi - margin)
                                                    : random.uniform(-kPi / 2.0 + margin, kPi / 2.0 - margin);
            const Eigen::Vector3d a(random.uniform(-kPi, kPi), middle, random.uniform(-kPi, kPi));
            const Eigen::Vector3d shift = 2.0 * kPi * Eigen::Vector3d(random.integer(-2, 2), random.integer(-2, 2), random.integer(-2, 2));
            const Eigen::Vector3d target = (i % 2 == 0 ? a : mirrored(a, c)) + shift;
            const Eigen::Vector3d previous = target + random.vector(0.05);
            const Eigen::Vector3d r = gyre::nearestEquivalentAngles(a, previous, c);
            GYRE_CHECK((r - target).cwiseAbs().maxCoeff() < 1e-12,
                       QStringLiteral("%1: angles %2, previous %3: got %4, expected %5").arg(nameOf(c), anglesStr(a), anglesStr(previous), anglesStr(r), anglesStr(target)));
        }
    }
}

// The filter on stored angles (continuousEulerAngles) against a construction of the test's own: a continuous
// ramp of triples, each after the first replaced by an equivalent one (every angle shifted by a random number of
// turns, and half of them the twin solution), must come back as the ramp.
void TestEulerAngles::storedAnglesFilteredBackToARamp()
{
    Random random(23);
    constexpr int kKeys = 40;
    for (const EulerConvention& c : EulerConvention::all()) {
        // Outer angles turn up to 0.4 rad a key (several turns in all); the middle one swings well clear of lock.
        const double centre = c.isProperEuler() ? kPi / 2.0 : 0.0;
        const Eigen::Vector3d start(random.uniform(-kPi, kPi), centre, random.uniform(-kPi, kPi));
        const Eigen::Vector3d rate(random.uniform(-0.4, 0.4), 0.0, random.uniform(-0.4, 0.4));
        std::vector<Eigen::Vector3d> ramp;
        std::vector<Eigen::Vector3d> stored;
        for (int k = 0; k < kKeys; ++k) {
            Eigen::Vector3d angles = start + k * rate;
            angles[1] = centre + 0.9 * std::sin(0.3 * k);
            ramp.push_back(angles);
            if (k == 0) {
                stored.push_back(angles); // the filter keeps the first key as it is
                continue;
            }
            const Eigen::Vector3d turns(random.integer(-3, 3), random.integer(-3, 3), random.integer(-3, 3));
            const Eigen::Vector3d equivalent = (k % 2 == 0 ? mirrored(angles, c) : angles) + 2.0 * kPi * turns;
            QVERIFY2(matrixDistance(composedMatrix(equivalent, c), composedMatrix(angles, c)) < 1e-12, qPrintable(nameOf(c)));
            stored.push_back(equivalent);
        }
        const std::vector<Eigen::Vector3d> filtered = continuousEulerAngles(stored, c);
        QCOMPARE(filtered.size(), ramp.size());
        for (int k = 0; k < kKeys; ++k)
            GYRE_CHECK((filtered[k] - ramp[k]).cwiseAbs().maxCoeff() < 1e-12,
                       QStringLiteral("%1 key %2: stored %3, filtered %4, ramp %5")
                           .arg(nameOf(c)).arg(k).arg(anglesStr(stored[k]), anglesStr(filtered[k]), anglesStr(ramp[k])));
        // With a triple before them, the first key too is chosen nearest to it.
        const Eigen::Vector3d before = ramp[0] - 0.1 * rate;
        const std::vector<Eigen::Vector3d> shiftedFirst = continuousEulerAngles(
            {mirrored(ramp[0], c) + Eigen::Vector3d(2.0 * kPi, -4.0 * kPi, 0.0), stored[1]}, c, before);
        GYRE_CHECK((shiftedFirst[0] - ramp[0]).cwiseAbs().maxCoeff() < 1e-12,
                   QStringLiteral("%1: first key %2, expected %3").arg(nameOf(c), anglesStr(shiftedFirst[0]), anglesStr(ramp[0])));
    }
}

void TestEulerAngles::wrapAngle()
{
    QCOMPARE(gyre::wrapAngle(0.0), 0.0);
    QCOMPARE(gyre::wrapAngle(kPi), kPi);
    QCOMPARE(gyre::wrapAngle(-kPi), kPi);
    QVERIFY(std::abs(gyre::wrapAngle(-1.5 * kPi) - 0.5 * kPi) < 1e-15);
    QVERIFY(std::abs(gyre::wrapAngle(2.0 * kPi + 0.25) - 0.25) < 1e-15);
    Random random(36);
    for (int i = 0; i < 1000; ++i) {
        const double x = random.uniform(-100.0, 100.0);
        const double w = gyre::wrapAngle(x);
        GYRE_CHECK(w > -kPi && w <= kPi, QStringLiteral("wrapAngle(%1) = %2").arg(str(x), str(w)));
        const double turns = (x - w) / (2.0 * kPi);
        GYRE_CHECK(std::abs(turns - std::round(turns)) < 1e-12, QStringLiteral("wrapAngle(%1) = %2 is not equivalent").arg(str(x), str(w)));
    }
}

// eulerAnglesFromQuaternion reads its middle angle with the core's fast arctangent and its outer
// angles with the precise one, each rounded once; quaternionFromEulerAngles takes the half-angle sines
// and cosines from the fast sine and cosine. The references are the same formulas with the standard library's functions (atan2Angles and
// composedQuaternion), over random rotations, rotations near and at gimbal lock, quaternions off the
// unit sphere and angles far outside (−π, π].
void TestEulerAngles::withinRoundingOfTheAtan2Formulas()
{
    // rad, modulo 2π. The reference's outer angles are sums of two rounded half angles, up to 2π before
    // wrapping: they are off the exact angles of their quaternion pairs by up to 8.9e-16 on these
    // rotations.
    constexpr double kAngleBound = 1e-15;
    constexpr double kQuaternionBound = 1e-15; // on each coefficient
    Random random(37);
    Eigen::Vector2d worst = Eigen::Vector2d::Zero();
    for (const EulerConvention& c : EulerConvention::all()) {
        const std::vector<double> locks = c.isProperEuler() ? std::vector<double>{0.0, kPi} : std::vector<double>{kPi / 2.0, -kPi / 2.0};
        for (int n = 0; n < 3000; ++n) {
            const double fromLock = n % 3 == 0 ? 0.0 : random.uniform(-1.0, 1.0) * std::pow(10.0, random.uniform(-16.0, 0.0));
            const Eigen::Vector3d built(random.uniform(-kPi, kPi), locks[std::size_t(n % 2)] + fromLock, random.uniform(-kPi, kPi));
            Eigen::Quaterniond q = n % 4 == 0 ? random.rotation() : composedQuaternion(built, c);
            if (n % 5 == 0)
                q.coeffs() *= 2.5;
            const EulerAngles got = eulerAnglesFromQuaternion(q, c);
            const Eigen::Vector4d expected = atan2Angles(q, c);
            const double error = std::max({std::abs(wrapped(got.angles[0] - expected[0])), std::abs(got.angles[1] - expected[1]),
                                           std::abs(wrapped(got.angles[2] - expected[2])), std::abs(got.gimbalLockDistance - expected[3])});
            worst[0] = std::max(worst[0], error);
            GYRE_CHECK(error <= kAngleBound, QStringLiteral("%1, q %2: angles %3 (lock distance %4), expected %5 (%6), off by %7")
                                                 .arg(nameOf(c), str(q), anglesStr(got.angles), str(got.gimbalLockDistance),
                                                      anglesStr(expected.head<3>()), str(expected[3]), str(error)));

            const Eigen::Vector3d angles = random.vector(n % 2 == 0 ? kPi : 40.0);
            const Eigen::Quaterniond rebuilt = quaternionFromEulerAngles(angles, c);
            const double quaternionError = (rebuilt.coeffs() - composedQuaternion(angles, c).coeffs()).cwiseAbs().maxCoeff();
            worst[1] = std::max(worst[1], quaternionError);
            GYRE_CHECK(quaternionError <= kQuaternionBound, QStringLiteral("%1, angles %2: %3, expected %4")
                                                                .arg(nameOf(c), anglesStr(angles), str(rebuilt), str(composedQuaternion(angles, c))));
        }
    }
    qInfo("worst differences from the standard library's formulas: angles %.3g rad, quaternion coefficients %.3g", worst[0], worst[1]);
}

QTEST_APPLESS_MAIN(TestEulerAngles)
#include "tst_euler_angles.moc"
