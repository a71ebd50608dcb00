#pragma once
// A thread of its own for one kind of work, newest request first. A request made while the thread is
// busy replaces the request still waiting, if any, so a burst of requests (a pose being dragged, a
// stroke being drawn) costs one run per finished run, not one per request, and the last request made
// is always run. A running job learns through `superseded` that a newer request is waiting, so long
// work (a fit) can stop early.
//
// Results go back to the UI thread through a queued call on a QObject the work captures
// (QMetaObject::invokeMethod(receiver, ..., Qt::QueuedConnection)); such calls are dropped if the
// receiver is gone. Declare the JobThread after everything its work uses, so it is destroyed, and its
// thread joined, first.

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace gyre::jobs {

// What the exception being handled says, inside a catch block: its what(), or that it is unknown. For a
// job's `catch (...)`, so that every failure, not only the expected ones, reaches the UI as a message.
std::string currentExceptionText();

class JobThread {
public:
    using Work = std::function<void(const std::atomic<bool>& superseded)>;

    JobThread();
    // Lets the running job see `superseded`, waits for it to return, and drops a waiting request.
    ~JobThread();
    JobThread(const JobThread&) = delete;
    JobThread& operator=(const JobThread&) = delete;

    // Runs `work` on the thread once the current job is done, in place of a request still waiting. Work
    // reports its own failures; an exception that still escapes it is dropped, and the thread lives on.
    void post(Work work);

private:
    void run();

    std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<Work> waiting_;
    bool stopping_ = false;
    std::atomic<bool> superseded_ = false;
    std::thread thread_; // last: starts once everything above exists
};

} // namespace gyre::jobs
