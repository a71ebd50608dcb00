#pragma once
// ScrewBender's subdivision off the UI thread, for the stroboscopic trails of the selected screw tracks, which
// follow a dragged control pose. A request holds every polyscrew to subdivide (one per selected screw track);
// every request gets a generation, increasing; a burst of requests while the worker is busy costs one run (a
// newest-wins Job), and only the result of the newest request is emitted, so a result never arrives after a
// newer one and the UI never waits. The generation names the request an answer belongs to; the trail needs no
// more than "the newest", which tst_subdivision_job checks by it.
//
// While one pose is dragged only its track changes: a polyscrew equal to one of the previous run's (the same
// control poses and settings) is not subdivided again, its poses are shared with that run's answer, so the
// other selected tracks add only a comparison to each run. The job keeps one PolyscrewSubdivider, whose
// buffers grow once and are reused by every later request (one request runs at a time).

#include "core/pose.h"
#include "core/subdivision.h"
#include "jobs/job.h"

#include <QObject>
#include <QString>

#include <cstdint>
#include <memory>
#include <vector>

namespace gyre::jobs {

class SubdivisionJob : public QObject {
    Q_OBJECT

public:
    struct Polyscrew {
        std::vector<Pose> controlPoses;
        SubdivisionSettings settings;
    };
    // One polyscrew's subdivided poses, shared by the answers that have it unchanged.
    using SubdividedPoses = std::shared_ptr<const std::vector<Pose>>;

    explicit SubdivisionJob(QObject* parent = nullptr);
    ~SubdivisionJob() override;

    // Asks for each of `polyscrews` subdivided with its settings; returns the request's generation.
    std::uint64_t request(std::vector<Polyscrew> polyscrews);
    // Drops the results of every request made so far: nothing more is emitted until the next request.
    void cancel();

signals:
    // The newest request's poses, one list per polyscrew in the request's order, and how long the worker
    // took to subdivide them.
    void subdivided(std::uint64_t generation, const std::vector<gyre::jobs::SubdivisionJob::SubdividedPoses>& poses,
                    qint64 nanoseconds);
    // The newest request could not be subdivided (PolyscrewSubdivider's std::invalid_argument, a polyscrew past
    // the pose budget, or whatever else the subdivision threw).
    void failed(std::uint64_t generation, const QString& reason);

private:
    struct Subdivided {
        std::vector<SubdividedPoses> poses;
        qint64 nanoseconds = 0;
    };
    struct Kept {
        Polyscrew polyscrew;
        SubdividedPoses poses;
    };

    // Used by the job's work only.
    PolyscrewSubdivider subdivider_;
    std::vector<Kept> previousRun_; // the polyscrews of the last run and their poses
    Job<Subdivided> job_;           // last: waits for the work before the subdivider goes
};

} // namespace gyre::jobs
