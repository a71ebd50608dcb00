// From a track's sketch to the fit's problem and back: the edit window, the strokes as the fit reads
// them, the target (strokes over the motion's own direction, the sketched magnitude over its own
// speed), the refusals, and the result as the document applies it.

#include "model/fit_input.h"
#include "model/sketch_fit_problem.h"
#include "model/track_evaluation.h"

#include <QObject>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace gyre;
using namespace gyre::model;

namespace {

constexpr double kTolerance = 1e-9;

// A steady spin of 1 rad/s about z, keyed every second over [0, 4] s.
MotionTrack steadySpin()
{
    MotionTrack track;
    track.interpolation = InterpolationMethod::Hermite;
    for (int second = 0; second <= 4; ++second)
        track.keys.push_back({double(second), {Eigen::Quaterniond(Eigen::AngleAxisd(second, Eigen::Vector3d::UnitZ())), Eigen::Vector3d::Zero()}, true});
    return track;
}

DirectionStroke timedStroke(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double start, double end)
{
    return {{from.normalized(), to.normalized()}, {start, end}};
}

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

// steadySpin with its middle key free and a stroke tilting the spin towards x over [1, 3] s.
MotionTrack tiltedSpinWithAFreeKey()
{
    MotionTrack track = steadySpin();
    track.keys[2].constrained = false;
    const Eigen::Vector3d tilted = Eigen::Vector3d(1, 0, 1).normalized();
    track.sketch.directionStrokes.push_back(timedStroke(Eigen::Vector3d::UnitZ(), tilted, 1.0, 3.0));
    return track;
}

Eigen::Quaterniond turnedAboutX(const Eigen::Quaterniond& orientation, double angle)
{
    return orientation * Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX()));
}

// ∫ |ω − ωˢ|² dt over the problem's window, by the midpoint rule at 100 samples per second.
double deviationFromTarget(const TrackMotion& motion, const SketchFitProblem& problem)
{
    const fit::TimeWindow window = *problem.settings.window;
    const int count = static_cast<int>(std::ceil((window.end - window.start) * 100.0));
    const double step = (window.end - window.start) / count;
    double sum = 0.0;
    for (int i = 0; i < count; ++i) {
        const double time = window.start + (i + 0.5) * step;
        sum += (motion.angularVelocity(time) - problem.target.at(time)).squaredNorm() * step;
    }
    return sum;
}

template <class Call>
bool refusesWith(Call call, const char* words)
{
    try {
        call();
    } catch (const SketchFitError& error) {
        return QString::fromUtf8(error.what()).contains(QLatin1String(words));
    }
    return false;
}

} // namespace

class TstSketchFitProblem : public QObject {
    Q_OBJECT

private slots:
    void editWindowIsTheSketchedSpanWithinTheKeys();
    void untimedStrokesSpreadOverTheWindow();
    void patternFollowsTheStroke();
    void targetFollowsStrokesAndKeepsTheMotionElsewhere();
    void laterStrokeWinsWhereStrokesOverlap();
    void sketchedMagnitudeSetsTheSpeed();
    void settingsComeFromTheSketch();
    void refusesWhatCannotBeFitted();
    void appliedResultKeepsConstrainedKeysAndLeansTowardsTheSketch();
    void cheapChecksRefuseAsTheProblemDoes();
    void fittingAgainStartsFromTheKeysBeforeTheFit();
    void aKeyTurnedSinceTheFitReadItDropsItsResult();
};

void TstSketchFitProblem::editWindowIsTheSketchedSpanWithinTheKeys()
{
    MotionTrack track = steadySpin();
    QVERIFY(!editWindow(track));

    track.sketch.directionStrokes.push_back(timedStroke(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 1.0, 2.0));
    track.sketch.magnitude = {{1.5, 1.0}, {3.0, 2.0}};
    auto window = editWindow(track);
    QVERIFY(window);
    QCOMPARE(window->start, 1.0);
    QCOMPARE(window->end, 3.0);

    track.sketch.window = std::pair(-1.0, 2.5);
    window = editWindow(track);
    QVERIFY(window);
    QCOMPARE(window->start, 0.0);
    QCOMPARE(window->end, 2.5);

    track.sketch.window = std::pair(5.0, 6.0);
    QVERIFY(!editWindow(track));

    track.keys.resize(1);
    track.sketch.window.reset();
    QVERIFY(!editWindow(track));
}

void TstSketchFitProblem::untimedStrokesSpreadOverTheWindow()
{
    MotionTrack track = steadySpin();
    track.sketch.directionStrokes.push_back({{Eigen::Vector3d::UnitX(), Eigen::Vector3d(1, 1, 0).normalized(), Eigen::Vector3d::UnitY()}, {}});
    const auto window = editWindow(track);
    QVERIFY(window);
    QCOMPARE(window->start, 0.0);
    QCOMPARE(window->end, 4.0);

    const auto strokes = timedStrokes(track);
    QCOMPARE(strokes.size(), std::size_t(1));
    QCOMPARE(strokes[0].size(), std::size_t(3));
    QCOMPARE(strokes[0].front().time, 0.0);
    QCOMPARE(strokes[0].back().time, 4.0);
    // The two arcs are equally long (45° each), so the middle point falls half way.
    QVERIFY(std::abs(strokes[0][1].time - 2.0) < kTolerance);
}

void TstSketchFitProblem::patternFollowsTheStroke()
{
    MotionTrack track = steadySpin();
    track.sketch.directionStrokes.push_back(timedStroke(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 1.0, 3.0));
    track.sketch.pattern = {{0.0, 0.0}, {0.5, 0.3}, {1.0, 0.0}};
    track.sketch.patternRepeat = 4;

    const auto strokes = timedStrokes(track);
    QCOMPARE(strokes.size(), std::size_t(1));
    QVERIFY(strokes[0].size() > 2);
    QVERIFY(std::abs(strokes[0].front().time - 1.0) < kTolerance);
    QVERIFY(std::abs(strokes[0].back().time - 3.0) < kTolerance);
    double furthest = 0.0;
    for (const fit::TimedVector& point : strokes[0]) {
        QVERIFY(std::abs(point.value.norm() - 1.0) < kTolerance);
        furthest = std::max(furthest, std::abs(point.value.z())); // off the x–y great circle
    }
    QVERIFY(furthest > 0.05);

    track.sketch.patternRepeat = 0;
    QCOMPARE(timedStrokes(track)[0].size(), std::size_t(2));
}

void TstSketchFitProblem::targetFollowsStrokesAndKeepsTheMotionElsewhere()
{
    MotionTrack track = steadySpin();
    track.sketch.window = std::pair(0.5, 3.5);
    track.sketch.directionStrokes.push_back(timedStroke(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 1.0, 3.0));
    const SketchFitProblem problem = sketchFitProblem(track, {});

    // Half way along the great arc from x to y.
    const Eigen::Vector3d middle = problem.target.at(2.0);
    QVERIFY(angleBetween(middle, Eigen::Vector3d(1, 1, 0)) < 1e-6);
    // No magnitude is sketched: the spin keeps its own speed, about 1 rad/s.
    QVERIFY(std::abs(middle.norm() - 1.0) < 0.05);
    // Outside the stroke the motion's own axis, z.
    for (const double time : {0.75, 3.25}) {
        const Eigen::Vector3d omega = problem.target.at(time);
        QVERIFY(angleBetween(omega, Eigen::Vector3d::UnitZ()) < 1e-6);
        QVERIFY(std::abs(omega.norm() - 1.0) < 0.05);
    }
}

void TstSketchFitProblem::laterStrokeWinsWhereStrokesOverlap()
{
    MotionTrack track = steadySpin();
    track.sketch.directionStrokes.push_back(timedStroke(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 1.0, 3.0));
    track.sketch.directionStrokes.push_back(timedStroke(Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(), 1.5, 2.5));
    const SketchFitProblem problem = sketchFitProblem(track, {});
    QVERIFY(angleBetween(problem.target.at(2.0), Eigen::Vector3d(1, 0, 1)) < 1e-6);
    // Before the later stroke starts, the earlier one: at 1.25 s an eighth of the way from x to y.
    const double turned = (1.25 - 1.0) / (3.0 - 1.0) * std::numbers::pi / 2.0;
    QVERIFY(angleBetween(problem.target.at(1.25), Eigen::Vector3d(std::cos(turned), std::sin(turned), 0)) < 1e-6);
}

void TstSketchFitProblem::sketchedMagnitudeSetsTheSpeed()
{
    MotionTrack track = steadySpin();
    track.sketch.magnitude = {{1.0, 2.0}, {3.0, 4.0}};
    const SketchFitProblem problem = sketchFitProblem(track, {});
    const Eigen::Vector3d omega = problem.target.at(2.0);
    QVERIFY(std::abs(omega.norm() - 3.0) < 1e-9);
    QVERIFY(angleBetween(omega, Eigen::Vector3d::UnitZ()) < 1e-6);
    QCOMPARE(problem.target.startTime(), 1.0);
    QCOMPARE(problem.target.endTime(), 3.0);
}

void TstSketchFitProblem::settingsComeFromTheSketch()
{
    MotionTrack track = steadySpin();
    track.keys[2].constrained = false;
    track.sketch.magnitude = {{1.0, 2.0}, {3.0, 4.0}};
    track.sketch.alpha = 0.004;
    track.sketch.beta = 2.0;
    track.sketch.delta = 0.3;
    track.sketch.window = std::pair(0.5, 3.5);
    const SketchFitProblem problem = sketchFitProblem(track, {});
    QCOMPARE(problem.settings.alpha, 0.004);
    QCOMPARE(problem.settings.beta, 2.0);
    QCOMPARE(problem.settings.delta, 0.3);
    QVERIFY(problem.settings.window);
    QCOMPARE(problem.settings.window->start, 0.5);
    QCOMPARE(problem.settings.window->end, 3.5);
    QCOMPARE(problem.keys.size(), track.keys.size());
    QVERIFY(!problem.keys[2].constrained);
    QVERIFY(problem.keys[3].rotation.isApprox(track.keys[3].pose.orientation, 0.0));
}

void TstSketchFitProblem::refusesWhatCannotBeFitted()
{
    MotionTrack track = steadySpin();
    QVERIFY(refusesWith([&] { sketchFitProblem(track, {}); }, "Nothing is sketched"));
    track.sketch.magnitude = {{1.0, 2.0}, {3.0, 4.0}};
    track.sketch.window = std::pair(5.0, 6.0);
    QVERIFY(refusesWith([&] { sketchFitProblem(track, {}); }, "window"));
    track.keys.resize(1);
    QVERIFY(refusesWith([&] { sketchFitProblem(track, {}); }, "two keyframes"));
}

void TstSketchFitProblem::appliedResultKeepsConstrainedKeysAndLeansTowardsTheSketch()
{
    // Free every key after the window's start, so the motion can follow the sketch to the end.
    MotionTrack track = steadySpin();
    for (std::size_t i = 1; i < track.keys.size(); ++i)
        track.keys[i].constrained = false;
    track.sketch.window = std::pair(0.5, 4.0);
    const Eigen::Vector3d tilted = Eigen::Vector3d(1, 0, 1).normalized();
    track.sketch.directionStrokes.push_back(timedStroke(tilted, tilted, 1.0, 3.0));
    track.sketch.directionStrokes.back().points = {tilted, Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitZ()) * tilted};

    const SketchFitProblem problem = sketchFitProblem(track, {});
    const fit::FitResult result = model::fitSketch(problem);
    const FitResult applied = appliedFitResult(track, result);

    QCOMPARE(applied.curve.size(), result.controlPoints.size());
    QCOMPARE(applied.keys.size(), track.keys.size());
    for (std::size_t i = 0; i < track.keys.size(); ++i) {
        QCOMPARE(applied.keys[i].time, track.keys[i].time);
        QCOMPARE(applied.keys[i].constrained, track.keys[i].constrained);
        const Eigen::Quaterniond expected = track.keys[i].constrained ? track.keys[i].pose.orientation : result.keys[i].rotation;
        QVERIFY(applied.keys[i].pose.orientation.coeffs() == expected.coeffs());
    }

    MotionTrack fitted = track;
    fitted.keys = applied.keys;
    fitted.sketch.fittedCurve = applied.curve;
    const double before = deviationFromTarget(TrackMotion(track), problem);
    const double after = deviationFromTarget(TrackMotion(fitted), problem);
    QVERIFY2(after < 0.5 * before, qPrintable(QStringLiteral("%1 rad²/s before, %2 after").arg(before).arg(after)));
}

// checkSketchFittable, which the fit panel runs at every edit, refuses what sketchFitProblem refuses
// before it builds anything, with the same message, and passes what it builds.
void TstSketchFitProblem::cheapChecksRefuseAsTheProblemDoes()
{
    const auto sameRefusal = [](const MotionTrack& track, const char* words) {
        return refusesWith([&] { checkSketchFittable(track); }, words)
               && refusesWith([&] { sketchFitProblem(track, {}); }, words);
    };
    MotionTrack track = steadySpin();
    QVERIFY(sameRefusal(track, "Nothing is sketched"));
    track.sketch.magnitude = {{1.0, 2.0}, {3.0, 4.0}};
    checkSketchFittable(track);
    sketchFitProblem(track, {});
    track.sketch.pattern = {{0, 0}, {1, 0}};
    track.sketch.patternRepeat = 1 << 20;
    QVERIFY(sameRefusal(track, "pattern"));
    track.sketch.patternRepeat = 0;
    track.sketch.window = std::pair(5.0, 6.0);
    QVERIFY(sameRefusal(track, "window"));
    track.keys.resize(1);
    QVERIFY(sameRefusal(track, "two keyframes"));
}

// The fit reads the track without its fit, the keys the last fit moved put back: fitting a fitted
// track again reads what the first fit read and gives the same result, to the last bit.
void TstSketchFitProblem::fittingAgainStartsFromTheKeysBeforeTheFit()
{
    const MotionTrack track = tiltedSpinWithAFreeKey();
    const SketchFitProblem first = sketchFitProblem(track, {});
    const FitResult applied = appliedFitResult(track, fitSketch(first));
    const MotionTrack fitted = withFitApplied(track, applied);
    QVERIFY(fitted.keys[2].pose.orientation.coeffs() != track.keys[2].pose.orientation.coeffs()); // the fit turned it
    QCOMPARE(fitted.sketch.keysBeforeFit.size(), std::size_t{1});

    const SketchFitProblem again = sketchFitProblem(fitted, {});
    QCOMPARE(again.keys.size(), first.keys.size());
    for (std::size_t i = 0; i < first.keys.size(); ++i)
        QVERIFY2(again.keys[i].rotation.coeffs() == first.keys[i].rotation.coeffs(), qPrintable(QString::number(i)));
    for (double time = 1.0; time <= 3.0; time += 0.125)
        QCOMPARE(again.target.at(time), first.target.at(time));
    const FitResult reapplied = appliedFitResult(fitted, fitSketch(again));
    QCOMPARE(reapplied.curve.size(), applied.curve.size());
    for (std::size_t i = 0; i < applied.curve.size(); ++i)
        QVERIFY(reapplied.curve[i].value.coeffs() == applied.curve[i].value.coeffs());
    for (std::size_t i = 0; i < applied.keys.size(); ++i)
        QVERIFY(reapplied.keys[i].pose.orientation.coeffs() == applied.keys[i].pose.orientation.coeffs());
    // Applied again, it leaves the keys as they were before any fit to restore.
    const MotionTrack refitted = withFitApplied(fitted, reapplied);
    QCOMPARE(refitted.sketch.keysBeforeFit.size(), std::size_t{1});
    QVERIFY(withoutFit(refitted).keys[2].pose.orientation.coeffs() == track.keys[2].pose.orientation.coeffs());
}

// A fit's result is dropped when a key it read or would replace was turned after it read the track,
// a free key included; the track it was made from, or that track with the result applied, takes it.
void TstSketchFitProblem::aKeyTurnedSinceTheFitReadItDropsItsResult()
{
    const MotionTrack track = tiltedSpinWithAFreeKey();
    const FitResult applied = appliedFitResult(track, fitSketch(sketchFitProblem(track, {})));
    QVERIFY(fitResultApplies(track, track, applied));
    const MotionTrack fitted = withFitApplied(track, applied);
    QVERIFY(sameFitInput(track, fitted)); // applying a fit changes nothing the next fit reads
    QVERIFY(fitResultApplies(track, fitted, applied));

    // The free key turned while the fit ran: the fit read another track.
    MotionTrack turned = track;
    turned.keys[2].pose.orientation = turnedAboutX(track.keys[2].pose.orientation, 0.3);
    QVERIFY(!sameFitInput(track, turned));
    QVERIFY(!fitResultApplies(track, turned, applied));

    // A refit of the fitted track, whose free key the artist turns while it runs: the fit reads the key
    // as it was before the first fit, the same either way, but its result would undo the turn.
    const FitResult reapplied = appliedFitResult(fitted, fitSketch(sketchFitProblem(fitted, {})));
    MotionTrack turnedAfterFit = fitted;
    turnedAfterFit.keys[2].pose.orientation = turnedAboutX(fitted.keys[2].pose.orientation, 0.3);
    QVERIFY(sameFitInput(fitted, turnedAfterFit));
    QVERIFY(!fitResultApplies(fitted, turnedAfterFit, reapplied));
    QVERIFY(fitResultApplies(fitted, fitted, reapplied));
}

QTEST_GUILESS_MAIN(TstSketchFitProblem)
#include "tst_sketch_fit_problem.moc"
