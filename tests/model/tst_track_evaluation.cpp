// Track evaluation: each interpolation through its keys, the screw motion against the SE(3) geodesic
// and the subdivided poses, the fit's window, and the bake's sample times.

#include "core/core_test_support.h"
#include "core/key_time_map.h"
#include "core/subdivision.h"
#include "model/track_evaluation.h"

#include <QObject>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

using namespace gyre;
using namespace gyre::model;
using namespace gyre::test;

namespace {

constexpr double kTolerance = 1e-9;

MotionTrack randomTrack(InterpolationMethod method, const std::vector<double>& times, std::uint64_t seed)
{
    Random random(seed);
    MotionTrack track;
    track.interpolation = method;
    for (const double time : times)
        track.keys.push_back({time, random.pose(5.0), true});
    return track;
}

Pose fromMatrix(const Eigen::Matrix4d& m)
{
    return {Eigen::Quaterniond(Eigen::Matrix3d(m.topLeftCorner<3, 3>())), m.topRightCorner<3, 1>()};
}

// The normalised cubic Hermite curve in R⁴ between two control points, written out:
// p(u) = h₀₀q₀ + h₁₀Δm₀ + h₀₁q₁ + h₁₁Δm₁.
Eigen::Quaterniond hermite(const HermiteControlPoint& a, const HermiteControlPoint& b, double time)
{
    const double span = b.time - a.time;
    const double u = (time - a.time) / span;
    const double h00 = 2 * u * u * u - 3 * u * u + 1;
    const double h10 = u * u * u - 2 * u * u + u;
    const double h01 = -2 * u * u * u + 3 * u * u;
    const double h11 = u * u * u - u * u;
    Eigen::Quaterniond q;
    q.coeffs() = h00 * a.value.coeffs() + h10 * span * a.derivative.coeffs() + h01 * b.value.coeffs() +
                 h11 * span * b.derivative.coeffs();
    return q.normalized();
}

} // namespace

class TstTrackEvaluation : public QObject {
    Q_OBJECT

private slots:
    void passesThroughItsKeys_data();
    void passesThroughItsKeys();
    void linearAndCubicPositions_data();
    void linearAndCubicPositions();
    void slerpBetweenKeys();
    void holdsTheEndsOutsideTheKeys();
    void angularVelocityOfSlerpIsTheTurnOverTheSpan();
    void angularVelocityMatchesTheAnalyticHermite();
    void screwWithoutSubdivisionIsThePlainPolyscrew();
    void cyclicScrewClosesAndRepeats();
    void subdividedScrewPlaysTheSubdividedPoses();
    void screwSpeedIsContinuousAcrossKeys();
    void fittedCurveOverridesOnlyItsWindow();
    void trackWithoutKeysStaysAtIdentity();
    void ballisticFliesTheChosenFlights();
    void refusesKeysOutOfOrder();
    void bakeSamplesFramesAndKeys();
    void bakeTrackGivesThePosesAtItsTimes();
    void bakeRefusesBadRanges();
};

void TstTrackEvaluation::passesThroughItsKeys_data()
{
    QTest::addColumn<int>("method");
    QTest::addColumn<int>("levels");
    QTest::addColumn<bool>("cyclic");
    QTest::newRow("slerp") << int(InterpolationMethod::Slerp) << 0 << false;
    QTest::newRow("nlerp") << int(InterpolationMethod::Nlerp) << 0 << false;
    QTest::newRow("squad") << int(InterpolationMethod::Squad) << 0 << false;
    QTest::newRow("hermite") << int(InterpolationMethod::Hermite) << 0 << false;
    QTest::newRow("euler") << int(InterpolationMethod::Euler) << 0 << false;
    QTest::newRow("screw") << int(InterpolationMethod::Screw) << 0 << false;
    QTest::newRow("ballistic") << int(InterpolationMethod::Ballistic) << 0 << false;
    // Four-point subdivision interpolates: control pose i stays at parameter i.
    QTest::newRow("screw four-point open") << int(InterpolationMethod::Screw) << 3 << false;
    QTest::newRow("screw four-point cyclic") << int(InterpolationMethod::Screw) << 3 << true;
}

void TstTrackEvaluation::passesThroughItsKeys()
{
    QFETCH(int, method);
    QFETCH(int, levels);
    QFETCH(bool, cyclic);
    MotionTrack track = randomTrack(InterpolationMethod(method), {0.2, 0.5, 1.4, 1.5, 3.0}, 11);
    track.subdivision = {SubdivisionScheme::FourPoint, levels, cyclic, false};
    const TrackMotion motion(track);
    for (const Keyframe& key : track.keys)
        GYRE_CHECK(poseDistance(motion.at(key.time), key.pose) < kTolerance,
                   QStringLiteral("at %1: %2, key %3").arg(str(key.time), str(motion.at(key.time)), str(key.pose)));
}

void TstTrackEvaluation::linearAndCubicPositions_data()
{
    QTest::addColumn<int>("method");
    QTest::addColumn<bool>("cubic");
    QTest::newRow("slerp") << int(InterpolationMethod::Slerp) << false;
    QTest::newRow("nlerp") << int(InterpolationMethod::Nlerp) << false;
    QTest::newRow("euler") << int(InterpolationMethod::Euler) << false;
    QTest::newRow("squad") << int(InterpolationMethod::Squad) << true;
    QTest::newRow("hermite") << int(InterpolationMethod::Hermite) << true;
}

// At the middle of the last span (h = 2): (p₁ + p₂)/2, plus h/8·(m₁ − m₂) for the cubic, whose slopes
// are (p₂ − p₀)/(t₂ − t₀) inside and one-sided (p₂ − p₁)/(t₂ − t₁) at the last key.
void TstTrackEvaluation::linearAndCubicPositions()
{
    QFETCH(int, method);
    QFETCH(bool, cubic);
    const std::vector<Eigen::Vector3d> p{{0, 0, 0}, {1, 2, 0}, {5, -1, 3}};
    const std::vector<double> t{0, 1, 3};
    MotionTrack track;
    track.interpolation = InterpolationMethod(method);
    for (std::size_t i = 0; i < 3; ++i)
        track.keys.push_back({t[i], {Eigen::Quaterniond::Identity(), p[i]}, true});
    Eigen::Vector3d expected = (p[1] + p[2]) / 2;
    if (cubic)
        expected += 2.0 / 8.0 * ((p[2] - p[0]) / (t[2] - t[0]) - (p[2] - p[1]) / (t[2] - t[1]));
    const Pose pose = TrackMotion(track).at(2.0);
    QVERIFY((pose.position - expected).norm() < kTolerance);
    QVERIFY(distanceUpToSign(pose.orientation, Eigen::Quaterniond::Identity()) < kTolerance);
}

void TstTrackEvaluation::slerpBetweenKeys()
{
    const MotionTrack track = randomTrack(InterpolationMethod::Slerp, {0.0, 0.4, 2.0}, 5);
    const TrackMotion motion(track);
    const double u = 0.3;
    const Eigen::Quaterniond& a = track.keys[1].pose.orientation;
    const Eigen::Quaterniond b = sameHemisphere(track.keys[2].pose.orientation, a);
    const Pose pose = motion.at(0.4 + u * 1.6);
    QVERIFY(distanceUpToSign(pose.orientation, a.slerp(u, b)) < kTolerance);
    const Eigen::Vector3d position = (1 - u) * track.keys[1].pose.position + u * track.keys[2].pose.position;
    QVERIFY((pose.position - position).norm() < kTolerance);
}

void TstTrackEvaluation::holdsTheEndsOutsideTheKeys()
{
    for (const InterpolationMethod method : {InterpolationMethod::Hermite, InterpolationMethod::Screw}) {
        MotionTrack track = randomTrack(method, {1.0, 2.0, 4.0}, 7);
        track.subdivision = {SubdivisionScheme::Jarek, 2, false, false};
        const TrackMotion motion(track);
        QVERIFY(poseDistance(motion.at(-3.0), motion.at(1.0)) < kTolerance);
        QVERIFY(poseDistance(motion.at(9.0), motion.at(4.0)) < kTolerance);
    }
}

// Slerp from a to b over T turns at the constant world rate ω = θ·n/T, where b·a⁻¹ = AngleAxis(θ, n);
// held ends do not turn.
void TstTrackEvaluation::angularVelocityOfSlerpIsTheTurnOverTheSpan()
{
    const MotionTrack track = randomTrack(InterpolationMethod::Slerp, {0.5, 2.5}, 11);
    const TrackMotion motion(track);
    const Eigen::Quaterniond& a = track.keys[0].pose.orientation;
    const Eigen::AngleAxisd turn(sameHemisphere(track.keys[1].pose.orientation, a) * a.conjugate());
    const Eigen::Vector3d expected = turn.angle() * turn.axis() / 2.0;
    for (const double time : {0.7, 1.5, 2.3})
        QVERIFY((motion.angularVelocity(time) - expected).norm() < 1e-6 * expected.norm());
    QVERIFY(motion.angularVelocity(0.0).norm() < kTolerance);
    QVERIFY(motion.angularVelocity(3.0).norm() < kTolerance);
}

// The central difference against the spline's own analytic ω = 2q′q⁻¹.
void TstTrackEvaluation::angularVelocityMatchesTheAnalyticHermite()
{
    const MotionTrack track = randomTrack(InterpolationMethod::Hermite, {0.0, 0.5, 1.5, 2.0, 3.5}, 13);
    std::vector<OrientationKey> keys;
    for (const Keyframe& key : track.keys)
        keys.push_back({key.time, key.pose.orientation});
    const auto spline = makeOrientationCurve(InterpolationMethod::Hermite, keys, {});
    const TrackMotion motion(track);
    for (double time = 0.05; time < 3.5; time += 0.173) {
        const Eigen::Vector3d expected = spline->sample(time).angularVelocity;
        QVERIFY2((motion.angularVelocity(time) - expected).norm() < 1e-6 * (1.0 + expected.norm()),
                 qPrintable(QString::number(time)));
    }
}

// Between keys i and i+1 the track plays the geodesic Lᵢ·exp(u·log(Lᵢ⁻¹Lᵢ₊₁)) at u = p(t) − i, p the key
// times' time map (tested on its own in tst_core_key_time_map).
void TstTrackEvaluation::screwWithoutSubdivisionIsThePlainPolyscrew()
{
    MotionTrack track = randomTrack(InterpolationMethod::Screw, {0.0, 2.0, 3.0}, 3);
    track.subdivision = {SubdivisionScheme::BSpline, 0, false, false};
    const TrackMotion motion(track);
    const KeyTimeMap timeMap(keyTimes(track), false);
    for (const auto& [time, span] : {std::pair{0.25, 0}, {1.0, 0}, {2.25, 1}, {2.9, 1}}) {
        const double u = timeMap.parameterAt(time) - span;
        QVERIFY(u > 0.0 && u < 1.0);
        const Pose expected = fromMatrix(geodesic(track.keys[span].pose, track.keys[span + 1].pose, u));
        GYRE_CHECK(poseDistance(motion.at(time), expected) < kTolerance,
                   QStringLiteral("at %1: %2, expected %3").arg(str(time), str(motion.at(time)), str(expected)));
    }
}

// A cycle of 4 keys over 3 s: the closing span lasts the mean span, 1 s; the period is 4 s.
void TstTrackEvaluation::cyclicScrewClosesAndRepeats()
{
    MotionTrack track = randomTrack(InterpolationMethod::Screw, {1.0, 1.5, 3.0, 4.0}, 9);
    track.subdivision = {SubdivisionScheme::FourPoint, 0, true, false};
    const TrackMotion motion(track);
    const KeyTimeMap timeMap(keyTimes(track), true);
    const Pose closing = fromMatrix(geodesic(track.keys[3].pose, track.keys[0].pose, timeMap.parameterAt(4.25) - 3.0));
    QVERIFY(poseDistance(motion.at(4.25), closing) < kTolerance);
    QVERIFY(poseDistance(motion.at(5.0), track.keys[0].pose) < kTolerance);
    for (const double time : {1.2, 2.0, 3.7, 4.6})
        for (const double periods : {-2.0, 1.0, 3.0})
            QVERIFY(poseDistance(motion.at(time + 4.0 * periods), motion.at(time)) < 1e-8);
}

// Subdivided L levels, span i holds 2^L screws: subdivided pose i·2^L + j plays when p(t) = i + j/2^L.
void TstTrackEvaluation::subdividedScrewPlaysTheSubdividedPoses()
{
    for (const bool cyclic : {false, true}) {
        MotionTrack track = randomTrack(InterpolationMethod::Screw, {0.0, 0.5, 2.0, 2.5}, 13);
        track.subdivision = {SubdivisionScheme::Jarek, 2, cyclic, false};
        std::vector<Pose> controlPoses;
        for (const Keyframe& key : track.keys)
            controlPoses.push_back(key.pose);
        const std::vector<Pose> subdivided = subdividePolyscrew(controlPoses, track.subdivision);
        const TrackMotion motion(track);
        const KeyTimeMap timeMap(keyTimes(track), cyclic);
        const std::size_t spans = cyclic ? 4 : 3;
        for (std::size_t k = 0; k < 4 * spans; ++k)
            QVERIFY(poseDistance(motion.at(timeMap.timeAt(static_cast<double>(k) / 4.0)), subdivided[k]) < kTolerance);
    }
}

// Keys unevenly spaced in time (0, 0.3, 1.5, 1.8, 3.0, 3.4 s; neighbouring spans up to 4× apart): the
// angular speed and the speed of a point just before and just after every key agree to within the
// subdivided polyscrew's own kink there, which shrinks as 2^−L: under 2% at 8 levels (29% at 4). A map
// linear per span scales them by the ratio of the spans besides, 0.25 to 4.
void TstTrackEvaluation::screwSpeedIsContinuousAcrossKeys()
{
    for (const bool cyclic : {false, true}) {
        MotionTrack track = randomTrack(InterpolationMethod::Screw, {0.0, 0.3, 1.5, 1.8, 3.0, 3.4}, 21);
        track.subdivision = {SubdivisionScheme::BSpline, 8, cyclic, false};
        const TrackMotion motion(track);
        const double h = 1e-5;
        const auto pointSpeed = [&](double from, double to) {
            const Eigen::Vector3d corner(1.0, 0.5, -0.25); // a point of the object, in its own frame
            const Pose a = motion.at(from);
            const Pose b = motion.at(to);
            return ((b.orientation * corner + b.position) - (a.orientation * corner + a.position)).norm() / (to - from);
        };
        for (std::size_t i = cyclic ? 0 : 1; i + 1 < track.keys.size(); ++i) {
            const double t = track.keys[i].time;
            const double angularBefore = motion.angularVelocity(t - 2 * h).norm();
            const double angularAfter = motion.angularVelocity(t + 2 * h).norm();
            const double before = pointSpeed(t - 2 * h, t - h);
            const double after = pointSpeed(t + h, t + 2 * h);
            GYRE_CHECK(std::abs(angularAfter / angularBefore - 1.0) < 0.03 && std::abs(after / before - 1.0) < 0.03,
                       QStringLiteral("%1 key %2: angular speed %3 → %4 rad/s, point speed %5 → %6")
                           .arg(cyclic ? "cyclic" : "open")
                           .arg(i)
                           .arg(angularBefore)
                           .arg(angularAfter)
                           .arg(before)
                           .arg(after));
        }
    }
}

void TstTrackEvaluation::fittedCurveOverridesOnlyItsWindow()
{
    MotionTrack track = randomTrack(InterpolationMethod::Slerp, {0.0, 1.0, 2.0, 3.0}, 17);
    Random random(19);
    for (const double time : {0.5, 1.25, 2.5}) {
        HermiteControlPoint point{time, random.rotation(), random.rotation()};
        point.value.coeffs() *= 1.5; // unnormalised on purpose: the track plays the normalised curve
        track.sketch.fittedCurve.push_back(point);
    }
    const std::vector<HermiteControlPoint>& fit = track.sketch.fittedCurve;
    const TrackMotion fitted(track);
    MotionTrack unfitted = track;
    unfitted.sketch.fittedCurve.clear();
    const TrackMotion plain(unfitted);

    for (const double time : {0.5, 0.8, 1.25, 2.0, 2.5}) {
        const std::size_t segment = time < 1.25 ? 0 : 1;
        const Eigen::Quaterniond expected =
            time == 2.5 ? fit[2].value.normalized() : hermite(fit[segment], fit[segment + 1], time);
        GYRE_CHECK(distanceUpToSign(fitted.at(time).orientation, expected) < kTolerance,
                   QStringLiteral("at %1: %2, expected %3").arg(str(time), str(fitted.at(time).orientation), str(expected)));
        QVERIFY((fitted.at(time).position - plain.at(time).position).norm() < kTolerance);
    }
    for (const double time : {0.0, 0.49, 2.51, 3.0}) {
        QVERIFY(poseDistance(fitted.at(time), plain.at(time)) < kTolerance);
        QVERIFY(distanceUpToSign(fitted.at(time).orientation, fit.front().value.normalized()) > 1e-3);
    }
}

// A ballistic track of a body with three different moments: each span offers its flights, the track's choice
// picks one (modulo the count), and the world angular momentum R·I·Rᵀ·ω stays put within each span.
void TstTrackEvaluation::ballisticFliesTheChosenFlights()
{
    MotionTrack track = randomTrack(InterpolationMethod::Ballistic, {0.0, 0.6, 1.1}, 5);
    MassProperties body;
    body.inertia = Eigen::Vector3d(0.6, 1.0, 1.3).asDiagonal();
    body.centre = Eigen::Vector3d(0.1, 0.0, 0.0);
    const TrackMotion byDefault(track, {}, body);
    QCOMPARE(byDefault.flightChoices().size(), std::size_t(2));
    const std::size_t count = byDefault.flightChoices()[1].count;
    QVERIFY(count >= 2);
    track.keys.edit()[1].flightSolution = static_cast<int>(byDefault.flightChoices()[1].chosen + 1);
    const TrackMotion stepped(track, {}, body);
    QCOMPARE(stepped.flightChoices()[0].chosen, byDefault.flightChoices()[0].chosen);
    QCOMPARE(stepped.flightChoices()[1].chosen, (byDefault.flightChoices()[1].chosen + 1) % count);
    QVERIFY(poseDistance(stepped.at(0.3), byDefault.at(0.3)) < kTolerance);
    QVERIFY(poseDistance(stepped.at(0.85), byDefault.at(0.85)) > 1e-3);
    for (const Keyframe& key : track.keys)
        QVERIFY(poseDistance(stepped.at(key.time), key.pose) < kTolerance);
    const auto momentum = [&](double t) {
        const Eigen::Matrix3d r = stepped.at(t).orientation.toRotationMatrix();
        return Eigen::Vector3d(r * body.inertia * r.transpose() * stepped.angularVelocity(t));
    };
    for (double t = 0.7; t < 1.05; t += 0.05)  // central differences: good to about 1e-8
        QVERIFY((momentum(t) - momentum(0.65)).norm() < 1e-6 * momentum(0.65).norm());
}

void TstTrackEvaluation::trackWithoutKeysStaysAtIdentity()
{
    const TrackMotion motion{MotionTrack{}};
    QVERIFY(poseDistance(motion.at(1.5), Pose{}) == 0.0);
}

void TstTrackEvaluation::refusesKeysOutOfOrder()
{
    for (const InterpolationMethod method : {InterpolationMethod::Slerp, InterpolationMethod::Screw}) {
        const MotionTrack track = randomTrack(method, {0.0, 2.0, 2.0}, 23);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, TrackMotion{track});
    }
    MotionTrack track = randomTrack(InterpolationMethod::Slerp, {0.0, 2.0}, 23);
    track.sketch.fittedCurve = {HermiteControlPoint{1.0}, HermiteControlPoint{0.5}};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, TrackMotion{track});
}

// Frames 0.1 + k/4 up to 1.0 and the keys inside the range; the frames at 0.35 and 0.6 give way to
// the keys within 1e-9 s of them.
void TstTrackEvaluation::bakeSamplesFramesAndKeys()
{
    const std::vector<double> keys{0.0, 0.35, 0.6000000001, 0.95, 1.2};
    const BakeRange range{0.1, 1.0, 4.0};
    std::vector<double> expected;
    for (const double key : keys)
        if (key >= range.start && key <= range.end)
            expected.push_back(key);
    for (int k = 0; range.start + k / range.fps <= range.end; ++k) {
        const double frame = range.start + k / range.fps;
        if (std::ranges::none_of(keys, [frame](double key) { return std::abs(key - frame) <= 1e-9; }))
            expected.push_back(frame);
    }
    std::ranges::sort(expected);
    QCOMPARE(expected.size(), std::size_t{5}); // 0.1, 0.35, 0.6000000001, 0.85, 0.95
    QCOMPARE(bakeTimes(keys, range), expected);
    QVERIFY(bakeSampleBound(range, keys.size()) >= 5.0);
}

void TstTrackEvaluation::bakeTrackGivesThePosesAtItsTimes()
{
    const MotionTrack track = randomTrack(InterpolationMethod::Squad, {0.0, 0.35, 1.0}, 29);
    const std::vector<TimedPose> baked = bakeTrack(track, {0.0, 1.0, 10.0});
    QCOMPARE(baked.size(), std::size_t{12}); // eleven frames and the key at 0.35
    QCOMPARE(baked[4].time, 0.35);
    QVERIFY(poseDistance(baked[4].pose, track.keys[1].pose) < kTolerance);
    QVERIFY(poseDistance(baked.back().pose, track.keys[2].pose) < kTolerance);
}

void TstTrackEvaluation::bakeRefusesBadRanges()
{
    const std::vector<double> keys{0.0, 1.0};
    for (const BakeRange& range : {BakeRange{0, 1, 0}, BakeRange{0, 1, -24}, BakeRange{0, 1, std::nan("")},
                                   BakeRange{2, 1, 24}, BakeRange{0, INFINITY, 24}})
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bakeTimes(keys, range));
}

QTEST_GUILESS_MAIN(TstTrackEvaluation)
#include "tst_track_evaluation.moc"
