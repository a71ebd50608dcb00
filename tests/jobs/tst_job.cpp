// The one job type (jobs/job.h): newest request wins, the queue's order, cancel, progress, exceptions
// turned into errors, destruction while work runs, and the pool's limit of one thread per job.

#include "jobs/job.h"

#include <QCoreApplication>
#include <QSemaphore>
#include <QTest>
#include <QThread>

#include <atomic>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <vector>

using namespace gyre;
using jobs::Job;
using jobs::JobPolicy;
using jobs::JobRun;
using jobs::NoProgress;

namespace {

constexpr int kWaitMilliseconds = 20000;

// What a job delivered, in order, on the UI thread.
struct Answers {
    std::vector<int> finished;
    std::vector<QString> failures;
    int cancellations = 0;
    std::vector<int> progress;

    Job<int, int>::Handlers handlers()
    {
        return {.finished = [this](int value) { finished.push_back(value); },
                .failed = [this](const QString& message) { failures.push_back(message); },
                .cancelled = [this] { ++cancellations; },
                .progressed = [this](const int& value) { progress.push_back(value); }};
    }
    std::size_t count() const { return finished.size() + failures.size() + std::size_t(cancellations); }
};

// Numbers appended by works on the pool.
class RunLog {
public:
    void add(int value)
    {
        const std::lock_guard lock(mutex_);
        values_.push_back(value);
    }
    std::vector<int> values()
    {
        const std::lock_guard lock(mutex_);
        return values_;
    }

private:
    std::mutex mutex_;
    std::vector<int> values_;
};

} // namespace

class TestJob : public QObject {
    Q_OBJECT

private slots:
    // A burst of requests while one runs costs one run more, the last; the running one sees it is
    // superseded; only the last request's result arrives.
    void aBurstWhileOneRunsCostsOneMoreRunAndOnlyTheNewestIsAnswered()
    {
        Answers answers;
        RunLog runs;
        QSemaphore started;
        QSemaphore release;
        std::atomic<bool> firstSawSuperseded = false;
        Job<int, int> job(JobPolicy::NewestWins, answers.handlers());
        job.post([&](const JobRun<int>& run) {
            runs.add(0);
            started.release();
            (void)release.tryAcquire(1, kWaitMilliseconds);
            firstSawSuperseded = run.stopRequested();
            return 0;
        });
        QVERIFY(started.tryAcquire(1, kWaitMilliseconds));
        constexpr int kBurst = 50;
        for (int request = 1; request <= kBurst; ++request)
            job.post([&runs, request](const JobRun<int>&) {
                runs.add(request);
                return request;
            });
        QCOMPARE(job.newestRequest(), std::uint64_t{kBurst + 1});
        release.release();
        QTRY_VERIFY(job.isIdle());
        QCOMPARE(runs.values(), (std::vector<int>{0, kBurst}));
        QVERIFY(firstSawSuperseded);
        QCOMPARE(answers.finished, std::vector<int>{kBurst});
        QCOMPARE(answers.count(), std::size_t{1});
    }

    // A result that arrives after a newer request was made is dropped, though the newer one has not
    // run yet.
    void aResultOvertakenByANewerRequestIsDropped()
    {
        Answers answers;
        QSemaphore done;
        Job<int, int> job(JobPolicy::NewestWins, answers.handlers());
        job.post([&](const JobRun<int>&) {
            done.release();
            return 1;
        });
        // The first work has run, its result on its way or about to be, when the second request is made.
        QVERIFY(done.tryAcquire(1, kWaitMilliseconds));
        job.post([](const JobRun<int>&) { return 2; });
        QTRY_VERIFY(job.isIdle());
        QCOMPARE(answers.finished, std::vector<int>{2});
    }

    void aQueueRunsAndAnswersEveryRequestInOrder()
    {
        Answers answers;
        RunLog runs;
        Job<int, int> job(JobPolicy::Queue, answers.handlers());
        constexpr int kRequests = 40;
        std::vector<int> expected;
        for (int request = 0; request < kRequests; ++request) {
            job.post([&runs, request](const JobRun<int>& run) {
                runs.add(request);
                if (run.stopRequested())
                    throw std::logic_error("a queued request was told to stop");
                return request;
            });
            expected.push_back(request);
        }
        QVERIFY(!job.isIdle());
        QTRY_VERIFY(job.isIdle());
        QCOMPARE(runs.values(), expected);
        QCOMPARE(answers.finished, expected);
        QVERIFY(answers.failures.empty());
    }

    // The running work sees the cancel and stops; the request waiting behind it runs told to stop from
    // its start; both are answered by cancelled, not finished; a request made afterwards runs as usual.
    void cancelStopsTheRunningWorkAndAnswersCancelled()
    {
        Answers answers;
        RunLog runs;
        QSemaphore started;
        Job<int, int> job(JobPolicy::Queue, answers.handlers());
        job.post([&](const JobRun<int>& run) {
            runs.add(1);
            started.release();
            while (!run.stopRequested())
                QThread::yieldCurrentThread();
            return 1;
        });
        job.post([&](const JobRun<int>& run) {
            runs.add(run.stopRequested() ? 2 : -2);
            return 2;
        });
        QVERIFY(started.tryAcquire(1, kWaitMilliseconds));
        job.cancel();
        QTRY_VERIFY(job.isIdle());
        QCOMPARE(answers.cancellations, 2);
        QVERIFY(answers.finished.empty());
        QCOMPARE(runs.values(), (std::vector<int>{1, 2}));

        job.post([](const JobRun<int>&) { return 3; });
        QTRY_COMPARE(answers.finished, std::vector<int>{3});
        QCOMPARE(answers.cancellations, 2);
    }

    // A work that ends through throwIfStopped after a cancel is answered by cancelled, not failed.
    void aWorkStoppedEarlyIsAnsweredByCancelled()
    {
        Answers answers;
        QSemaphore started;
        Job<int, int> job(JobPolicy::NewestWins, answers.handlers());
        job.post([&](const JobRun<int>& run) {
            started.release();
            while (!run.stopRequested())
                QThread::yieldCurrentThread();
            run.throwIfStopped();
            return 1;
        });
        QVERIFY(started.tryAcquire(1, kWaitMilliseconds));
        job.cancel();
        QTRY_VERIFY(job.isIdle());
        QCOMPARE(answers.cancellations, 1);
        QCOMPARE(answers.count(), std::size_t{1});
    }

    void cancelWithNothingToAnswerDoesNothing()
    {
        Answers answers;
        Job<int, int> job(JobPolicy::NewestWins, answers.handlers());
        job.post([](const JobRun<int>&) { return 1; });
        QTRY_VERIFY(job.isIdle());
        job.cancel();
        QCoreApplication::processEvents();
        QCOMPARE(answers.finished, std::vector<int>{1});
        QCOMPARE(answers.cancellations, 0);
    }

    // Progress arrives in order on the UI thread, before the result; none arrives once cancelled.
    void progressArrivesInOrderBeforeTheResultAndStopsAtACancel()
    {
        Answers answers;
        Job<int, int> job(JobPolicy::Queue, answers.handlers());
        job.post([](const JobRun<int>& run) {
            for (int step = 1; step <= 5; ++step)
                run.progress(step);
            return 5;
        });
        QTRY_VERIFY(job.isIdle());
        QCOMPARE(answers.progress, (std::vector<int>{1, 2, 3, 4, 5}));
        QCOMPARE(answers.finished, std::vector<int>{5});

        answers.progress.clear();
        QSemaphore reported;
        QSemaphore cancelled;
        job.post([&](const JobRun<int>& run) {
            run.progress(1);
            reported.release();
            (void)cancelled.tryAcquire(1, kWaitMilliseconds);
            run.progress(2);
            return 2;
        });
        QVERIFY(reported.tryAcquire(1, kWaitMilliseconds));
        QTRY_COMPARE(answers.progress, std::vector<int>{1});
        job.cancel();
        cancelled.release();
        QTRY_VERIFY(job.isIdle());
        QCOMPARE(answers.progress, std::vector<int>{1});
        QCOMPARE(answers.cancellations, 1);
    }

    // A std::exception's what(), and a throw of anything else, reach failed on the UI thread; the job
    // runs its next request as usual.
    void anExceptionOfAnyTypeIsDeliveredAsFailed()
    {
        Answers answers;
        Job<int, int> job(JobPolicy::Queue, answers.handlers());
        job.post([](const JobRun<int>&) -> int { throw std::runtime_error("the solver gave up"); });
        job.post([](const JobRun<int>&) -> int { throw 42; });
        job.post([](const JobRun<int>&) -> int { throw std::bad_alloc(); });
        job.post([](const JobRun<int>&) { return 7; });
        QTRY_VERIFY(job.isIdle());
        QCOMPARE(answers.failures, (std::vector<QString>{QStringLiteral("the solver gave up"), QStringLiteral("an unknown error"),
                                                         QStringLiteral("not enough memory")}));
        QCOMPARE(answers.finished, std::vector<int>{7});
    }

    void aJobWithoutItsFailedHandlerIsRefused()
    {
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 Job<int>(JobPolicy::Queue, {.finished = [](int) {}, .failed = nullptr}));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 Job<int>(JobPolicy::Queue, {.finished = nullptr, .failed = [](const QString&) {}}));
    }

    // Destroying a job while its work runs tells the work to stop, waits for it, drops the request
    // waiting, and delivers nothing afterwards, though the handlers' receiver is gone (ASan checks).
    void destroyingAJobWhileItsWorkRunsIsSafe()
    {
        auto answers = std::make_unique<Answers>();
        auto job = std::make_unique<Job<int, int>>(JobPolicy::Queue, answers->handlers());
        RunLog runs;
        QSemaphore started;
        std::atomic<bool> sawStop = false;
        job->post([&](const JobRun<int>& run) {
            runs.add(1);
            run.progress(1);
            started.release();
            while (!run.stopRequested())
                QThread::yieldCurrentThread();
            sawStop = true;
            return 1;
        });
        job->post([&](const JobRun<int>&) {
            runs.add(2);
            return 2;
        });
        QVERIFY(started.tryAcquire(1, kWaitMilliseconds));
        job.reset();
        QVERIFY(sawStop);
        answers.reset();
        QCoreApplication::processEvents();
        QCOMPARE(runs.values(), std::vector<int>{1});
    }

    // A result and progress already on their way to the UI thread are dropped with their job.
    void aResultOnItsWayIsDroppedWithItsJob()
    {
        Answers answers;
        auto job = std::make_unique<Job<int, int>>(JobPolicy::NewestWins, answers.handlers());
        QSemaphore reported;
        job->post([&](const JobRun<int>& run) {
            run.progress(1);
            reported.release();
            return 1;
        });
        QVERIFY(reported.tryAcquire(1, kWaitMilliseconds));
        job.reset(); // waits for the work: its result is queued by now
        QCoreApplication::processEvents();
        QCOMPARE(answers.count(), std::size_t{0});
        QVERIFY(answers.progress.empty());
    }

    // A long work on one job does not hold up another's: each job has a thread of the pool, however many
    // jobs there are (more than the machine's cores here).
    void aLongWorkDoesNotStarveAnotherJob()
    {
        constexpr int kJobs = 12;
        std::vector<std::unique_ptr<Answers>> answers;
        std::vector<std::unique_ptr<Job<int, int>>> jobs;
        QSemaphore allRunning;
        QSemaphore release;
        for (int index = 0; index < kJobs; ++index) {
            answers.push_back(std::make_unique<Answers>());
            jobs.push_back(std::make_unique<Job<int, int>>(JobPolicy::Queue, answers.back()->handlers()));
            jobs.back()->post([&, index](const JobRun<int>&) {
                allRunning.release();
                (void)release.tryAcquire(1, kWaitMilliseconds);
                return index;
            });
        }
        // Every work is running at once, each waiting for the others.
        QVERIFY(allRunning.tryAcquire(kJobs, kWaitMilliseconds));
        release.release(kJobs);
        for (int index = 0; index < kJobs; ++index)
            QTRY_COMPARE(answers[std::size_t(index)]->finished, std::vector<int>{index});
    }
};

QTEST_MAIN(TestJob)
#include "tst_job.moc"
