#pragma once
// The messages between Gyre and gyre-scene-worker, the program that runs Assimp in a process of its
// own (scene_worker.h). A message is binary: the magic "GYSW", the wire version, its kind, then its
// contents, little-endian. Arrays of numbers travel as whole blocks, so that a mocap of 140,000 keys
// costs one copy each way rather than a call per number.
//
// The worker parses untrusted files with a library that can crash or be subverted, so the parent
// reads its replies as untrusted too: every count is checked against the bytes that are left before
// anything is allocated, and the scene is checked as the project reader checks it (finite numbers,
// unit quaternions, increasing times, meshes whose indices name positions, unique ids, parents before
// children). A reply that fails a check throws WireError.

#include "io/scene_export.h"
#include "io/scene_import.h"

#include <QByteArray>
#include <QString>

#include <stdexcept>
#include <variant>

namespace gyre::io::wire {

inline constexpr quint32 kMagic = 0x57535947; // "GYSW" read as little-endian bytes
// 2: import options (takes, frame rate, unit, up axis, time origin); the takes, settings and time shift
// of an import. 3: each mesh's skin. 4: each object's typed mass properties. 5: each track's rotation mode
// and its keys' Euler angles. 6: the scene's gravity. 7: each object's Empty flag.
inline constexpr quint16 kVersion = 7;

// The largest request or reply either side accepts: more is not a scene Gyre could hold.
inline constexpr qint64 kMaxMessageBytes = qint64{1} << 30;

// A message that is not what the wire format allows.
class WireError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// `locale` names the translation the worker's messages use (QLocale::name()); empty for English.
struct ImportRequest {
    QString path;
    QString locale;
    ImportOptions options;
};

struct ExportRequest {
    QString path;
    QString locale;
    SceneFormat format = SceneFormat::Glb;
    double fps = 24.0;
    model::Scene scene;
};

// What the worker says when the file itself is at fault: the message of the InputError or OutputError
// it caught, which starts with the file's path.
struct Failure {
    enum class Kind : quint8 { Input = 1, Output = 2 };
    Kind kind = Kind::Input;
    QString message;
};

using Request = std::variant<ImportRequest, ExportRequest>;
using Reply = std::variant<SceneImport, ExportReport, Failure>;

QByteArray encodeRequest(const Request& request);
Request decodeRequest(const QByteArray& bytes);

QByteArray encodeReply(const Reply& reply);
Reply decodeReply(const QByteArray& bytes);

} // namespace gyre::io::wire
