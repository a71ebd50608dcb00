#pragma once
// Curves of the selected object's motion for a view, sampled off the UI thread: building a track's
// motion grows with 2^levels for a screw track, far beyond what the UI thread can spare. Requests are
// coalesced to one every kIntervalMilliseconds, and a view off screen samples nothing until it is
// shown again (ViewRefresh). Only the newest request's curves are shown (a newest-wins Job).

#include "app/selection.h"
#include "app/view_refresh.h"
#include "jobs/job.h"
#include "model/document.h"

#include <QWidget>

#include <functional>
#include <memory>
#include <utility>

namespace gyre::app {

template <class Curves>
class SelectedTrackSampler {
public:
    static constexpr int kIntervalMilliseconds = 50;

    // Called on the UI thread with the selected track's shared motion (Document::motion) and the
    // scene; returns the sampling to run on the job, holding copies of what it reads. The sampling may
    // throw std::invalid_argument for a track too large to evaluate (track_evaluation.h): the view then
    // shows no curves, as it does for any other failure rather than the curves of an older track. The
    // message is not repeated here: the same shared motion fails the viewport's drawing the same way,
    // and the viewport puts it in the status bar (DrawnMotion::failed).
    using Motion = std::shared_ptr<const model::SharedTrackMotion>;
    using MakeSampling = std::function<std::function<Curves()>(const Motion&, const model::Scene&)>;
    using Show = std::function<void(const Curves&)>;

    // `view` owns the sampler (it is a member); while it is off screen nothing is sampled (ViewRefresh).
    SelectedTrackSampler(QWidget& view, const Selection& selection, const model::Document& document,
                         MakeSampling makeSampling, Show show)
        : selection_(selection)
        , document_(document)
        , makeSampling_(std::move(makeSampling))
        , show_(std::move(show))
        , refresh_(view, kIntervalMilliseconds, [this] { sampleNow(); })
        , job_(jobs::JobPolicy::NewestWins, {.finished = [this](const Curves& curves) { show_(curves); },
                                             .failed = [this](const QString&) { show_(Curves{}); }})
    {
    }

    // Samples the selected object's track within kIntervalMilliseconds if the view is on screen,
    // else once it is shown again.
    void schedule() { refresh_.request(); }
    // Whether a sampling has been posted and its curves are not yet shown.
    bool isSampling() const { return !job_.isIdle(); }

private:
    void sampleNow()
    {
        const Motion motion = document_.motion(selection_.object());
        if (!motion) {
            job_.cancel();
            show_(Curves{});
            return;
        }
        job_.post([sampling = makeSampling_(motion, document_.scene())](const jobs::JobRun<jobs::NoProgress>& run) {
            run.throwIfStopped(); // cancelled before it started
            return sampling();
        });
    }

    const Selection& selection_;
    const model::Document& document_;
    MakeSampling makeSampling_;
    Show show_;
    ViewRefresh refresh_;
    jobs::Job<Curves> job_; // last: waits for the work before the members it uses go
};

} // namespace gyre::app
