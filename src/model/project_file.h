#pragma once
// The project file, `.gyre` (docs/file-format.md). Version 3, which Gyre writes, starts with the
// format's name and version, then a JSON header (the scene's settings, its objects, their sketches)
// and binary blocks after it: each track's keys, each mesh once however many objects share it, each
// distinct list of key times once however many tracks share it. Versions 1 and 2 are JSON text.
// Numbers read back as the same doubles. Reading and writing go block by block: no JSON of the keys
// is ever built.
//
// Reading checks everything (types, ranges, finite numbers, unit quaternions, increasing times,
// references between objects) and builds a fresh Scene, so a bad file changes nothing; its message
// names the file and the field, as in `scene.gyre: objects[2].keyframes[5].time: ...`.

#include "model/scene.h"

#include "model/json_field.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>

namespace gyre::model {

inline constexpr char kProjectFormat[] = "gyre-project";
// The version this build writes. It reads it and every older one: version 1 has no sketch-editing
// state, which reads as empty; version 2 is JSON text.
inline constexpr int kProjectVersion = 3;
// Larger files are refused before they are read. At 32 to 65 bytes a key, a version 3 file this
// size would hold more keys than a project may (kMaxProjectKeys, model/project_blocks.h).
inline constexpr qint64 kMaxProjectBytes = qint64{1} << 30;

// One keyframe as version 2 writes it in JSON text, `{"time", "orientation": [w, x, y, z], "position",
// "constrained"}`, and read back, checked as a file's are (throws FieldError). The clipboard carries
// keys in this form (key_clipboard.h).
QJsonObject keyframeJson(const Keyframe& key);
Keyframe keyframeFromJson(const JsonField& field);

// The project file's bytes: the same bytes for the same scene, since the header's members are
// written in sorted order. Saving writes these bytes; tests compare them.
QByteArray projectBytes(const Scene& scene);

// The scene that a project file's bytes hold, in any version. Throws InputError naming `path` and
// the field.
Scene parseProject(const QByteArray& bytes, const QString& path);

// Reads the project file at `path`. Throws InputError naming the file and the field.
Scene readProject(const QString& path);

// Writes the project file, version 3, through an OutputTarget (model/output_target.h): on any error
// (OutputError) a regular file already at `path` keeps its contents and none is created; a FIFO or
// a device is written in place, and "-" is standard output. A scene that would not read back, such as one holding a
// number that is not finite, is refused rather than written: its blocks are read back and checked,
// one at a time, before any is written.
void writeProject(const QString& path, const Scene& scene);

} // namespace gyre::model
