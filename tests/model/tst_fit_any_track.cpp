// The sketch fit on a track of any interpolation (issue 20's "Sketch-edit any track"): a screw track's
// subdivided, retimed polyscrew and every keyed interpolation are the motion the fit starts from and
// keeps outside its window, joined C¹ at the window's ends; a screw track keeps its keys and positions;
// a cyclic screw track repeats its fit; and the report's error measures only what was drawn.

#include "model/commands/apply_fit_result_command.h"
#include "model/sketch_fit_problem.h"
#include "model/track_evaluation.h"

#include <QObject>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace gyre;
using namespace gyre::model;

Q_DECLARE_METATYPE(gyre::model::MotionTrack)

namespace {

// Window ends between keys, so that both are held ends.
constexpr double kWindowStart = 0.8;
constexpr double kWindowEnd = 3.3;

// A tumble: a turn about z at 1.2 rad/s while it rocks about x at 4 rad/s, q(t) = Rz(1.2t)·Rx(0.3 + 0.25 sin 4t).
Eigen::Quaterniond tumbleAt(double time)
{
    return Eigen::Quaterniond(Eigen::AngleAxisd(1.2 * time, Eigen::Vector3d::UnitZ()) *
                              Eigen::AngleAxisd(0.3 + 0.25 * std::sin(4.0 * time), Eigen::Vector3d::UnitX()));
}

// The tumble keyed every half second over [0, 4] s, too sparsely to carry the rocking, moving along a
// line; every key constrained.
MotionTrack tumble(InterpolationMethod interpolation)
{
    MotionTrack track;
    track.interpolation = interpolation;
    track.subdivision = SubdivisionSettings{SubdivisionScheme::FourPoint, 4, false, false};
    for (int i = 0; i <= 8; ++i) {
        const double time = 0.5 * i;
        track.keys.push_back({time, {tumbleAt(time), Eigen::Vector3d(time, 0.5 * time, 1.0)}, true});
    }
    return track;
}

// A stroke from 1 s to 3 s along the tumble's own axis, ω/|ω| by a central difference, and a window
// around it: what the keys alone miss.
SketchState tumbleAxisSketch()
{
    SketchState sketch;
    DirectionStroke stroke;
    constexpr double kStep = 1e-6;
    for (int i = 0; i <= 80; ++i) {
        const double time = 1.0 + 2.0 * i / 80.0;
        const Eigen::AngleAxisd turn(tumbleAt(time + kStep) * tumbleAt(time - kStep).conjugate());
        stroke.points.push_back(turn.axis());
        stroke.times.push_back(time);
    }
    sketch.directionStrokes.push_back(stroke);
    sketch.window = std::pair(kWindowStart, kWindowEnd);
    return sketch;
}

MotionTrack fitted(const MotionTrack& track)
{
    const fit::FitResult result = fitSketch(sketchFitProblem(track, {}));
    return withFitApplied(track, appliedFitResult(track, result));
}

double angle(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    return a.angularDistance(b);
}

} // namespace

class TstFitAnyTrack : public QObject {
    Q_OBJECT

private slots:
    void everyInterpolationIsFittedFromItsOwnMotion_data();
    void everyInterpolationIsFittedFromItsOwnMotion();
    void aScrewTrackKeepsItsKeysAndPositions();
    void aCyclicScrewTrackRepeatsItsFit();
    void drawnErrorMeasuresOnlyWhatWasDrawn();
    void aBallisticTrackIsFittedFromTheBodyItFlies();
};

void TstFitAnyTrack::everyInterpolationIsFittedFromItsOwnMotion_data()
{
    QTest::addColumn<MotionTrack>("track");
    for (const InterpolationMethod method : {InterpolationMethod::Slerp, InterpolationMethod::Nlerp,
                                             InterpolationMethod::Squad, InterpolationMethod::Hermite,
                                             InterpolationMethod::Euler, InterpolationMethod::Screw})
        QTest::newRow(interpolationMethodName(method).data()) << tumble(method);
    MotionTrack bspline = tumble(InterpolationMethod::Screw);
    bspline.subdivision.scheme = SubdivisionScheme::BSpline;
    QTest::newRow("screw, B-spline") << bspline;
}

// Outside the window the fitted track is the keyed one exactly; across each window end the
// orientation and ω are continuous (a fit that started from another curve than the track's own would
// jump in ω there by tenths of a rad/s); a constrained key's time keeps the orientation the motion
// through the keys has there; and the motion now follows the drawn axis more closely (less so on a
// B-spline screw track, whose constrained orientations are the subdivided ones, off the tumble).
void TstFitAnyTrack::everyInterpolationIsFittedFromItsOwnMotion()
{
    QFETCH(MotionTrack, track);
    track.sketch = tumbleAxisSketch();
    const SketchFitProblem problem = sketchFitProblem(track, {});
    const fit::FitResult result = fitSketch(problem);
    const FitResult applied = appliedFitResult(track, result);
    const TrackMotion keyed(track);
    const TrackMotion edited(withFitApplied(track, applied));

    for (double time = 0.0; time <= 4.0; time += 0.01)
        if (time < kWindowStart || time > kWindowEnd)
            QVERIFY2(angle(edited.at(time).orientation, keyed.at(time).orientation) == 0.0, qPrintable(QString::number(time)));
    constexpr double kStep = 1e-4;
    for (const double end : {kWindowStart, kWindowEnd}) {
        const double jump = angle(edited.at(end - kStep).orientation, edited.at(end + kStep).orientation);
        QVERIFY2(jump < 3.0 * kStep * keyed.angularVelocity(end).norm(), qPrintable(QString::number(jump)));
        const double omegaJump = (edited.angularVelocity(end - 3 * kStep) - edited.angularVelocity(end + 3 * kStep)).norm();
        QVERIFY2(omegaJump < 0.01, qPrintable(QStringLiteral("ω jumps by %1 rad/s at %2 s").arg(omegaJump).arg(end)));
    }
    for (const Keyframe& key : track.keys)
        if (key.time > kWindowStart && key.time < kWindowEnd)
            QVERIFY(angle(edited.at(key.time).orientation, keyed.at(key.time).orientation) < 1e-12);

    const DrawnErrors drawn = drawnErrors(track, *problem.motionWithoutFit, applied, {});
    QVERIFY2(drawn.after < 0.7 * drawn.before, qPrintable(QStringLiteral("%1 → %2").arg(drawn.before).arg(drawn.after)));
}

// The fit never moves a screw track's keys, even freed ones, and leaves its positions as the polyscrew
// makes them; it keeps a constrained key's time at the polyscrew's orientation, which B-spline
// subdivision takes away from the key's own.
void TstFitAnyTrack::aScrewTrackKeepsItsKeysAndPositions()
{
    MotionTrack track = tumble(InterpolationMethod::Screw);
    track.subdivision.scheme = SubdivisionScheme::BSpline;
    track.sketch = tumbleAxisSketch();
    track.keys[4].constrained = false;
    const SketchFitProblem problem = sketchFitProblem(track, {});
    const TrackMotion keyed(track);
    QVERIFY(problem.initialMotion);
    QVERIFY(angle(problem.keys[3].rotation, keyed.at(1.5).orientation) < 1e-15);
    QVERIFY(angle(track.keys[3].pose.orientation, keyed.at(1.5).orientation) > 1e-3);

    const fit::FitResult result = fitSketch(problem);
    const FitResult applied = appliedFitResult(track, result);
    QVERIFY(std::ranges::equal(applied.keys, track.keys.vector(), [](const Keyframe& a, const Keyframe& b) {
        return a.time == b.time && a.constrained == b.constrained && a.pose.position == b.pose.position
               && a.pose.orientation.coeffs() == b.pose.orientation.coeffs();
    }));
    const MotionTrack edited = withFitApplied(track, applied);
    QVERIFY(edited.sketch.keysBeforeFit.empty());
    const TrackMotion editedMotion(edited);
    for (double time = 0.0; time <= 4.0; time += 0.05)
        QCOMPARE(editedMotion.at(time).position, keyed.at(time).position);
}

// A cyclic screw track plays its fit in every cycle, and the first cycle is the fitted one itself.
void TstFitAnyTrack::aCyclicScrewTrackRepeatsItsFit()
{
    MotionTrack track = tumble(InterpolationMethod::Screw);
    track.subdivision.cyclic = true;
    track.sketch = tumbleAxisSketch();
    const MotionTrack edited = fitted(track);
    const TrackMotion keyed(track);
    const TrackMotion editedMotion(edited);
    const double period = 9.0 * 4.0 / 8.0;  // n·(tₙ₋₁ − t₀)/(n − 1) for 9 keys over 4 s
    double largestEdit = 0.0;
    for (double time = kWindowStart; time <= kWindowEnd; time += 0.05) {
        largestEdit = std::max(largestEdit, angle(editedMotion.at(time).orientation, keyed.at(time).orientation));
        for (const int cycle : {-1, 1, 2})
            QVERIFY(angle(editedMotion.at(time + cycle * period).orientation, editedMotion.at(time).orientation) < 1e-9);
    }
    QVERIFY2(largestEdit > 0.05, qPrintable(QString::number(largestEdit)));
}

// Keys of a steady 3 rad/s spin about z. Drawn: only the axis z, then only the speed 3 rad/s, then
// both as 2 rad/s about z; the error counts only what was drawn: zero for the first two, (3 − 2)² rad²/s²
// over the 2 s drawn for the third.
void TstFitAnyTrack::drawnErrorMeasuresOnlyWhatWasDrawn()
{
    MotionTrack spin;
    spin.interpolation = InterpolationMethod::Slerp;  // exactly steady between the keys
    for (int i = 0; i <= 8; ++i)
        spin.keys.push_back({0.5 * i, {Eigen::Quaterniond(Eigen::AngleAxisd(1.5 * i, Eigen::Vector3d::UnitZ())),
                                       Eigen::Vector3d::Zero()}, true});
    const TrackMotion motion(spin);

    MotionTrack axisDrawn = spin;
    axisDrawn.sketch.directionStrokes.push_back({{Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ()}, {1.0, 3.0}});
    QVERIFY(drawnError(axisDrawn, motion) < 1e-9);

    MotionTrack speedDrawn = spin;
    speedDrawn.sketch.magnitude = {{1.0, 3.0}, {3.0, 3.0}};
    QVERIFY(drawnError(speedDrawn, motion) < 1e-9);

    MotionTrack bothDrawn = axisDrawn;
    bothDrawn.sketch.magnitude = {{1.0, 2.0}, {3.0, 2.0}};
    QVERIFY2(std::abs(drawnError(bothDrawn, motion) - 2.0) < 1e-6, qPrintable(QString::number(drawnError(bothDrawn, motion))));

    // Nothing sketched: nothing to measure.
    QCOMPARE(drawnError(spin, motion), 0.0);
}

// A ballistic track's fit starts from the free flight of the body it is given, the one the document plays
// (flightBodyOf), not from a default body's: a long flat box flies differently from a unit sphere between
// the same keys, and the fit's motion through the keys is the box's at every time.
void TstFitAnyTrack::aBallisticTrackIsFittedFromTheBodyItFlies()
{
    MotionTrack track = tumble(InterpolationMethod::Ballistic);
    track.keys.resize(2); // one span, 0 to 0.5 s: each motion below solves one flight
    SketchState& sketch = track.sketch;
    sketch.directionStrokes = {{{Eigen::Vector3d::UnitZ(), Eigen::Vector3d(0, 1, 1).normalized()}, {0.15, 0.35}}};
    sketch.window = std::pair(0.1, 0.4);
    const MassProperties box{3.0, Eigen::Vector3d(0.1, 0.0, -0.2), Eigen::Vector3d(0.5, 2.0, 2.4).asDiagonal()};
    const SketchFitProblem problem = sketchFitProblem(track, box);
    const TrackMotion flown(track, {}, box);
    const TrackMotion sphere(track, {}, MassProperties{});
    double sphereApart = 0.0;
    for (double time = 0.0; time <= 0.5; time += 0.025) {
        QCOMPARE(angle(problem.motionWithoutFit->at(time).orientation, flown.at(time).orientation), 0.0);
        sphereApart = std::max(sphereApart, angle(sphere.at(time).orientation, flown.at(time).orientation));
    }
    QVERIFY2(sphereApart > 1e-3, qPrintable(QString::number(sphereApart)));
}

QTEST_GUILESS_MAIN(TstFitAnyTrack)
#include "tst_fit_any_track.moc"
