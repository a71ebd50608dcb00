#include "jobs/job_thread.h"

#include <exception>
#include <new>
#include <utility>

namespace gyre::jobs {

std::string currentExceptionText()
{
    try {
        throw;
    } catch (const std::bad_alloc&) {
        return "not enough memory";
    } catch (const std::exception& error) {
        return error.what();
    } catch (...) {
        return "an unknown error";
    }
}

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
        // An exception leaving a std::thread's function ends the process: the work has had its chance to
        // report it, so it stops here.
        try {
            work(superseded_);
        } catch (...) {
        }
    }
}

} // namespace gyre::jobs
