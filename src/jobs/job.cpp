#include "jobs/job.h"

#include <QMetaObject>
#include <QThreadPool>

#include <algorithm>
#include <exception>
#include <new>
#include <string>

namespace gyre::jobs::detail {

namespace {

// The pool every job runs on, and its limit: one thread per job alive (job.h).
class JobPool {
public:
    void reserveThread() { countJobs(+1); }
    void releaseThread() { countJobs(-1); }
    void start(std::function<void()> run) { pool_.start(std::move(run)); }

private:
    void countJobs(int change)
    {
        const std::lock_guard lock(mutex_);
        jobs_ += change;
        pool_.setMaxThreadCount(std::max(1, jobs_));
    }

    std::mutex mutex_;
    int jobs_ = 0;
    QThreadPool pool_;
};

JobPool& jobPool()
{
    static JobPool pool;
    return pool;
}

// What the exception being handled says, inside a catch block: its what(), or that it is unknown.
QString currentExceptionText()
{
    try {
        throw;
    } catch (const std::bad_alloc&) {
        return QStringLiteral("not enough memory");
    } catch (const std::exception& error) {
        return QString::fromUtf8(error.what());
    } catch (...) {
        return QStringLiteral("an unknown error");
    }
}

} // namespace

JobCore::JobCore(JobPolicy policy, std::function<void(const QString&)> failed, std::function<void()> cancelled)
    : policy_(policy)
    , failed_(std::move(failed))
    , cancelled_(std::move(cancelled))
{
    jobPool().reserveThread();
}

JobCore::~JobCore()
{
    std::unique_lock lock(mutex_);
    stopping_ = true;
    waiting_.clear();
    if (running_)
        running_->stop = true;
    drained_.wait(lock, [this] { return !draining_; });
    lock.unlock();
    jobPool().releaseThread();
}

std::uint64_t JobCore::post(std::function<void(const std::shared_ptr<JobRequest>&)> run)
{
    auto request = std::make_shared<JobRequest>();
    request->number = ++newest_;
    request->run = std::move(run);
    if (policy_ == JobPolicy::NewestWins)
        unanswered_.clear(); // superseded: never answered
    unanswered_.push_back(request);

    const std::lock_guard lock(mutex_);
    if (policy_ == JobPolicy::NewestWins) {
        waiting_.clear();
        if (running_)
            running_->stop = true;
    }
    waiting_.push_back(std::move(request));
    if (!draining_) {
        draining_ = true;
        jobPool().start([this] { drain(); });
    }
    return newest_;
}

void JobCore::cancel()
{
    for (const std::shared_ptr<JobRequest>& request : unanswered_) {
        request->cancelled = true;
        request->stop = true;
    }
}

void JobCore::drain()
{
    for (;;) {
        std::shared_ptr<JobRequest> request;
        {
            const std::lock_guard lock(mutex_);
            running_.reset();
            if (stopping_ || waiting_.empty()) {
                draining_ = false;
                // Under the lock: the destructor cannot return, and take the condition with it, before this.
                drained_.notify_all();
                return;
            }
            request = std::move(waiting_.front());
            waiting_.pop_front();
            running_ = request;
        }
        // The run's captures (a scene's copy) go as soon as it returns.
        const auto run = std::move(request->run);
        try {
            run(request);
        } catch (const JobStopped&) {
            postAnswer(request, {});
        } catch (...) {
            postAnswer(request, [this, message = currentExceptionText()] { failed_(message); });
        }
    }
}

void JobCore::postAnswer(const std::shared_ptr<JobRequest>& request, std::function<void()> deliver)
{
    QMetaObject::invokeMethod(
        &uiContext_, [this, request, deliver = std::move(deliver)] { answer(*request, deliver); },
        Qt::QueuedConnection);
}

void JobCore::postProgress(const std::shared_ptr<JobRequest>& request, std::function<void()> deliver)
{
    QMetaObject::invokeMethod(
        &uiContext_,
        [this, request, deliver = std::move(deliver)] {
            if (isUnanswered(*request) && !request->cancelled)
                deliver();
        },
        Qt::QueuedConnection);
}

bool JobCore::isUnanswered(const JobRequest& request) const
{
    return std::any_of(unanswered_.begin(), unanswered_.end(),
                       [&](const std::shared_ptr<JobRequest>& waiting) { return waiting.get() == &request; });
}

void JobCore::answer(const JobRequest& request, const std::function<void()>& deliver)
{
    // Answers arrive in the order the requests ran, which is the order they were made: a request not at
    // the front was superseded (newest wins) and is not answered.
    if (unanswered_.empty() || unanswered_.front().get() != &request)
        return;
    const bool cancelled = request.cancelled;
    unanswered_.pop_front();
    if (cancelled) {
        if (cancelled_)
            cancelled_();
    } else if (deliver) {
        deliver();
    }
}

} // namespace gyre::jobs::detail
