// The subdivision job under a burst of requests, as while a pose is dragged: the newest request's
// result arrives, equal to a direct subdivision, and no older result arrives after it. A request of several
// polyscrews (the selected screw tracks) answers each with its own subdivision, and one unchanged since the
// previous run is not subdivided again: its poses are the previous answer's.

#include "jobs/subdivision_job.h"

#include <QEvent>
#include <QSignalSpy>
#include <QTest>

#include <cstdint>
#include <numbers>
#include <vector>

using namespace gyre;

namespace {

// The L-shaped cycle of the ScrewBender paper, its second pose moved `offset` along x: each request
// of a burst gives a different motion.
std::vector<Pose> lCycle(double offset)
{
    const auto turn = [](double degrees, const Eigen::Vector3d& axis) {
        return Eigen::Quaterniond(Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0, axis));
    };
    return {
        {Eigen::Quaterniond::Identity(), Eigen::Vector3d(0, 0, 0)},
        {Eigen::Quaterniond::Identity(), Eigen::Vector3d(4 + offset, 0, 0)},
        {turn(90, Eigen::Vector3d::UnitZ()), Eigen::Vector3d(4, 2, 0)},
        {turn(45, Eigen::Vector3d::UnitX()), Eigen::Vector3d(2, 2, 0)},
        {turn(120, Eigen::Vector3d::UnitZ()), Eigen::Vector3d(2, 6, 0)},
        {turn(30, Eigen::Vector3d::UnitY()), Eigen::Vector3d(0, 6, 0)},
    };
}

bool samePoses(const std::vector<Pose>& a, const std::vector<Pose>& b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!a[i].orientation.coeffs().isApprox(b[i].orientation.coeffs(), 1e-12)
            || !a[i].position.isApprox(b[i].position, 1e-12))
            return false;
    }
    return true;
}

std::vector<jobs::SubdivisionJob::Polyscrew> one(std::vector<Pose> controlPoses, const SubdivisionSettings& settings)
{
    return {{std::move(controlPoses), settings}};
}

using Answer = std::vector<jobs::SubdivisionJob::SubdividedPoses>;

// Counts the answers that reach a job on this thread, emitted or dropped: job.h delivers each through a queued
// call to a plain QObject of the job's, a MetaCall event, which an event filter on the application sees as it
// sees every event of the main thread. Meant for a test that makes no other queued calls while it counts.
class JobDeliveries : public QObject {
public:
    JobDeliveries() { QCoreApplication::instance()->installEventFilter(this); }
    int count() const { return count_; }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() == QEvent::MetaCall && watched->metaObject() == &QObject::staticMetaObject)
            ++count_;
        return false;
    }

private:
    int count_ = 0;
};

} // namespace

class TestSubdivisionJob : public QObject {
    Q_OBJECT

private slots:
    void aBurstEndsWithTheNewestResultAndNothingOlderAfterIt()
    {
        jobs::SubdivisionJob job;
        std::vector<std::uint64_t> arrived;
        std::vector<Pose> lastPoses;
        connect(&job, &jobs::SubdivisionJob::subdivided, this,
                [&](std::uint64_t generation, const Answer& poses, qint64 nanoseconds) {
                    QVERIFY(nanoseconds >= 0);
                    QCOMPARE(poses.size(), std::size_t{1});
                    arrived.push_back(generation);
                    lastPoses = *poses.front();
                });
        const SubdivisionSettings settings{SubdivisionScheme::Jarek, 8, true, false};
        constexpr int kRequests = 200;
        std::uint64_t newest = 0;
        for (int request = 0; request < kRequests; ++request) {
            newest = job.request(one(lCycle(0.01 * request), settings));
            // Let a result come back now and then, as the UI's event loop does between mouse moves.
            if (request % 20 == 0)
                QCoreApplication::processEvents();
        }
        QCOMPARE(newest, std::uint64_t{kRequests});
        QTRY_VERIFY(!arrived.empty() && arrived.back() == newest);
        QVERIFY(samePoses(lastPoses, subdividePolyscrew(lCycle(0.01 * (kRequests - 1)), settings)));
        QCOMPARE(lastPoses.size(), *subdividedPoseCount(6, 8, true));
        // Answers arrive in the order their requests ran, so a result still queued from an older request would
        // arrive before the answer to one more request: that answer must come right after the newest.
        const std::uint64_t followUp = job.request(one(lCycle(-1.0), settings));
        QTRY_VERIFY(arrived.back() == followUp);
        QCOMPARE(arrived.size() >= 2 ? arrived[arrived.size() - 2] : 0, newest);
        for (std::size_t i = 1; i < arrived.size(); ++i)
            QVERIFY(arrived[i] > arrived[i - 1]);
        QVERIFY(samePoses(lastPoses, subdividePolyscrew(lCycle(-1.0), settings)));
    }

    void cancelDropsTheResultOnItsWay()
    {
        jobs::SubdivisionJob job;
        std::vector<std::uint64_t> arrived;
        connect(&job, &jobs::SubdivisionJob::subdivided, this,
                [&](std::uint64_t generation, const Answer&, qint64) { arrived.push_back(generation); });
        JobDeliveries deliveries;
        job.request(one(lCycle(0), SubdivisionSettings{SubdivisionScheme::BSpline, 6, false, false}));
        job.cancel();
        // The cancelled request's answer, whether its work ran or stopped at its start, reaches the job and is
        // dropped there. A request made before it arrives would supersede the cancelled one (newest wins) and
        // hide a cancel that dropped nothing, so the test awaits the answer itself.
        QTRY_COMPARE(deliveries.count(), 1);
        QVERIFY(arrived.empty());
        const std::uint64_t next = job.request(one(lCycle(1), SubdivisionSettings{SubdivisionScheme::BSpline, 2, false, false}));
        QTRY_VERIFY(!arrived.empty());
        QCOMPARE(arrived, std::vector<std::uint64_t>{next});
    }

    void aSubdivisionTooLargeIsReportedAsFailed()
    {
        jobs::SubdivisionJob job;
        QSignalSpy failures(&job, &jobs::SubdivisionJob::failed);
        const std::uint64_t generation = job.request(one(lCycle(0), SubdivisionSettings{SubdivisionScheme::Jarek, -1, true, false}));
        QTRY_COMPARE(failures.count(), 1);
        QCOMPARE(failures.front().front().value<std::uint64_t>(), generation);
    }

    // 5,000 poses at 16 levels would be 327,680,000 poses (about 30 GB): the job refuses them up front
    // with the numbers, through its failed signal, where once it threw std::bad_alloc and ended the
    // process.
    void aRequestPastThePoseBudgetIsReportedAsFailed()
    {
        jobs::SubdivisionJob job;
        QSignalSpy failures(&job, &jobs::SubdivisionJob::failed);
        QSignalSpy results(&job, &jobs::SubdivisionJob::subdivided);
        std::vector<Pose> many;
        for (int k = 0; k < 5000; ++k)
            many.push_back(lCycle(0)[k % 6]);
        const std::uint64_t generation = job.request(one(many, SubdivisionSettings{SubdivisionScheme::Jarek, 16, true, false}));
        QTRY_COMPARE(failures.count(), 1);
        QCOMPARE(failures.front().front().value<std::uint64_t>(), generation);
        const QString reason = failures.front().at(1).toString();
        QVERIFY2(reason.contains("5,000 keys at 16 levels make 327,680,000 poses; the budget is 1,048,576"), qPrintable(reason));
        QCOMPARE(results.count(), 0);
    }

    void eachPolyscrewOfARequestGetsItsSubdivisionAndAnUnchangedOneIsKept()
    {
        jobs::SubdivisionJob job;
        QSignalSpy results(&job, &jobs::SubdivisionJob::subdivided);
        const SubdivisionSettings cyclic{SubdivisionScheme::Jarek, 4, true, false};
        const SubdivisionSettings open{SubdivisionScheme::BSpline, 3, false, false};
        job.request({{lCycle(0), cyclic}, {lCycle(1), open}});
        QTRY_COMPARE(results.count(), 1);
        const Answer first = results.takeFirst().at(1).value<Answer>();
        QCOMPARE(first.size(), std::size_t{2});
        QVERIFY(samePoses(*first[0], subdividePolyscrew(lCycle(0), cyclic)));
        QVERIFY(samePoses(*first[1], subdividePolyscrew(lCycle(1), open)));
        QCOMPARE(first[1]->size(), *subdividedPoseCount(6, 3, false));

        // The first one's pose moved, as while it is dragged; the second unchanged, now asked for first.
        job.request({{lCycle(1), open}, {lCycle(0.5), cyclic}});
        QTRY_COMPARE(results.count(), 1);
        const Answer second = results.takeFirst().at(1).value<Answer>();
        QCOMPARE(second.size(), std::size_t{2});
        QCOMPARE(second[0].get(), first[1].get()); // not subdivided again
        QVERIFY(samePoses(*second[1], subdividePolyscrew(lCycle(0.5), cyclic)));
        QVERIFY(!samePoses(*second[1], *first[0]));
    }
};

QTEST_MAIN(TestSubdivisionJob)
#include "tst_subdivision_job.moc"
