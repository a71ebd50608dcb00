// gyre-scene-worker: reads one request on standard input, imports or exports a scene with Assimp, and
// writes one reply on standard output (io/scene_wire.h). Gyre and gyre-cli start it for every scene
// file (io/scene_worker.h), so that whatever Assimp does with a damaged file (crash, abort, endless
// allocation) ends this process and not theirs. It takes no arguments and is not meant to be run by
// hand.
//
// Exit status: 0 with a reply written (the reply may be the file's error); kWorkerOutOfMemoryStatus
// when an allocation failed under the memory limit its parent set; 1 when the request could not be
// read or the reply could not be written.

#include "io/scene_wire.h"
#include "io/scene_worker.h"

#include <QCoreApplication>
#include <QLocale>
#include <QTranslator>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <variant>

namespace {

using namespace gyre;

// Any allocation that fails, in Gyre or in Assimp (whose readers catch std::bad_alloc and report it
// as a read error), ends the worker at once with the status that tells the parent why.
[[noreturn]] void exitOutOfMemory() { _exit(kWorkerOutOfMemoryStatus); }

QByteArray readAll(int fd)
{
    QByteArray bytes;
    char buffer[1 << 16];
    while (true) {
        const ssize_t n = read(fd, buffer, sizeof buffer);
        if (n == 0)
            return bytes;
        if (n < 0)
            throw std::runtime_error(std::string("cannot read the request: ") + std::strerror(errno));
        bytes.append(buffer, n);
    }
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

// Gyre's translation for the locale the request names, as the app installs it (app/language.cpp).
void installTranslation(const QString& locale, QTranslator& translator)
{
    if (!locale.isEmpty() && translator.load(QLocale(locale), QStringLiteral("gyre"), QStringLiteral("_"),
                                             QStringLiteral(":/i18n")))
        QCoreApplication::installTranslator(&translator);
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
        const wire::Request request = wire::decodeRequest(readAll(STDIN_FILENO));
        QTranslator translator;
        installTranslation(std::visit([](const auto& job) { return job.locale; }, request), translator);
        writeAll(replyFd, wire::encodeReply(answer(request)));
        // The process is done: freeing what the import holds (tens of megabytes of keys and Assimp's
        // scene) would only cost time.
        std::fflush(stderr);
        std::_Exit(0);
    } catch (const std::bad_alloc&) {
        exitOutOfMemory();
    } catch (const std::exception& error) {
        std::fprintf(stderr, "gyre-scene-worker: %s\n", error.what());
        return 1;
    }
}
