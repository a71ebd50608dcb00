#include "io/worker_process.h"

#include <QFile>
#include <QProcessEnvironment>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <string>
#include <system_error>
#include <vector>

namespace gyre::io {

namespace {

// How often a waiting call looks at the cancel flag.
constexpr qint64 kPollMilliseconds = 50;

constexpr qsizetype kKeptErrorBytes = 4096;
constexpr int kFrameHeaderBytes = 8;
// How long an idle worker is given to end after its channel closes before it is killed.
constexpr int kEndMilliseconds = 2000;

// The poll timeout: what is left of `deadline`, at most kPollMilliseconds.
int pollTimeout(const QDeadlineTimer& deadline)
{
    const qint64 remaining = deadline.remainingTime(); // -1 for a deadline that never comes
    return static_cast<int>(remaining < 0 ? kPollMilliseconds : std::min(remaining, kPollMilliseconds));
}

[[noreturn]] void throwErrno() { throw std::system_error(errno, std::generic_category()); }

// The environment the worker starts with, prepared before fork: the child may not allocate.
std::vector<std::string> workerEnvironment([[maybe_unused]] qint64 memoryBytes)
{
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
#if defined(__SANITIZE_ADDRESS__)
    // A sanitizer's report ends a process with status 1, which would read as a failure of the worker
    // rather than the crash it stands for: ended by abort(), its memory errors are crashes here too.
    // With no address-space limit, AddressSanitizer's own bound on one allocation stands in for it, so
    // a file that asks for gigabytes is stopped before it takes them.
    const auto addOptions = [&environment](const QString& name, const QString& added) {
        const QString options = environment.value(name);
        environment.insert(name, options.isEmpty() ? added : options + QLatin1Char(':') + added);
    };
    addOptions(QStringLiteral("ASAN_OPTIONS"),
               QStringLiteral("abort_on_error=1:max_allocation_size_mb=%1").arg(memoryBytes >> 20));
    addOptions(QStringLiteral("UBSAN_OPTIONS"), QStringLiteral("abort_on_error=1"));
#endif
    std::vector<std::string> entries;
    for (const QString& entry : environment.toStringList())
        entries.push_back(QFile::encodeName(entry).toStdString());
    return entries;
}

std::vector<char*> pointersTo(std::vector<std::string>& strings)
{
    std::vector<char*> pointers;
    for (std::string& string : strings)
        pointers.push_back(string.data());
    pointers.push_back(nullptr);
    return pointers;
}

QByteArray frameHeader(quint64 length)
{
    QByteArray header(kFrameHeaderBytes, Qt::Uninitialized);
    for (int i = 0; i < kFrameHeaderBytes; ++i)
        header[i] = static_cast<char>((length >> (8 * i)) & 0xff);
    return header;
}

quint64 frameLength(const QByteArray& header)
{
    quint64 length = 0;
    for (int i = 0; i < kFrameHeaderBytes; ++i)
        length |= quint64{static_cast<unsigned char>(header[i])} << (8 * i);
    return length;
}

} // namespace

WorkerProcess::WorkerProcess(const QString& program, qint64 memoryBytes)
    : program_(program), memoryBytes_(memoryBytes)
{
    std::string path = QFile::encodeName(program).toStdString();
    std::vector<std::string> environmentStrings = workerEnvironment(memoryBytes);
    std::vector<char*> environment = pointersTo(environmentStrings);
    char* const argv[] = {path.data(), nullptr};

    int channel[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, channel) != 0)
        throwErrno();
    int errorPipe[2] = {-1, -1};
    // The child writes errno here when execve fails; a successful exec closes it (O_CLOEXEC).
    int execPipe[2];
    if (pipe2(errorPipe, O_CLOEXEC) != 0 || pipe2(execPipe, O_CLOEXEC) != 0) {
        const int error = errno;
        for (int fd : {channel[0], channel[1], errorPipe[0], errorPipe[1]})
            if (fd >= 0)
                close(fd);
        throw std::system_error(error, std::generic_category());
    }
#if !defined(__SANITIZE_ADDRESS__)
    const rlimit limit{static_cast<rlim_t>(memoryBytes), static_cast<rlim_t>(memoryBytes)};
#endif
    pid_ = fork();
    if (pid_ == 0) {
        // Between fork and exec only async-signal-safe calls: the parent may have other threads,
        // whose locks are copied held. dup2 clears FD_CLOEXEC on the copies the worker keeps.
#if !defined(__SANITIZE_ADDRESS__)
        // Its failure leaves the limit off; the time limit still holds.
        setrlimit(RLIMIT_AS, &limit);
#endif
        if (dup2(channel[1], STDIN_FILENO) >= 0 && dup2(channel[1], STDOUT_FILENO) >= 0 &&
            dup2(errorPipe[1], STDERR_FILENO) >= 0)
            execve(argv[0], argv, environment.data());
        const int error = errno;
        [[maybe_unused]] const ssize_t written = write(execPipe[1], &error, sizeof error);
        _exit(127);
    }
    const int forkError = errno;
    close(channel[1]);
    close(errorPipe[1]);
    close(execPipe[1]);
    channel_ = channel[0];
    errorPipe_ = errorPipe[0];
    if (pid_ < 0) {
        close(execPipe[0]);
        closeChannels();
        throw std::system_error(forkError, std::generic_category());
    }
    int execError = 0;
    ssize_t n;
    do
        n = read(execPipe[0], &execError, sizeof execError);
    while (n < 0 && errno == EINTR);
    close(execPipe[0]);
    if (n == sizeof execError) {
        kill();
        throw std::system_error(execError, std::generic_category());
    }
    // Non-blocking, so that neither a worker that stops reading nor one that stops writing can hold
    // this side past its deadline.
    fcntl(channel_, F_SETFL, fcntl(channel_, F_GETFL) | O_NONBLOCK);
    fcntl(errorPipe_, F_SETFL, fcntl(errorPipe_, F_GETFL) | O_NONBLOCK);
}

WorkerProcess::~WorkerProcess()
{
    // The worker ends at the end of its input; an idle one does so at once.
    if (channel_ >= 0)
        close(channel_);
    channel_ = -1;
    if (pid_ > 0 && !waitForEnd(QDeadlineTimer(kEndMilliseconds), nullptr))
        kill();
    closeChannels();
}

void WorkerProcess::closeChannels()
{
    for (int* fd : {&channel_, &errorPipe_})
        if (*fd >= 0) {
            close(*fd);
            *fd = -1;
        }
}

void WorkerProcess::kill()
{
    if (pid_ > 0) {
        ::kill(pid_, SIGKILL);
        while (waitpid(pid_, &status_, 0) < 0 && errno == EINTR) {
        }
        pid_ = -1;
    }
    closeChannels();
}

bool WorkerProcess::isRunning()
{
    if (pid_ > 0 && waitpid(pid_, &status_, WNOHANG) == pid_)
        pid_ = -1;
    return pid_ > 0;
}

// Reads what the worker wrote on standard error; false at its end.
bool WorkerProcess::readErrors()
{
    if (errorPipe_ < 0)
        return false;
    char buffer[4096];
    while (true) {
        const ssize_t n = read(errorPipe_, buffer, sizeof buffer);
        if (n > 0) {
            errors_.append(buffer, n);
            if (errors_.size() > kKeptErrorBytes)
                errors_ = errors_.right(kKeptErrorBytes);
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0 && errno == EAGAIN)
            return true;
        close(errorPipe_);
        errorPipe_ = -1;
        return false;
    }
}

bool WorkerProcess::waitForEnd(const QDeadlineTimer& deadline, const std::atomic_bool* cancel)
{
    while (true) {
        const pid_t ended = waitpid(pid_, &status_, WNOHANG);
        if (ended == pid_ || (ended < 0 && errno != EINTR)) {
            pid_ = -1;
            readErrors();
            return true;
        }
        if (deadline.hasExpired() || (cancel && cancel->load()))
            return false;
        // Its standard error ends with it; until then, the poll also paces this loop.
        pollfd errorPoll{errorPipe_, POLLIN, 0};
        if (errorPipe_ < 0)
            usleep(1000);
        else if (poll(&errorPoll, 1, pollTimeout(deadline)) > 0)
            readErrors();
    }
}

WorkerProcess::Outcome WorkerProcess::exchange(const QByteArray& request, QByteArray& reply, qint64 maxReplyBytes,
                                               const QDeadlineTimer& deadline, const std::atomic_bool* cancel)
{
    errors_.clear();
    const QByteArray frame = frameHeader(static_cast<quint64>(request.size())) + request;
    qsizetype sent = 0;
    QByteArray header;
    quint64 length = 0;
    bool channelOpen = true;
    reply.clear();
    while (channelOpen) {
        if (cancel && cancel->load())
            return Outcome::Cancelled;
        if (deadline.hasExpired())
            return Outcome::TimedOut;
        pollfd fds[2] = {{channel_, static_cast<short>(POLLIN | (sent < frame.size() ? POLLOUT : 0)), 0},
                         {errorPipe_, POLLIN, 0}};
        if (poll(fds, errorPipe_ >= 0 ? 2 : 1, pollTimeout(deadline)) < 0 && errno != EINTR)
            throwErrno();
        if (fds[1].revents != 0)
            readErrors();
        if (sent < frame.size() && (fds[0].revents & POLLOUT)) {
            const ssize_t n = send(channel_, frame.constData() + sent, static_cast<std::size_t>(frame.size() - sent),
                                   MSG_NOSIGNAL);
            if (n > 0)
                sent += n;
            else if (n < 0 && errno != EAGAIN && errno != EINTR)
                channelOpen = false; // the worker has gone: its status says how
        }
        if (!(fds[0].revents & (POLLIN | POLLHUP | POLLERR)))
            continue;
        // Only the bytes this frame still needs: anything after it is not read as part of it.
        char buffer[1 << 16];
        const bool inHeader = header.size() < kFrameHeaderBytes;
        const qint64 wanted = inHeader ? kFrameHeaderBytes - header.size() : static_cast<qint64>(length) - reply.size();
        const ssize_t n = recv(channel_, buffer, static_cast<std::size_t>(std::min<qint64>(wanted, sizeof buffer)), 0);
        if (n < 0) {
            if (errno != EAGAIN && errno != EINTR)
                channelOpen = false;
            continue;
        }
        if (n == 0) {
            channelOpen = false;
            continue;
        }
        if (inHeader) {
            header.append(buffer, n);
            if (header.size() == kFrameHeaderBytes) {
                length = frameLength(header);
                if (length > static_cast<quint64>(maxReplyBytes))
                    return Outcome::TooLarge;
                reply.reserve(static_cast<qsizetype>(length));
            }
        } else {
            reply.append(buffer, n);
        }
        if (header.size() == kFrameHeaderBytes && reply.size() == static_cast<qsizetype>(length)) {
            ++served_;
            readErrors();
            return Outcome::Replied;
        }
    }
    if (!waitForEnd(deadline, cancel))
        return cancel && cancel->load() ? Outcome::Cancelled : Outcome::TimedOut;
    return Outcome::Ended;
}

} // namespace gyre::io
