#pragma once
// Work for a view, off the UI thread, of which only the newest request's result is shown: a result
// that answers an older request is dropped on arrival, as a newer one is on its way. The work runs on
// a JobThread of its own (newest request wins), and its result comes back through a queued call on
// the receiver, which is dropped if the receiver is gone.

#include "jobs/job_thread.h"

#include <QMetaObject>
#include <QObject>

#include <cstdint>
#include <functional>
#include <utility>

namespace gyre::app {

class LatestResultJob {
public:
    // `receiver` owns this job (it is a member), so the job outlives every call queued on it.
    explicit LatestResultJob(QObject& receiver)
        : receiver_(receiver)
    {
    }

    // Runs `work` (which must hold copies of what it reads) on the thread, then `show` with its
    // result on the receiver's thread, unless a newer request was made in the meantime.
    template <class Result>
    void post(std::function<Result()> work, std::function<void(Result)> show)
    {
        const std::uint64_t request = ++latestRequest_;
        thread_.post([this, request, work = std::move(work), show = std::move(show)](const std::atomic<bool>&) {
            QMetaObject::invokeMethod(
                &receiver_,
                [this, request, show, result = work()]() mutable {
                    if (request == latestRequest_)
                        show(std::move(result));
                },
                Qt::QueuedConnection);
        });
    }

    // Drops the results of every request made so far.
    void cancel() { ++latestRequest_; }

private:
    QObject& receiver_;
    std::uint64_t latestRequest_ = 0; // read and written on the UI thread only
    jobs::JobThread thread_;          // last: joined before the members its work uses are destroyed
};

} // namespace gyre::app
