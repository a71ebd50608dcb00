#include "io/scene_worker.h"

#include "io/scene_wire.h"
#include "io/worker_process.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QFileInfo>

#include <sys/wait.h>

#include <cstring>
#include <memory>
#include <mutex>
#include <system_error>

namespace gyre::io {

namespace {

constexpr qsizetype kMaxQuotedErrorChars = 300;

QString sizeText(qint64 bytes)
{
    constexpr qint64 kMiB = qint64{1} << 20;
    constexpr qint64 kGiB = qint64{1} << 30;
    if (bytes % kGiB == 0)
        return FileError::tr("%1 GiB").arg(bytes / kGiB);
    return FileError::tr("%1 MiB").arg(bytes / kMiB);
}

// "SIGSEGV" for 11.
QString signalName(int signal)
{
    const char* abbreviation = sigabbrev_np(signal);
    return abbreviation ? QStringLiteral("SIG") + QString::fromLatin1(abbreviation) : QString();
}

// The last line the worker wrote on standard error, as ": <line>", or nothing.
QString lastErrorLine(const QByteArray& errors)
{
    const QList<QByteArray> lines = errors.trimmed().split('\n');
    const QString line = QString::fromUtf8(lines.back().trimmed()).left(kMaxQuotedErrorChars);
    return line.isEmpty() ? QString() : QStringLiteral(": ") + line;
}

QString executableDirectory()
{
    if (QCoreApplication::instance())
        return QCoreApplication::applicationDirPath();
    return QFileInfo(QFileInfo(QStringLiteral("/proc/self/exe")).canonicalFilePath()).path();
}

// The one worker this process keeps between requests, with the lock that gives it one request at a
// time. Destroyed at exit, after the thread pool's jobs have ended with the application: its
// destructor uses POSIX calls only, so the order of static destruction cannot matter.
struct SharedWorker {
    std::mutex mutex;
    std::unique_ptr<WorkerProcess> process;
};

SharedWorker& sharedWorker()
{
    static SharedWorker worker;
    return worker;
}

template <class Error>
Error workerError(const QString& path, const QString& what)
{
    return Error(path, what.toStdString());
}

// Whether a worker that has ended ran out of memory.
bool ranOutOfMemory([[maybe_unused]] const WorkerProcess& worker)
{
#if defined(__SANITIZE_ADDRESS__)
    // The sanitizer's allocation bound, standing in for the address-space limit, ends the worker by
    // its report and abort(): the same failure as status kWorkerOutOfMemoryStatus without it.
    return worker.errors().contains("SUMMARY: AddressSanitizer: allocation-size-too-big") ||
           worker.errors().contains("SUMMARY: AddressSanitizer: out-of-memory");
#else
    return WIFEXITED(worker.status()) && WEXITSTATUS(worker.status()) == kWorkerOutOfMemoryStatus;
#endif
}

// Sends `request` to `worker` and returns the reply, a Result or the file's Failure, or throws Error
// naming `path`. Sets `outOfMemory` instead of throwing when the worker ran out of memory, which the
// caller may retry.
template <class Result, class Error>
wire::Reply askWorker(WorkerProcess& worker, const QString& path, const QByteArray& request,
                     const SceneWorkerLimits& limits, const std::atomic_bool* cancel, bool& outOfMemory)
{
    const auto fail = [&path](const QString& what) { return workerError<Error>(path, what); };
    QByteArray reply;
    const auto decode = [&] {
        wire::Reply decoded;
        try {
            decoded = wire::decodeReply(reply);
        } catch (const wire::WireError& error) {
            worker.kill();
            throw fail(FileError::tr("the scene reader's reply is malformed: %1").arg(QString::fromUtf8(error.what())));
        }
        if (!std::holds_alternative<Result>(decoded) && !std::holds_alternative<wire::Failure>(decoded)) {
            worker.kill();
            throw fail(FileError::tr("the scene reader's reply is malformed: the wrong kind of reply"));
        }
        return decoded;
    };
    const WorkerProcess::Outcome outcome =
        worker.exchange(request, reply, wire::kMaxMessageBytes, QDeadlineTimer(limits.time), cancel);
    if (outcome == WorkerProcess::Outcome::Replied)
        return decode();
    worker.kill();
    switch (outcome) {
    case WorkerProcess::Outcome::Cancelled:
        throw SceneWorkerCancelled();
    case WorkerProcess::Outcome::TimedOut:
        throw fail(FileError::tr("the scene reader took longer than %1 s and was stopped; the file may be "
                                 "damaged or too large")
                       .arg(FileError::number(std::chrono::duration<double>(limits.time).count())));
    case WorkerProcess::Outcome::TooLarge:
        throw fail(FileError::tr("the scene reader's reply is larger than %1").arg(sizeText(wire::kMaxMessageBytes)));
    default:
        break;
    }
    const int status = worker.status();
    if (ranOutOfMemory(worker)) {
        outOfMemory = true;
        return {};
    }
    if (WIFSIGNALED(status))
        throw fail(FileError::tr("the scene reader crashed on this file (signal %1, %2)%3")
                       .arg(WTERMSIG(status))
                       .arg(signalName(WTERMSIG(status)), lastErrorLine(worker.errors())));
    if (WEXITSTATUS(status) != 0)
        throw fail(FileError::tr("the scene reader failed (exit status %1)%2")
                       .arg(WEXITSTATUS(status))
                       .arg(lastErrorLine(worker.errors())));
    // Ended with success before a whole frame: what came is read as the reply, untrusted as ever.
    return decode();
}

// Runs the worker on `request` and returns its reply, or throws Error (InputError or OutputError)
// naming `path`. The worker of an earlier request answers if it runs the same program under the same
// limit; any failure but the file's own error reply ends it, and the next request starts another.
template <class Result, class Error>
wire::Reply runWorker(const QString& path, const QByteArray& request, const SceneWorkerLimits& limits,
                      const std::atomic_bool* cancel)
{
    const auto fail = [&path](const QString& what) { return workerError<Error>(path, what); };
    const QString program = sceneWorkerProgram();
    if (program.isEmpty())
        throw fail(FileError::tr("the scene reader %1 is not installed beside %2")
                       .arg(QLatin1String(kSceneWorkerName), executableDirectory()));
    // Checked before forking, for a plainer message than exec's.
    if (const QFileInfo info(program); !info.isFile() || !info.isExecutable())
        throw fail(FileError::tr("the scene reader %1 is missing or not executable").arg(program));

    SharedWorker& shared = sharedWorker();
    const std::lock_guard lock(shared.mutex);
    std::unique_ptr<WorkerProcess>& worker = shared.process;
    // The address-space limit holds for the worker's whole life, and heap left from earlier requests
    // counts against it: a reused worker that runs out of memory gets the request again, once, in a
    // fresh process, so that only a file a fresh worker cannot read fails for memory.
    for (int attempt = 0;; ++attempt) {
        if (worker && (!worker->isRunning() || worker->program() != program ||
                       worker->memoryBytes() != limits.memoryBytes))
            worker.reset();
        if (!worker) {
            try {
                worker = std::make_unique<WorkerProcess>(program, limits.memoryBytes);
            } catch (const std::system_error& error) {
                throw fail(FileError::tr("the scene reader %1 cannot be started: %2")
                               .arg(program, QString::fromLocal8Bit(error.what())));
            }
        }
        const bool reused = worker->served() > 0;
        bool outOfMemory = false;
        wire::Reply reply;
        try {
            reply = askWorker<Result, Error>(*worker, path, request, limits, cancel, outOfMemory);
        } catch (...) {
            worker.reset();
            throw;
        }
        if (!outOfMemory)
            return reply;
        worker.reset();
        if (!reused || attempt > 0)
            throw fail(FileError::tr("the scene reader needed more than %1 of memory for this file and was stopped")
                           .arg(sizeText(limits.memoryBytes)));
    }
}

// The worker's own error, as it would have been thrown here: its message already names the file.
template <class Error>
[[noreturn]] void rethrow(const QString& path, const wire::Failure& failure)
{
    const QString prefix = path + QStringLiteral(": ");
    const QString& message = failure.message;
    const QString what = message.startsWith(prefix) ? message.mid(prefix.size()) : message;
    if (failure.kind == wire::Failure::Kind::Output)
        throw OutputError(path, what.toStdString());
    throw Error(path, what.toStdString());
}

template <class Result, class Error>
Result resultOf(const QString& path, wire::Reply reply)
{
    if (auto* result = std::get_if<Result>(&reply))
        return std::move(*result);
    rethrow<Error>(path, std::get<wire::Failure>(reply)); // runWorker let no other kind through
}

// The locale's name, guarded: the app sets it on its UI thread, jobs read it on the thread pool.
std::mutex localeMutex;
QString workerLocale;

QString sceneWorkerLocale()
{
    const std::lock_guard lock(localeMutex);
    return workerLocale;
}

} // namespace

void setSceneWorkerLocale(const QLocale& locale)
{
    const std::lock_guard lock(localeMutex);
    workerLocale = locale == QLocale::c() ? QString() : locale.name();
}

QString sceneWorkerProgram()
{
    if (qEnvironmentVariableIsSet(kSceneWorkerVariable))
        return qEnvironmentVariable(kSceneWorkerVariable);
    const QString directory = executableDirectory();
    const QString name = QLatin1String(kSceneWorkerName);
    for (const QString& candidate : {directory + QLatin1Char('/') + name, directory + QStringLiteral("/../worker/") + name})
        if (const QFileInfo info(candidate); info.isFile() && info.isExecutable())
            return info.absoluteFilePath();
    return {};
}

SceneImport importSceneInWorker(const QString& path, const ImportOptions& options, const SceneWorkerLimits& limits,
                                const std::atomic_bool* cancel)
{
    const QByteArray request = wire::encodeRequest(wire::ImportRequest{path, sceneWorkerLocale(), options});
    return resultOf<SceneImport, InputError>(path, runWorker<SceneImport, InputError>(path, request, limits, cancel));
}

ExportReport exportSceneInWorker(const model::Scene& scene, const QString& path, SceneFormat format, double fps,
                                 const SceneWorkerLimits& limits)
{
    const QByteArray request = wire::encodeRequest(wire::ExportRequest{path, sceneWorkerLocale(), format, fps, scene});
    return resultOf<ExportReport, OutputError>(path, runWorker<ExportReport, OutputError>(path, request, limits, nullptr));
}

} // namespace gyre::io
