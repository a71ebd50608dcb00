#pragma once
// Curves of the selected object's motion for a view, sampled off the UI thread: building a track's
// motion grows with 2^levels for a screw track, far beyond what the UI thread can spare. Requests are
// coalesced to one every kIntervalMilliseconds, and a view off screen samples nothing until it is
// shown again (ViewRefresh). Only the newest request's curves are shown (LatestResultJob).

#include "app/latest_result_job.h"
#include "app/selection.h"
#include "app/view_refresh.h"
#include "model/document.h"

#include <QWidget>

#include <functional>
#include <memory>
#include <stdexcept>
#include <utility>

namespace gyre::app {

template <class Curves>
class SelectedTrackSampler {
public:
    static constexpr int kIntervalMilliseconds = 50;

    // Called on the UI thread with the selected track's shared motion (Document::motion) and the
    // scene; returns the sampling to run on the job thread, holding copies of what it reads. The
    // sampling may throw std::invalid_argument for a track too large to evaluate
    // (track_evaluation.h): the view then shows no curves.
    using Motion = std::shared_ptr<const model::SharedTrackMotion>;
    using MakeSampling = std::function<std::function<Curves()>(const Motion&, const model::Scene&)>;
    using Show = std::function<void(const Curves&)>;

    // `view` owns the sampler (it is a member), so the sampler outlives every call queued on it.
    SelectedTrackSampler(QWidget& view, const Selection& selection, const model::Document& document,
                         MakeSampling makeSampling, Show show)
        : selection_(selection)
        , document_(document)
        , makeSampling_(std::move(makeSampling))
        , show_(std::move(show))
        , refresh_(view, kIntervalMilliseconds, [this] { sampleNow(); })
        , job_(view)
    {
    }

    // Samples the selected object's track within kIntervalMilliseconds if the view is on screen,
    // else once it is shown again.
    void schedule() { refresh_.request(); }

private:
    void sampleNow()
    {
        const Motion motion = document_.motion(selection_.object());
        if (!motion) {
            job_.cancel();
            show_(Curves{});
            return;
        }
        job_.post<Curves>(
            [sampling = makeSampling_(motion, document_.scene())] {
                try {
                    return sampling();
                } catch (const std::invalid_argument&) {
                    return Curves{};
                }
            },
            show_);
    }

    const Selection& selection_;
    const model::Document& document_;
    MakeSampling makeSampling_;
    Show show_;
    ViewRefresh refresh_;
    LatestResultJob job_; // last: joined before the members its work uses are destroyed
};

} // namespace gyre::app
