// The fit job on a steady spin about z whose sketch tilts the spin towards x: its result is the fit
// run directly, a cancel or a newer request stops it, and a sketch that cannot be fitted fails with
// the bridge's message.

#include "fit/angular_velocity_fit.h"
#include "model/fit_input.h"
#include "jobs/fit_job.h"
#include "model/sketch_fit_problem.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <numbers>
#include <vector>

using namespace gyre;

namespace {

constexpr double kSpinRate = std::numbers::pi / 2; // rad/s about z

// Keys every second from 0 to `seconds` of a steady spin about z; a stroke from z tilting 60° towards
// x over 1–3 s, a magnitude of kSpinRate over the same span, and that span as the window.
model::MotionTrack tiltedSpin(int seconds = 4)
{
    model::MotionTrack track;
    track.interpolation = InterpolationMethod::Hermite;
    for (int second = 0; second <= seconds; ++second) {
        model::Keyframe key;
        key.time = second;
        key.pose.orientation = Eigen::AngleAxisd(kSpinRate * second, Eigen::Vector3d::UnitZ());
        track.keys.push_back(key);
    }
    model::DirectionStroke stroke;
    constexpr int kPoints = 9;
    for (int i = 0; i < kPoints; ++i) {
        const double tilt = (std::numbers::pi / 3) * i / (kPoints - 1);
        stroke.points.emplace_back(std::sin(tilt), 0.0, std::cos(tilt));
        stroke.times.push_back(1.0 + 2.0 * i / (kPoints - 1));
    }
    track.sketch.directionStrokes.push_back(stroke);
    track.sketch.magnitude = {{1.0, kSpinRate}, {3.0, kSpinRate}};
    track.sketch.window = std::pair(1.0, 3.0);
    return track;
}

// A fit that takes long, seconds even in a Release build: a minute of keys, the whole of it refitted
// against a speed the keys cannot follow, and every fragment error above δ, so that it inserts
// variable frames round after round.
model::MotionTrack slowToFit()
{
    constexpr int kSeconds = 60;
    model::MotionTrack track = tiltedSpin(kSeconds);
    track.sketch.delta = 1e-12;
    track.sketch.window = std::pair(0.0, double{kSeconds});
    track.sketch.magnitude = {{0.0, 3 * kSpinRate}, {double{kSeconds}, kSpinRate}};
    return track;
}

bool sameQuaternion(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    return a.coeffs() == b.coeffs();
}

bool sameResult(const model::FitResult& a, const model::FitResult& b)
{
    if (a.curve.size() != b.curve.size() || a.keys.size() != b.keys.size())
        return false;
    for (std::size_t i = 0; i < a.curve.size(); ++i)
        if (a.curve[i].time != b.curve[i].time || !sameQuaternion(a.curve[i].value, b.curve[i].value)
            || !sameQuaternion(a.curve[i].derivative, b.curve[i].derivative))
            return false;
    for (std::size_t i = 0; i < a.keys.size(); ++i)
        if (a.keys[i].time != b.keys[i].time || !sameQuaternion(a.keys[i].pose.orientation, b.keys[i].pose.orientation)
            || a.keys[i].pose.position != b.keys[i].pose.position || a.keys[i].constrained != b.keys[i].constrained)
            return false;
    return true;
}

// What the job emitted, in order.
struct Answers {
    std::vector<model::MotionTrack> finishedInputs;
    std::vector<model::FitResult> results;
    std::vector<jobs::FitSummary> summaries;
    std::vector<QString> failures;
    std::vector<model::ObjectId> cancellations;
    std::vector<jobs::FitJobProgress> progress;

    explicit Answers(jobs::FitJob& job)
    {
        QObject::connect(&job, &jobs::FitJob::finished, &job,
                         [this](model::ObjectId, const model::MotionTrack& input, const model::FitResult& result,
                                const jobs::FitSummary& summary) {
                             finishedInputs.push_back(input);
                             results.push_back(result);
                             summaries.push_back(summary);
                         });
        QObject::connect(&job, &jobs::FitJob::failed, &job,
                         [this](model::ObjectId, const QString& message) { failures.push_back(message); });
        QObject::connect(&job, &jobs::FitJob::cancelled, &job,
                         [this](model::ObjectId id) { cancellations.push_back(id); });
        QObject::connect(&job, &jobs::FitJob::progressed, &job,
                         [this](model::ObjectId, const jobs::FitJobProgress& report) { progress.push_back(report); });
    }

    std::size_t count() const { return finishedInputs.size() + failures.size() + cancellations.size(); }
};

constexpr int kFitTimeoutMilliseconds = 120'000;

} // namespace

class TestFitJob : public QObject {
    Q_OBJECT

private slots:
    void aFitFinishesWithTheResultOfTheFitRunDirectly()
    {
        jobs::FitJob job;
        Answers answers(job);
        const model::MotionTrack track = tiltedSpin();
        job.request(7, track, {});
        QVERIFY(job.isRunning());
        QTRY_VERIFY_WITH_TIMEOUT(answers.count() == 1, kFitTimeoutMilliseconds);
        QVERIFY(!job.isRunning());
        QCOMPARE(answers.results.size(), std::size_t{1});
        QVERIFY(model::sameFitInput(answers.finishedInputs.front(), track));

        const model::SketchFitProblem problem = model::sketchFitProblem(track, {});
        const fit::FitResult direct = model::fitSketch(problem);
        QVERIFY(!answers.results.front().curve.empty());
        QVERIFY(sameResult(answers.results.front(), model::appliedFitResult(track, direct)));

        const jobs::FitSummary& summary = answers.summaries.front();
        QCOMPARE(summary.outcome, QString::fromUtf8(nameOf(fit::kFitOutcomeNames, direct.outcome).data()));
        QCOMPARE(summary.rounds, direct.rounds);
        QCOMPARE(summary.iterations, direct.iterations);
        QCOMPARE(summary.largestRelativeError, direct.largestRelativeError);
        const model::DrawnErrors drawn = model::drawnErrors(track, *problem.motionWithoutFit, model::appliedFitResult(track, direct), {});
        QCOMPARE(summary.drawnErrors.before, drawn.before);
        QCOMPARE(summary.drawnErrors.after, drawn.after);
        QVERIFY(drawn.after < drawn.before);
        QVERIFY(summary.seconds > 0.0);

        // Progress came first, round by round, within the fit's round limit.
        QVERIFY(!answers.progress.empty());
        for (const jobs::FitJobProgress& report : answers.progress) {
            QCOMPARE(report.maxRounds, problem.settings.maxRounds);
            QVERIFY(report.round >= 1 && report.round <= direct.rounds);
        }
    }

    void cancelStopsTheFitAndEmitsCancelledNotFinished()
    {
        jobs::FitJob job;
        Answers answers(job);
        job.request(3, slowToFit(), {});
        QTRY_VERIFY_WITH_TIMEOUT(!answers.progress.empty(), kFitTimeoutMilliseconds);
        job.cancel();
        QTRY_VERIFY_WITH_TIMEOUT(answers.count() == 1, kFitTimeoutMilliseconds);
        QCOMPARE(answers.cancellations, std::vector<model::ObjectId>{3});
        QVERIFY(!job.isRunning());
        QTest::qWait(200);
        QCOMPARE(answers.count(), std::size_t{1});
    }

    void aNewerRequestSupersedesTheRunningFit()
    {
        jobs::FitJob job;
        Answers answers(job);
        job.request(1, slowToFit(), {});
        QTRY_VERIFY_WITH_TIMEOUT(!answers.progress.empty(), kFitTimeoutMilliseconds);
        model::MotionTrack newer = tiltedSpin();
        newer.sketch.alpha = 0.004;
        job.request(2, newer, {});
        QTRY_VERIFY_WITH_TIMEOUT(answers.count() == 1, kFitTimeoutMilliseconds);
        QTest::qWait(200);
        QCOMPARE(answers.count(), std::size_t{1});
        QCOMPARE(answers.finishedInputs.size(), std::size_t{1});
        QVERIFY(model::sameFitInput(answers.finishedInputs.front(), newer));
        QCOMPARE(answers.finishedInputs.front().sketch.alpha, 0.004);
    }

    void aTrackThatCannotBeFittedFailsWithTheMessage()
    {
        model::MotionTrack unsketched = tiltedSpin();
        unsketched.sketch = {};
        QString expected;
        try {
            model::sketchFitProblem(unsketched, {});
        } catch (const model::SketchFitError& error) {
            expected = QString::fromUtf8(error.what());
        }
        QVERIFY(!expected.isEmpty());

        jobs::FitJob job;
        Answers answers(job);
        job.request(5, unsketched, {});
        QTRY_VERIFY_WITH_TIMEOUT(answers.count() == 1, kFitTimeoutMilliseconds);
        QCOMPARE(answers.failures, std::vector<QString>{expected});
    }

    void aCancelWithNothingRunningDoesNothing()
    {
        jobs::FitJob job;
        Answers answers(job);
        job.cancel();
        QVERIFY(!job.isRunning());
        QTest::qWait(100);
        QCOMPARE(answers.count(), std::size_t{0});
    }
};

QTEST_MAIN(TestFitJob)
#include "tst_fit_job.moc"
