#include "jobs/job_thread.h"

#include <utility>

namespace gyre::jobs {

JobThread::JobThread()
    : thread_([this] { run(); })
{
}

JobThread::~JobThread()
{
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
        waiting_.reset();
        superseded_ = true;
    }
    wake_.notify_one();
    thread_.join();
}

void JobThread::post(Work work)
{
    {
        const std::lock_guard lock(mutex_);
        waiting_ = std::move(work);
        superseded_ = true;
    }
    wake_.notify_one();
}

void JobThread::run()
{
    for (;;) {
        Work work;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return stopping_ || waiting_.has_value(); });
            if (stopping_)
                return;
            work = std::move(*waiting_);
            waiting_.reset();
            superseded_ = false;
        }
        work(superseded_);
    }
}

} // namespace gyre::jobs
