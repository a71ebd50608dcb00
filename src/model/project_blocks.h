#pragma once
// The binary blocks of a version 3 project file (docs/file-format.md): a track's keys and a mesh as
// little-endian arrays after the file's JSON header, which says how many items each block holds.
// project_file.cpp reads and writes the header; this reads and writes what follows it.
//
// Reading treats every byte as untrusted: a block's length comes from counts the header gave, which
// are checked against the key budget and against the bytes the file has left before anything is
// allocated; each value is checked as the JSON reader checks it (finite numbers, unit quaternions,
// increasing times, positions within the budget, flags 0 or 1), and a refusal names the field, as in
// `objects[2].keyframes[5].orientation: the quaternion is zero`.

#include "model/json_field.h"
#include "model/scene.h"

#include <QByteArray>
#include <QIODevice>

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace gyre::model {

// The most keys a project may hold, its tracks' keyframes and the keys they keep from before a fit
// together: 2^23, 8,388,608, a ten-minute take at 120 Hz of 116 joints. A key costs 104 bytes in
// memory, so the keys of a project stay under 873 MB, and up to 93 bytes on the way to gyre-scene-worker,
// so any project can be exported within the worker's message limit (io/scene_wire.h).
inline constexpr std::size_t kMaxProjectKeys = std::size_t{1} << 23;

// How a block stores a list of keys; the header gives it as the list's JSON member.
struct KeyLayout {
    std::size_t count = 0;
    std::size_t times = 0;                    // the index of the file's time list the keys use
    std::optional<Eigen::Vector3d> position;  // the position of every key, or none: listed
    std::optional<bool> constrained;          // the flag of every key, or none: listed
    bool eulerAngles = false;                 // the keys' stored angles follow (an Euler-mode track's)

    // The block: w, x, y, z per key as float64; then x, y, z per key as float64 unless the
    // position is the same for all; then one byte 0 or 1 per key unless the flag is; then, with
    // eulerAngles, e1, e2, e3 per key as float64 (radians, finite).
    qint64 blockBytes() const;
};

// The layout that stores `keys`, whose times are the file's list `times`.
KeyLayout keyLayoutOf(const std::vector<Keyframe>& keys, std::size_t times);
QByteArray keyBlock(const std::vector<Keyframe>& keys, const KeyLayout& layout);
// The keys of a block whose length blockBytes() gave, at `times` (already checked); `field` names
// the list in messages. Throws FieldError.
std::vector<Keyframe> keysFromBlock(const QByteArray& block, const KeyLayout& layout, const std::vector<double>& times,
                                    const JsonField& field);

// The times of `keys` as float64; read back, checked to lie within the time budget and increase.
QByteArray timeBlock(const std::vector<Keyframe>& keys);
std::vector<double> timesFromBlock(const QByteArray& block, const JsonField& field);

// An applied fit's Hermite control points: time, value w, x, y, z and derivative w, x, y, z, float64 each,
// kControlPointBytes a point; read back, checked as the JSON reader checks them (times within the
// budget and increasing, values and derivatives as controlValue and controlDerivative ask).
inline constexpr qint64 kControlPointBytes = 9 * sizeof(double);
QByteArray controlPointBlock(const std::vector<HermiteControlPoint>& points);
std::vector<HermiteControlPoint> controlPointsFromBlock(const QByteArray& block, const JsonField& field);

// A mesh: positions and normals as float32 x, y, z, then indices as uint32; for a skinned mesh then
// its joints' inverse bind matrices (16 float32 each, column-major), four joint indices per position
// as uint16, and four weights per position as float32. The header lists the skin's joints by id.
struct MeshCounts {
    std::size_t positions = 0;
    std::size_t normals = 0;
    std::size_t indices = 0;
    std::vector<ObjectId> skinJoints; // none: a rigid mesh
    qint64 blockBytes() const;
};
QByteArray meshBlock(const Mesh& mesh);
// Checked as every mesh is (checkMesh).
std::shared_ptr<const Mesh> meshFromBlock(const QByteArray& block, const MeshCounts& counts, const JsonField& field);

// Where a reader takes the blocks from, one after the other: a file, or the blocks a writer is
// about to write, which are read back before anything is written.
class BlockSource {
public:
    virtual ~BlockSource() = default;
    // The next `bytes` bytes; `field` names the block in a refusal.
    virtual QByteArray next(qint64 bytes, const JsonField& field) = 0;
};

// Blocks read from a device, `bytesLeft` of which may follow: the bytes the file has left where its
// size is known, else what is left of the project's size limit. A length beyond them is refused
// before any memory is taken for it, and a block is read in pieces, so a length a pipe does not
// deliver costs only the bytes that came.
class DeviceBlocks : public BlockSource {
public:
    DeviceBlocks(QIODevice& device, qint64 bytesLeft) : device_(device), left_(bytesLeft) {}
    QByteArray next(qint64 bytes, const JsonField& field) override;
    // Throws FieldError if the device holds more after the last block.
    void requireEnd();

private:
    QIODevice& device_;
    qint64 left_;
};

// Blocks made on demand, in order, by the writer's functions.
class WrittenBlocks : public BlockSource {
public:
    explicit WrittenBlocks(const std::vector<std::function<QByteArray()>>& blocks) : blocks_(blocks) {}
    QByteArray next(qint64 bytes, const JsonField& field) override;

private:
    const std::vector<std::function<QByteArray()>>& blocks_;
    std::size_t next_ = 0;
};

} // namespace gyre::model
