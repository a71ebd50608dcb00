#pragma once
// One gyre-scene-worker process kept alive between requests (scene_worker.h), driven with POSIX calls
// rather than QProcess, whose object belongs to the thread that made it: imports run on any thread of
// the pool, gyre-cli on its main thread. Requests and replies travel as frames on a socket pair: an
// 8-byte little-endian length, then the scene_wire bytes. The worker's standard error goes to a pipe
// whose end is kept for messages.
//
// Not thread-safe: its owner serialises the calls (one request at a time).

#include <QByteArray>
#include <QDeadlineTimer>
#include <QString>

#include <sys/types.h>

#include <atomic>

namespace gyre::io {

class WorkerProcess {
public:
    // How a request ended.
    enum class Outcome {
        Replied,   // `reply` holds one whole frame's contents
        Ended,     // the worker ended before a whole reply: see status()
        TimedOut,  // the deadline passed
        Cancelled, // the cancel flag was set
        TooLarge,  // the reply's length is over the bound
    };

    // Starts `program` with its address space limited to `memoryBytes` (not under AddressSanitizer,
    // whose shadow memory needs an unlimited one: its bound on one allocation stands in, set through
    // ASAN_OPTIONS). Throws std::system_error when the program cannot be started.
    WorkerProcess(const QString& program, qint64 memoryBytes);
    // Closes the channel, which ends an idle worker, and reaps it: never a zombie or an orphan.
    ~WorkerProcess();
    WorkerProcess(const WorkerProcess&) = delete;
    WorkerProcess& operator=(const WorkerProcess&) = delete;

    const QString& program() const { return program_; }
    qint64 memoryBytes() const { return memoryBytes_; }
    // Whether the process has not ended, reaping it if it has: a worker killed while idle is replaced
    // rather than blamed on the next file.
    bool isRunning();
    // The requests this process has answered.
    int served() const { return served_; }

    // Sends `request` as a frame and waits for the reply's frame, the worker's end, the deadline or the
    // cancel flag (looked at every 50 ms). After anything but Replied the worker has ended or must be
    // killed.
    Outcome exchange(const QByteArray& request, QByteArray& reply, qint64 maxReplyBytes,
                     const QDeadlineTimer& deadline, const std::atomic_bool* cancel);

    // After Outcome::Ended: the process's wait status, as waitpid gives it.
    int status() const { return status_; }
    // The last 4 KB the worker wrote on standard error.
    const QByteArray& errors() const { return errors_; }

    // SIGKILL and reap; idempotent.
    void kill();

private:
    bool readErrors();
    // Waits until the worker has ended (true), or the deadline or the cancel flag (false), keeping its
    // standard error.
    bool waitForEnd(const QDeadlineTimer& deadline, const std::atomic_bool* cancel);
    void closeChannels();

    QString program_;
    qint64 memoryBytes_ = 0;
    pid_t pid_ = -1;
    int channel_ = -1; // the parent's end of the socket pair
    int errorPipe_ = -1;
    int status_ = 0;
    int served_ = 0;
    QByteArray errors_;
};

} // namespace gyre::io
