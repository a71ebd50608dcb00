#include "io/scene_worker.h"

#include "io/scene_wire.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QFileInfo>
#include <QProcess>

#include <sys/resource.h>

#include <algorithm>
#include <cstring>
#include <mutex>

namespace gyre {

namespace {

// A reply larger than this is not a scene Gyre could hold: the worker is stopped.
constexpr qint64 kMaxReplyBytes = qint64{1} << 30;
// How often a waiting call looks at the clock and at the cancel flag.
constexpr int kPollMilliseconds = 50;
// The end of the worker's standard error kept for the message: an assertion's text, for example.
constexpr qsizetype kKeptErrorBytes = 4096;
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

void limitAddressSpace([[maybe_unused]] qint64 bytes)
{
#if !defined(__SANITIZE_ADDRESS__)
    // In the child between fork and exec, where only async-signal-safe calls are allowed: setrlimit
    // is a plain system call. Its failure leaves the limit off; the time limit still holds.
    const rlimit limit{static_cast<rlim_t>(bytes), static_cast<rlim_t>(bytes)};
    setrlimit(RLIMIT_AS, &limit);
#endif
    // AddressSanitizer reserves terabytes of address space for its shadow memory, so a worker built
    // with it cannot start under any address-space limit; such builds rely on the time limit alone.
}

QString executableDirectory()
{
    if (QCoreApplication::instance())
        return QCoreApplication::applicationDirPath();
    return QFileInfo(QFileInfo(QStringLiteral("/proc/self/exe")).canonicalFilePath()).path();
}

// Runs the worker on `request` and returns its reply, or throws Error (InputError or OutputError)
// naming `path`.
template <class Error>
wire::Reply runWorker(const QString& path, const QByteArray& request, const SceneWorkerLimits& limits,
                      const std::atomic_bool* cancel)
{
    const auto fail = [&path](const QString& what) { return Error(path, what.toStdString()); };
    const QString program = sceneWorkerProgram();
    if (program.isEmpty())
        throw fail(FileError::tr("the scene reader %1 is not installed beside %2")
                       .arg(QLatin1String(kSceneWorkerName), executableDirectory()));
    // Checked before forking, for a plainer message than exec's.
    if (const QFileInfo info(program); !info.isFile() || !info.isExecutable())
        throw fail(FileError::tr("the scene reader %1 is missing or not executable").arg(program));
    QProcess process;
    process.setProgram(program);
    const qint64 memoryBytes = limits.memoryBytes;
    process.setChildProcessModifier([memoryBytes] { limitAddressSpace(memoryBytes); });
#if defined(__SANITIZE_ADDRESS__)
    // A sanitizer's report ends a process with status 1, which would read as a failure of the worker
    // rather than the crash it stands for: ended by abort(), its memory errors are crashes here too.
    // With no address-space limit (limitAddressSpace), AddressSanitizer's own bound on one allocation
    // stands in for it, so a file that asks for gigabytes is stopped before it takes them.
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    const auto addOptions = [&environment](const QString& name, const QString& added) {
        const QString options = environment.value(name);
        environment.insert(name, options.isEmpty() ? added : options + QLatin1Char(':') + added);
    };
    addOptions(QStringLiteral("ASAN_OPTIONS"),
               QStringLiteral("abort_on_error=1:max_allocation_size_mb=%1").arg(memoryBytes >> 20));
    addOptions(QStringLiteral("UBSAN_OPTIONS"), QStringLiteral("abort_on_error=1"));
    process.setProcessEnvironment(environment);
#endif
    process.start(QIODevice::ReadWrite);
    if (!process.waitForStarted())
        throw fail(FileError::tr("the scene reader %1 cannot be started: %2").arg(program, process.errorString()));
    process.write(request);
    process.closeWriteChannel();

    const QDeadlineTimer deadline(limits.time);
    QByteArray reply;
    QByteArray errors;
    const auto stop = [&process] {
        process.kill();
        process.waitForFinished();
    };
    while (process.state() != QProcess::NotRunning) {
        if (cancel && cancel->load()) {
            stop();
            throw SceneWorkerCancelled();
        }
        if (deadline.hasExpired()) {
            stop();
            throw fail(FileError::tr("the scene reader took longer than %1 s and was stopped; the file may be "
                                     "damaged or too large")
                           .arg(FileError::number(std::chrono::duration<double>(limits.time).count())));
        }
        process.waitForFinished(static_cast<int>(std::min<qint64>(deadline.remainingTime(), kPollMilliseconds)));
        reply += process.readAllStandardOutput();
        errors = (errors + process.readAllStandardError()).right(kKeptErrorBytes);
        if (reply.size() > kMaxReplyBytes) {
            stop();
            throw fail(FileError::tr("the scene reader's reply is larger than %1").arg(sizeText(kMaxReplyBytes)));
        }
    }
    reply += process.readAllStandardOutput();
    errors = (errors + process.readAllStandardError()).right(kKeptErrorBytes);

#if defined(__SANITIZE_ADDRESS__)
    // The sanitizer's allocation bound, standing in for the address-space limit, ends the worker by
    // its report and abort(): the same failure as status kWorkerOutOfMemoryStatus without it.
    const bool outOfMemory = errors.contains("SUMMARY: AddressSanitizer: allocation-size-too-big") ||
                             errors.contains("SUMMARY: AddressSanitizer: out-of-memory");
#else
    const bool outOfMemory = process.exitStatus() == QProcess::NormalExit && process.exitCode() == kWorkerOutOfMemoryStatus;
#endif
    if (outOfMemory)
        throw fail(FileError::tr("the scene reader needed more than %1 of memory for this file and was stopped")
                       .arg(sizeText(limits.memoryBytes)));
    if (process.exitStatus() == QProcess::CrashExit) // Qt gives the signal as the exit code
        throw fail(FileError::tr("the scene reader crashed on this file (signal %1, %2)%3")
                       .arg(process.exitCode())
                       .arg(signalName(process.exitCode()), lastErrorLine(errors)));
    if (process.exitCode() != 0)
        throw fail(FileError::tr("the scene reader failed (exit status %1)%2")
                       .arg(process.exitCode())
                       .arg(lastErrorLine(errors)));
    try {
        return wire::decodeReply(reply);
    } catch (const wire::WireError& error) {
        throw fail(FileError::tr("the scene reader's reply is malformed: %1").arg(QString::fromUtf8(error.what())));
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
    if (const auto* failure = std::get_if<wire::Failure>(&reply))
        rethrow<Error>(path, *failure);
    throw Error(path, FileError::tr("the scene reader's reply is malformed: the wrong kind of reply").toStdString());
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
    return resultOf<SceneImport, InputError>(path, runWorker<InputError>(path, request, limits, cancel));
}

ExportReport exportSceneInWorker(const model::Scene& scene, const QString& path, SceneFormat format, double fps,
                                 const SceneWorkerLimits& limits)
{
    const QByteArray request = wire::encodeRequest(wire::ExportRequest{path, sceneWorkerLocale(), format, fps, scene});
    return resultOf<ExportReport, OutputError>(path, runWorker<OutputError>(path, request, limits, nullptr));
}

} // namespace gyre
