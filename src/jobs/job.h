#pragma once
// Every piece of work Gyre does off the UI thread (the trail's subdivision, the fit, the views' sampled
// curves, the viewport's motion, autosave, scene import and export) runs as a Job: the caller posts
// requests from the UI thread, each a function that reads only copies of what it needs (or what the
// job's owner keeps for the worker alone), and receives its answer on the UI thread.
//
// Policies:
// - NewestWins: a request made while one runs replaces the request still waiting, if any, so a burst of
//   requests (a pose being dragged) costs one run more, and the last request made is always run. The
//   running work sees through JobRun::stopRequested that it has been superseded and may stop early; only
//   the newest request is answered.
// - Queue: every request runs, one at a time, in the order made, and every request is answered.
// A cancelled request still runs (the newest one, newest wins), with stopRequested already true, so its
// work decides how to end: it may return at once, or stop what it started (an import's worker).
//
// Each answered request gets exactly one of: `finished` with the work's result; `failed` with the
// message of whatever the work threw (a std::exception's what(), or that it is unknown: no exception is
// ever dropped, and no throw ends the process); `cancelled` if cancel() was called before its answer
// arrived, whatever the work returned. `progressed` carries what the work reports through
// JobRun::progress while its request is still to be answered and not cancelled. All of them are called
// on the thread that made the job, through queued calls, never inside post().
//
// Destroying a job asks the running work to stop (stopRequested), drops the requests still waiting and
// waits for the running work to return; nothing is delivered after that. Declare a job after everything
// its work and its handlers use, so that it is destroyed first.
//
// Threads: every job runs on one pool owned by this layer. Its limit is the number of jobs alive (at
// least one): a job runs one request at a time, so each job always has a thread when it needs one, and a
// long fit cannot starve the trail's subdivision or an autosave, while an idle Gyre holds no job threads
// (a pool thread ends after 30 s without work).

#include <QObject>
#include <QString>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <utility>

namespace gyre::jobs {

enum class JobPolicy { NewestWins, Queue };

// The progress type of a job whose work reports none.
struct NoProgress {};

namespace detail {

// One request, shared by the job on the UI thread and its run on the pool.
struct JobRequest {
    std::uint64_t number = 0;
    std::atomic<bool> stop = false;      // cancelled, superseded, or the job is being destroyed
    std::atomic<bool> cancelled = false; // cancel() was called before the request was answered
    std::function<void(const std::shared_ptr<JobRequest>&)> run; // the work, and the posting of its result
};

// Thrown by JobRun::throwIfStopped: the work ended early, and its request is answered by cancelled or not
// at all, as it would be whatever the work returned.
struct JobStopped {};

// What a job does whatever its result and progress types (job.cpp).
class JobCore {
public:
    JobCore(JobPolicy policy, std::function<void(const QString&)> failed, std::function<void()> cancelled);
    ~JobCore();
    JobCore(const JobCore&) = delete;
    JobCore& operator=(const JobCore&) = delete;

    std::uint64_t post(std::function<void(const std::shared_ptr<JobRequest>&)> run);
    void cancel();
    bool isIdle() const { return unanswered_.empty(); }
    std::uint64_t newestRequest() const { return newest_; }

    // From the pool: calls `deliver` on the UI thread if `request` is then to be answered (answering it),
    // or `cancelled` in its place if it was cancelled.
    void postAnswer(const std::shared_ptr<JobRequest>& request, std::function<void()> deliver);
    // From the pool: calls `deliver` on the UI thread if `request` is then still to be answered and not
    // cancelled, without answering it.
    void postProgress(const std::shared_ptr<JobRequest>& request, std::function<void()> deliver);

private:
    void drain();
    void answer(const JobRequest& request, const std::function<void()>& deliver);
    bool isUnanswered(const JobRequest& request) const;

    const JobPolicy policy_;
    std::function<void(const QString&)> failed_;
    std::function<void()> cancelled_;

    // On the UI thread only.
    std::uint64_t newest_ = 0;
    std::deque<std::shared_ptr<JobRequest>> unanswered_; // in the order made

    // Shared with the pool, under mutex_.
    std::mutex mutex_;
    std::condition_variable drained_;
    std::deque<std::shared_ptr<JobRequest>> waiting_;
    std::shared_ptr<JobRequest> running_;
    bool draining_ = false; // a drain() is in the pool, started or not
    bool stopping_ = false;

    QObject uiContext_; // last: gone first, taking the calls still queued on it
};

} // namespace detail

// A request's run, as its work sees it on the pool.
template <class Progress>
class JobRun {
public:
    JobRun(detail::JobRequest& request, std::function<void(Progress)> report)
        : request_(request)
        , report_(std::move(report))
    {
    }

    // Whether the work may stop early: its request was cancelled or superseded, or its job is going.
    // What it returns from then on is never delivered.
    bool stopRequested() const { return request_.stop; }
    // The same flag, for code that polls one (importSceneInWorker).
    const std::atomic<bool>& stopFlag() const { return request_.stop; }
    // Ends the work when stopRequested(), with no result to make.
    void throwIfStopped() const
    {
        if (request_.stop)
            throw detail::JobStopped{};
    }
    // Sends `progress` to the job's `progressed` on the UI thread.
    void progress(Progress progress) const { report_(std::move(progress)); }

private:
    detail::JobRequest& request_;
    std::function<void(Progress)> report_;
};

template <class Result, class Progress = NoProgress>
class Job {
public:
    using Work = std::function<Result(const JobRun<Progress>&)>;
    struct Handlers {
        std::function<void(Result)> finished; // required
        std::function<void(const QString& message)> failed; // required: the caller shows the message
        std::function<void()> cancelled = {};
        std::function<void(const Progress&)> progressed = {};
    };

    Job(JobPolicy policy, Handlers handlers)
        : finished_(required(std::move(handlers.finished)))
        , progressed_(std::move(handlers.progressed))
        , core_(policy, required(std::move(handlers.failed)), std::move(handlers.cancelled))
    {
    }

    // Runs `work` on the pool as the policy says; returns the request's number, increasing from 1.
    std::uint64_t post(Work work)
    {
        return core_.post([this, work = std::move(work)](const std::shared_ptr<detail::JobRequest>& request) {
            const JobRun<Progress> run(*request, [this, request](Progress progress) {
                core_.postProgress(request, [this, progress = std::move(progress)] {
                    if (progressed_)
                        progressed_(progress);
                });
            });
            // Shared, so that a large result is moved, never copied, on its way to the UI thread.
            auto result = std::make_shared<Result>(work(run));
            core_.postAnswer(request, [this, result] { finished_(std::move(*result)); });
        });
    }

    // Cancels every request not answered yet: each is answered by cancelled, and its work, running or
    // still to run, sees stopRequested (an import's worker is stopped, a fit ends at its next iteration).
    void cancel() { core_.cancel(); }
    // Whether every request has been answered (or, newest wins, superseded).
    bool isIdle() const { return core_.isIdle(); }
    // The number of the newest request, the one newest wins answers.
    std::uint64_t newestRequest() const { return core_.newestRequest(); }

private:
    template <class Handler>
    static Handler required(Handler handler)
    {
        if (!handler)
            throw std::invalid_argument("a job needs its finished and failed handlers");
        return handler;
    }

    std::function<void(Result)> finished_;
    std::function<void(const Progress&)> progressed_;
    detail::JobCore core_; // last: waits for the running work before the handlers go
};

} // namespace gyre::jobs
