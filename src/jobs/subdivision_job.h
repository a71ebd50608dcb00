#pragma once
// ScrewBender's subdivision off the UI thread, for the stroboscopic trail that follows a dragged
// control pose. Every request gets a generation, increasing; a burst of requests while the worker is
// busy costs one run (a newest-wins Job), and only the result of the newest request is emitted, so a
// result never arrives after a newer one and the UI never waits. The generation names the request an
// answer belongs to; the trail needs no more than "the newest", which tst_subdivision_job checks by it. The job keeps one PolyscrewSubdivider,
// whose buffers grow once and are reused by every later request (one request runs at a time).

#include "core/pose.h"
#include "core/subdivision.h"
#include "jobs/job.h"

#include <QObject>
#include <QString>

#include <cstdint>
#include <vector>

namespace gyre::jobs {

class SubdivisionJob : public QObject {
    Q_OBJECT

public:
    explicit SubdivisionJob(QObject* parent = nullptr);
    ~SubdivisionJob() override;

    // Asks for `controlPoses` subdivided with `settings`; returns the request's generation.
    std::uint64_t request(std::vector<Pose> controlPoses, const SubdivisionSettings& settings);
    // Drops the results of every request made so far: nothing more is emitted until the next request.
    void cancel();

signals:
    // The newest request's poses, and how long the worker took to subdivide them.
    void subdivided(std::uint64_t generation, const std::vector<gyre::Pose>& poses, qint64 nanoseconds);
    // The newest request could not be subdivided (PolyscrewSubdivider's std::invalid_argument, or
    // whatever else the subdivision threw).
    void failed(std::uint64_t generation, const QString& reason);

private:
    struct Subdivided {
        std::vector<Pose> poses;
        qint64 nanoseconds = 0;
    };

    PolyscrewSubdivider subdivider_; // used by the job's work only
    Job<Subdivided> job_;            // last: waits for the work before the subdivider goes
};

} // namespace gyre::jobs
