// One behaviour for a sketch: gyre-cli fit on a project's object gives the motion the app's Fit gives
// (the model's sketchFitProblem and appliedFitResult, which FitJob runs, applied as
// ApplyFitResultCommand applies them), and the same sketch given to gyre-cli as files gives the same.

#include "cli_test_support.h"
#include "fit/angular_velocity_fit.h"
#include "model/commands/apply_fit_result_command.h"
#include "model/project_file.h"
#include "model/sketch_fit_problem.h"
#include "model/track_evaluation.h"

#include <QTest>

#include <cmath>

using namespace gyre;
using namespace gyre::test;

namespace {

constexpr double kFps = 30.0;
// The CLI and this test run the same code on the same numbers; only the CSV text's round trip and a
// normalisation may differ in the last bits.
constexpr double kSame = 1e-12;

// A top tumbling about a leaning axis while it turns about z, keyed every half second over 4 s, its
// centre moving along a line.
model::MotionTrack tumblingTrack()
{
    model::MotionTrack track;
    track.interpolation = InterpolationMethod::Hermite;
    const Eigen::Vector3d axis = Eigen::Vector3d(0.3, 0.2, 1.0).normalized();
    for (int i = 0; i <= 8; ++i) {
        const double time = 0.5 * i;
        const Eigen::Quaterniond orientation =
            Eigen::AngleAxisd(0.6 * time, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(2.0 * time, axis);
        track.keys.push_back({time, {orientation, Eigen::Vector3d(time, 0.0, 1.0)}, i % 3 != 1});
    }
    return track;
}

// A timed stroke from 1 s to 3 s that bends the spin axis over, and a drawn speed from 1.5 s to 3.5 s:
// each covers part of the window the other does not, so both rules for what is not drawn are used.
model::SketchState bentSketch()
{
    model::SketchState sketch;
    model::DirectionStroke stroke;
    for (int i = 0; i <= 8; ++i) {
        const double u = i / 8.0;
        stroke.points.push_back(Eigen::Vector3d(0.6 * std::sin(3.0 * u), 0.5 * u, 1.0).normalized());
        stroke.times.push_back(1.0 + 2.0 * u);
    }
    sketch.directionStrokes.push_back(stroke);
    for (int i = 0; i <= 4; ++i)
        sketch.magnitude.push_back({1.5 + 0.5 * i, 2.0 + 0.8 * std::sin(0.8 * i)});
    return sketch;
}

model::Scene sceneOf(const model::MotionTrack& track)
{
    model::SceneObject object;
    object.id = 1;
    object.name = QStringLiteral("top");
    object.track = track;
    model::Scene scene;
    scene.objects.push_back(object);
    scene.fps = kFps;
    scene.startTime = track.keys.front().time;
    scene.endTime = track.keys.back().time;
    scene.nextObjectId = 2;
    return scene;
}

// What the app's Fit does to the track: the fit of its sketch, applied; baked over its keys' span.
std::vector<model::TimedPose> appFit(const model::MotionTrack& track)
{
    const model::SketchFitProblem problem = model::sketchFitProblem(track, {});
    const fit::FitResult result = model::fitSketch(problem);
    const model::MotionTrack fitted = model::withFitApplied(track, model::appliedFitResult(track, result));
    return model::bakeTrack(fitted, {track.keys.front().time, track.keys.back().time, kFps});
}

// The largest difference between the frames and the poses: the angle between orientations, the
// distance between positions; infinite when their times differ.
double largestDifference(const Csv& frames, const std::vector<model::TimedPose>& poses)
{
    if (!frames.problem.isEmpty() || frames.rows.size() != poses.size())
        return INFINITY;
    double largest = 0.0;
    for (std::size_t row = 0; row < poses.size(); ++row) {
        if (std::abs(frames.at(row, "time") - poses[row].time) > kSame)
            return INFINITY;
        largest = std::max({largest, frames.quaternion(row).normalized().angularDistance(poses[row].pose.orientation),
                            (frames.position(row) - poses[row].pose.position).norm()});
    }
    return largest;
}

QByteArray keysCsv(const model::MotionTrack& track)
{
    QByteArray text = "time,qw,qx,qy,qz,x,y,z\n";
    for (const model::Keyframe& key : track.keys) {
        const Eigen::Quaterniond& q = key.pose.orientation;
        const Eigen::Vector3d& p = key.pose.position;
        text += QStringList{number(key.time), number(q.w()), number(q.x()), number(q.y()), number(q.z()),
                            number(p.x()), number(p.y()), number(p.z())}
                    .join(',')
                    .toUtf8() +
                '\n';
    }
    return text;
}

QByteArray strokeCsv(const model::DirectionStroke& stroke)
{
    QByteArray text = "time,x,y,z\n";
    for (std::size_t i = 0; i < stroke.points.size(); ++i)
        text += QStringList{number(stroke.times[i]), number(stroke.points[i].x()), number(stroke.points[i].y()),
                            number(stroke.points[i].z())}
                    .join(',')
                    .toUtf8() +
                '\n';
    return text;
}

QByteArray magnitudeCsv(const std::vector<model::MagnitudePoint>& curve)
{
    QByteArray text = "time,magnitude\n";
    for (const model::MagnitudePoint& point : curve)
        text += (number(point.time) + ',' + number(point.magnitude)).toUtf8() + '\n';
    return text;
}

// The indices of the keys that are not constrained, as --free takes them.
QString freeList(const model::MotionTrack& track)
{
    QStringList free;
    for (std::size_t i = 0; i < track.keys.size(); ++i)
        if (!track.keys[i].constrained)
            free.append(QString::number(i));
    return free.join(',');
}

} // namespace

class TstCliSketchFit : public CliTestCase {
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY(dir_.isValid()); }
    void projectFitIsTheAppsFit();
    void sketchFilesFitAsTheProject();
    void projectRefusals();
};

void TstCliSketchFit::projectFitIsTheAppsFit()
{
    model::MotionTrack track = tumblingTrack();
    track.sketch = bentSketch();
    model::writeProject(path("top.gyre"), sceneOf(track));
    QVERIFY(succeeds({"fit", path("top.gyre"), "--object", "top", "--fps", "30", "-o", path("project-fit.csv")},
                     Warnings::Refused));
    const Csv frames = readCsv(path("project-fit.csv"));
    const std::vector<model::TimedPose> app = appFit(track);
    const double difference = largestDifference(frames, app);
    QVERIFY2(difference <= kSame, qPrintable(QString::number(difference)));
    // Not the keyed motion: the fit bent it.
    const double bent = largestDifference(frames, model::bakeTrack(tumblingTrack(), {0.0, 4.0, kFps}));
    QVERIFY2(bent > 0.05, qPrintable(QString::number(bent)));
}

void TstCliSketchFit::sketchFilesFitAsTheProject()
{
    model::MotionTrack track = tumblingTrack();
    track.sketch = bentSketch();
    writeFile("keys.csv", keysCsv(track));
    writeFile("stroke.csv", strokeCsv(track.sketch.directionStrokes.front()));
    writeFile("speed.csv", magnitudeCsv(track.sketch.magnitude));
    QVERIFY(succeeds({"fit", path("keys.csv"), "--direction", path("stroke.csv"), "--magnitude", path("speed.csv"),
                      "--free", freeList(track), "--fps", "30", "-o", path("files-fit.csv")},
                     Warnings::Refused));
    const double difference = largestDifference(readCsv(path("files-fit.csv")), appFit(track));
    QVERIFY2(difference <= kSame, qPrintable(QString::number(difference)));

    // The direction alone: where no speed is drawn the motion keeps its own, as in the app.
    model::MotionTrack directionOnly = track;
    directionOnly.sketch.magnitude.clear();
    QVERIFY(succeeds({"fit", path("keys.csv"), "--direction", path("stroke.csv"), "--free", freeList(track), "--fps",
                      "30", "-o", path("direction-fit.csv")},
                     Warnings::Refused));
    const double directionDifference = largestDifference(readCsv(path("direction-fit.csv")), appFit(directionOnly));
    QVERIFY2(directionDifference <= kSame, qPrintable(QString::number(directionDifference)));
}

// A project's object without a sketch is refused as the app's Fit panel refuses it; the project holds
// the sketch's settings, so options that describe a sketch are refused with it.
void TstCliSketchFit::projectRefusals()
{
    model::writeProject(path("unsketched.gyre"), sceneOf(tumblingTrack()));
    const CliRun unsketched =
        runCli({"fit", path("unsketched.gyre"), "--object", "top", "--fps", "30", "-o", path("refused.csv")});
    QCOMPARE(unsketched.exitCode, 1);
    QVERIFY2(unsketched.err.contains("cannot fit 'top': Nothing is sketched yet"), qPrintable(unsketched.err));
    const CliRun withDelta = runCli(
        {"fit", path("unsketched.gyre"), "--object", "top", "--fps", "30", "--delta", "0.2", "-o", path("refused.csv")});
    QCOMPARE(withDelta.exitCode, 2);
    QVERIFY2(withDelta.err.contains("--delta goes with a keys file"), qPrintable(withDelta.err));
    QVERIFY(!QFile::exists(path("refused.csv")));
}

QTEST_GUILESS_MAIN(TstCliSketchFit)
#include "tst_cli_sketch_fit.moc"
