#pragma once
// The project file, `.gyre` (docs/file-format.md): the scene as JSON, with a `format` and a `version`.
// Meshes are stored in the file, each once however many objects share it. Numbers are written so
// that they read back as the same doubles.
//
// Reading checks everything (types, ranges, finite numbers, unit quaternions, increasing times,
// references between objects) and builds a fresh Scene, so a bad file changes nothing; its message
// names the file and the field, as in `scene.gyre: objects[2].keyframes[5].time: ...`.

#include "model/scene.h"

#include <QByteArray>
#include <QString>

namespace gyre::model {

inline constexpr char kProjectFormat[] = "gyre-project";
// The version this build writes. It reads it and every older one: version 1 has no sketch-editing
// state, which reads as empty.
inline constexpr int kProjectVersion = 2;
// Larger files are refused before they are read.
inline constexpr qint64 kMaxProjectBytes = qint64{1} << 30;

// The project as JSON text: the same bytes for the same scene, since members are written in sorted
// order. Saving writes these bytes; tests compare them.
QByteArray projectJson(const Scene& scene);

// The scene that project text holds. Throws InputError naming `path` and the field.
Scene parseProject(const QByteArray& json, const QString& path);

// Reads the project file at `path`. Throws InputError naming the file and the field.
Scene readProject(const QString& path);

// Writes the project file through an OutputTarget (model/output_target.h): on any error
// (OutputError) a regular file already at `path` keeps its contents and none is created; a FIFO or
// a device is written in place, and "-" is standard output. A scene that would not read back, such as one holding a
// number that is not finite, is refused rather than written.
void writeProject(const QString& path, const Scene& scene);

} // namespace gyre::model
