#pragma once
// Test programs live in build/tests/<layer>, where Gyre's lookup of gyre-scene-worker beside the
// running program (io/scene_worker.h) finds nothing: they name the worker just built through
// GYRE_SCENE_WORKER, unless whoever runs them has set it. CMake gives the path
// (gyre_use_built_scene_worker in tests/CMakeLists.txt).

#include "io/scene_worker.h"

#include <QtGlobal>

namespace gyre::test {

inline void useBuiltSceneWorker()
{
    if (!qEnvironmentVariableIsSet(io::kSceneWorkerVariable))
        qputenv(io::kSceneWorkerVariable, GYRE_SCENE_WORKER_PATH);
}

} // namespace gyre::test
