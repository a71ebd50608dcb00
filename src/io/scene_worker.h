#pragma once
// Scene import and export in a process of their own. Assimp can crash, abort or allocate without bound
// on a damaged file; run in gyre-scene-worker (src/worker), that costs an error naming the file
// instead of the program. The worker gets requests on standard input and writes a reply to each on
// standard output (scene_wire.h); this side limits its memory and its time, and reads the replies as
// untrusted input. One worker is kept between requests, so that only the first pays for starting a
// process and the next ones run on its warm heap; any failure but the file's own error replaces it
// (worker_process.h).
//
// These functions block until the worker answers, one call at a time; the app calls them on its thread
// pool (jobs), gyre-cli directly. Their results and errors are those of importScene and exportScene, plus these, each an
// InputError (import) or OutputError (export) naming the file:
//   "<file>: the scene reader crashed (signal 11, SIGSEGV) …"
//   "<file>: the scene reader needed more than 2 GiB of memory …"
//   "<file>: the scene reader took longer than 120 s …"
//   "<file>: the scene reader's reply is malformed: …"
//   "<file>: the scene reader gyre-scene-worker cannot be started: …"

#include "io/scene_export.h"
#include "io/scene_import.h"

#include <QLocale>
#include <QString>

#include <atomic>
#include <chrono>

namespace gyre::io {

inline constexpr char kSceneWorkerName[] = "gyre-scene-worker";
// Names the worker program to run instead of the one found beside the running program.
inline constexpr char kSceneWorkerVariable[] = "GYRE_SCENE_WORKER";
// The worker's exit status when an allocation failed: the memory limit was reached.
inline constexpr int kWorkerOutOfMemoryStatus = 3;

struct SceneWorkerLimits {
    // The worker's address space (RLIMIT_AS): Assimp's readers trust sizes written in the file, and a
    // 14 KB Collada file can ask for 7 GB. 2 GiB holds every scene Gyre can show smoothly.
    qint64 memoryBytes = qint64{2} << 30;
    // Killed after this long, hung or not: Assimp's readers have had endless loops on damaged files.
    std::chrono::milliseconds time = std::chrono::minutes(2);
};

// The language of the worker's messages: Gyre's translation for `locale`, as the app installs it
// (app/language.h); English for the C locale, which is the default, or a locale Gyre has no
// translation for. Applies to the imports and exports started from then on, from any thread.
void setSceneWorkerLocale(const QLocale& locale);

// The worker program: $GYRE_SCENE_WORKER when set; else gyre-scene-worker beside the running program
// (the installed package, /usr/bin), else in the build tree's src/worker beside src/app and src/cli.
// Empty when none of them exists.
QString sceneWorkerProgram();

// importScene(path, options) in the worker. Setting `cancel` kills the worker and throws
// SceneWorkerCancelled. A worker that has already answered and runs out of memory gets the file once
// more in a fresh one before the memory message: its limit counts heap left from earlier files.
SceneImport importSceneInWorker(const QString& path, const ImportOptions& options = {},
                                const SceneWorkerLimits& limits = {}, const std::atomic_bool* cancel = nullptr);

// exportScene(scene, path, format, fps) in the worker.
ExportReport exportSceneInWorker(const model::Scene& scene, const QString& path, SceneFormat format, double fps,
                                 const SceneWorkerLimits& limits = {});

class SceneWorkerCancelled : public std::exception {
public:
    const char* what() const noexcept override { return "cancelled"; }
};

} // namespace gyre::io
