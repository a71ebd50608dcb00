// gyre-scene-worker: reads requests on standard input, imports or exports a scene with Assimp for each,
// and writes each reply on standard output (io/scene_wire.h), both as frames: an 8-byte little-endian
// length, then the message. Gyre and gyre-cli keep one running between scene files
// (io/scene_worker.h), so that whatever Assimp does with a damaged file (crash, abort, endless
// allocation) ends this process and not theirs. It takes no arguments and is not meant to be run by
// hand.
//
// Exit status: 0 at the end of its input, every request answered (an answer may be the file's error);
// kWorkerOutOfMemoryStatus when an allocation failed under the memory limit its parent set; 1 when a
// request could not be read, was larger than kMaxMessageBytes, or a reply could not be written.

#include "io/scene_wire.h"
#include "io/scene_worker.h"

#include <QCoreApplication>
#include <QLocale>
#include <QTranslator>

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <exception>
#include <new>
#include <variant>

namespace {

using namespace gyre;
using namespace gyre::io;

// Any allocation that fails, in Gyre or in Assimp (whose readers catch std::bad_alloc and report it
// as a read error), ends the worker at once with the status that tells the parent why.
[[noreturn]] void exitOutOfMemory() { _exit(kWorkerOutOfMemoryStatus); }

constexpr int kFrameHeaderBytes = 8;

// Reads exactly `size` bytes; false at the end of the input before the first of them.
bool readExactly(int fd, char* into, std::size_t size)
{
    for (std::size_t at = 0; at < size;) {
        const ssize_t n = read(fd, into + at, size - at);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            throw std::runtime_error(std::string("cannot read the request: ") + std::strerror(errno));
        if (n == 0) {
            if (at == 0)
                return false;
            throw std::runtime_error("cannot read the request: it ends early");
        }
        at += static_cast<std::size_t>(n);
    }
    return true;
}

// The next request's frame: an 8-byte little-endian length, then the bytes. Nothing at the end of the
// input, which is the parent's way to end the worker.
std::optional<QByteArray> readFrame(int fd)
{
    unsigned char header[kFrameHeaderBytes];
    if (!readExactly(fd, reinterpret_cast<char*>(header), sizeof header))
        return std::nullopt;
    quint64 length = 0;
    for (int i = 0; i < kFrameHeaderBytes; ++i)
        length |= quint64{header[i]} << (8 * i);
    if (length > static_cast<quint64>(wire::kMaxMessageBytes))
        throw std::runtime_error("the request is larger than a scene Gyre could hold");
    QByteArray bytes(static_cast<qsizetype>(length), Qt::Uninitialized);
    if (length > 0 && !readExactly(fd, bytes.data(), bytes.size()))
        throw std::runtime_error("cannot read the request: it ends early");
    return bytes;
}

void writeAll(int fd, const QByteArray& bytes)
{
    for (qsizetype at = 0; at < bytes.size();) {
        const ssize_t n = write(fd, bytes.constData() + at, static_cast<std::size_t>(bytes.size() - at));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            throw std::runtime_error(std::string("cannot write the reply: ") + std::strerror(errno));
        at += n;
    }
}

void writeFrame(int fd, const QByteArray& bytes)
{
    QByteArray header(kFrameHeaderBytes, Qt::Uninitialized);
    for (int i = 0; i < kFrameHeaderBytes; ++i)
        header[i] = static_cast<char>((static_cast<quint64>(bytes.size()) >> (8 * i)) & 0xff);
    writeAll(fd, header);
    writeAll(fd, bytes);
}

// Gyre's translation for the locale the request names, as the app installs it (app/language.cpp). A
// worker serves many requests, so the translation of an earlier one is replaced.
void installTranslation(const QString& locale, std::unique_ptr<QTranslator>& translator)
{
    translator.reset(); // its destructor removes it from the application
    auto loaded = std::make_unique<QTranslator>();
    if (!locale.isEmpty() &&
        loaded->load(QLocale(locale), QStringLiteral("gyre"), QStringLiteral("_"), QStringLiteral(":/i18n"))) {
        QCoreApplication::installTranslator(loaded.get());
        translator = std::move(loaded);
    }
}

wire::Reply answer(const wire::Request& request)
{
    try {
        if (const auto* import = std::get_if<wire::ImportRequest>(&request))
            return importScene(import->path, import->options);
        const auto& job = std::get<wire::ExportRequest>(request);
        return exportScene(job.scene, job.path, job.format, job.fps);
    } catch (const OutputError& error) {
        return wire::Failure{wire::Failure::Kind::Output, QString::fromUtf8(error.what())};
    } catch (const InputError& error) {
        return wire::Failure{wire::Failure::Kind::Input, QString::fromUtf8(error.what())};
    }
}

} // namespace

int main(int argc, char* argv[])
{
    std::set_new_handler(exitOutOfMemory);
    // The reply goes to a descriptor of its own; whatever a library prints on standard output goes to
    // standard error instead, where it cannot corrupt the reply.
    const int replyFd = dup(STDOUT_FILENO);
    if (replyFd < 0 || dup2(STDERR_FILENO, STDOUT_FILENO) < 0) {
        std::perror("gyre-scene-worker");
        return 1;
    }
    try {
        const QCoreApplication application(argc, argv);
        std::unique_ptr<QTranslator> translator;
        std::optional<QString> locale;
        while (const std::optional<QByteArray> frame = readFrame(STDIN_FILENO)) {
            const wire::Request request = wire::decodeRequest(*frame);
            const QString requested = std::visit([](const auto& job) { return job.locale; }, request);
            if (requested != locale) {
                installTranslation(requested, translator);
                locale = requested;
            }
            writeFrame(replyFd, wire::encodeReply(answer(request)));
            std::fflush(stderr);
        }
        // The end of the input: the parent is done with this worker. Destroying the application and
        // what it holds would only cost time.
        std::fflush(stderr);
        std::_Exit(0);
    } catch (const std::bad_alloc&) {
        exitOutOfMemory();
    } catch (const std::exception& error) {
        std::fprintf(stderr, "gyre-scene-worker: %s\n", error.what());
        return 1;
    }
}
