#include "model/project_blocks.h"

#include "model/input_error.h"
#include "model/value_checks.h"

#include <QtEndian>

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace gyre::model {

namespace {

constexpr qint64 kQuaternionBytes = 4 * sizeof(double);
constexpr qint64 kPositionBytes = 3 * sizeof(double);
constexpr qint64 kAngleBytes = 3 * sizeof(double);
constexpr qint64 kVectorBytes = 3 * sizeof(float);
constexpr std::size_t kMatrixBytes = 16 * sizeof(float);
constexpr std::size_t kSkinVertexBytes = 4 * sizeof(std::uint16_t) + 4 * sizeof(float);
// A block is read in pieces of at most this size, so that a length the device does not deliver
// costs at most one piece beyond the bytes that came.
constexpr qint64 kReadPieceBytes = qint64{1} << 20;

// Appends `count` values, little-endian, to `bytes`.
template <class Value>
void appendValues(QByteArray& bytes, const Value* values, std::size_t count)
{
    if (count == 0) // Qt copies with memcpy, which must not see the null pointer of an empty array
        return;
    const qsizetype start = bytes.size();
    bytes.resize(start + static_cast<qsizetype>(count * sizeof(Value)));
    qToLittleEndian<Value>(values, static_cast<qsizetype>(count), bytes.data() + start);
}

template <class Value>
void appendValue(QByteArray& bytes, Value value)
{
    appendValues(bytes, &value, 1);
}

double doubleAt(const char* bytes, std::size_t index) { return qFromLittleEndian<double>(bytes + index * sizeof(double)); }

// The field `path` of the key at `index` of the list `field`, as in `objects[2].keyframes[5].orientation`.
[[noreturn]] void failAtKey(const JsonField& field, std::size_t index, const char* member, const char* problem)
{
    JsonField(QJsonValue(), field.path() + QLatin1Char('[') + QString::number(index) + QStringLiteral("].") +
                                QLatin1String(member))
        .fail(QString::fromUtf8(problem));
}

std::vector<Eigen::Vector3f> vectorsAt(const char* bytes, std::size_t count)
{
    std::vector<Eigen::Vector3f> vectors(count);
    if (count > 0)
        qFromLittleEndian<float>(bytes, static_cast<qsizetype>(count * 3), vectors.front().data());
    return vectors;
}

} // namespace

qint64 KeyLayout::blockBytes() const
{
    const auto n = static_cast<qint64>(count);
    return n * kQuaternionBytes + (position ? 0 : n * kPositionBytes) + (constrained ? 0 : n) +
           (eulerAngles ? n * kAngleBytes : 0);
}

KeyLayout keyLayoutOf(const std::vector<Keyframe>& keys, std::size_t times)
{
    KeyLayout layout{keys.size(), times, std::nullopt, std::nullopt, false};
    if (keys.empty())
        return layout;
    const Keyframe& first = keys.front();
    // Every key of a track has angles or none has (rotation_mode.h).
    layout.eulerAngles = first.eulerAngles.has_value();
    if (std::all_of(keys.begin(), keys.end(), [&](const Keyframe& key) { return key.pose.position == first.pose.position; }))
        layout.position = first.pose.position;
    if (std::all_of(keys.begin(), keys.end(), [&](const Keyframe& key) { return key.constrained == first.constrained; }))
        layout.constrained = first.constrained;
    return layout;
}

QByteArray keyBlock(const std::vector<Keyframe>& keys, const KeyLayout& layout)
{
    QByteArray block;
    block.reserve(static_cast<qsizetype>(layout.blockBytes()));
    for (const Keyframe& key : keys) {
        const Eigen::Quaterniond& q = key.pose.orientation;
        const double wxyz[4] = {q.w(), q.x(), q.y(), q.z()};
        appendValues(block, wxyz, 4);
    }
    if (!layout.position)
        for (const Keyframe& key : keys)
            appendValues(block, key.pose.position.data(), 3);
    if (!layout.constrained)
        for (const Keyframe& key : keys)
            appendValue<quint8>(block, key.constrained ? 1 : 0);
    if (layout.eulerAngles)
        for (const Keyframe& key : keys)
            appendValues(block, key.eulerAngles.value_or(Eigen::Vector3d::Zero()).data(), 3);
    return block;
}

std::vector<Keyframe> keysFromBlock(const QByteArray& block, const KeyLayout& layout, const std::vector<double>& times,
                                    const JsonField& field)
{
    const char* orientations = block.constData();
    const char* positions = orientations + layout.count * kQuaternionBytes;
    const char* flags = positions + (layout.position ? 0 : layout.count * kPositionBytes);
    const char* angles = flags + (layout.constrained ? 0 : layout.count);
    std::vector<Keyframe> keys(layout.count);
    for (std::size_t k = 0; k < keys.size(); ++k) {
        Keyframe& key = keys[k];
        key.time = times[k];
        const char* q = orientations + k * kQuaternionBytes;
        try {
            key.pose.orientation = unitQuaternion({doubleAt(q, 0), doubleAt(q, 1), doubleAt(q, 2), doubleAt(q, 3)});
        } catch (const std::invalid_argument& problem) {
            failAtKey(field, k, "orientation", problem.what());
        }
        if (layout.position) {
            key.pose.position = *layout.position;
        } else {
            const char* p = positions + k * kPositionBytes;
            try {
                key.pose.position = positionValue({doubleAt(p, 0), doubleAt(p, 1), doubleAt(p, 2)});
            } catch (const std::invalid_argument& problem) {
                failAtKey(field, k, "position", problem.what());
            }
        }
        if (layout.constrained) {
            key.constrained = *layout.constrained;
        } else {
            const auto flag = static_cast<quint8>(flags[k]);
            if (flag > 1)
                failAtKey(field, k, "constrained",
                          FileError::tr("%1 is neither 0 nor 1").arg(flag).toUtf8().constData());
            key.constrained = flag == 1;
        }
        if (layout.eulerAngles) {
            const char* e = angles + k * kAngleBytes;
            key.eulerAngles = Eigen::Vector3d(doubleAt(e, 0), doubleAt(e, 1), doubleAt(e, 2));
            if (!key.eulerAngles->allFinite())
                failAtKey(field, k, "eulerAngles", FileError::tr("the angles are not finite").toUtf8().constData());
        }
    }
    return keys;
}

QByteArray timeBlock(const std::vector<Keyframe>& keys)
{
    QByteArray block;
    block.reserve(static_cast<qsizetype>(keys.size() * sizeof(double)));
    for (const Keyframe& key : keys)
        appendValue(block, key.time);
    return block;
}

std::vector<double> timesFromBlock(const QByteArray& block, const JsonField& field)
{
    std::vector<double> times(static_cast<std::size_t>(block.size()) / sizeof(double));
    for (std::size_t i = 0; i < times.size(); ++i) {
        times[i] = doubleAt(block.constData(), i);
        try {
            i == 0 ? timeValue(times[i]) : timeAfter(times[i], times[i - 1]);
        } catch (const std::invalid_argument& problem) {
            JsonField(QJsonValue(), field.path() + QLatin1Char('[') + QString::number(i) + QLatin1Char(']'))
                .fail(QString::fromUtf8(problem.what()));
        }
    }
    return times;
}

QByteArray controlPointBlock(const std::vector<HermiteControlPoint>& points)
{
    QByteArray block;
    block.reserve(static_cast<qsizetype>(points.size()) * kControlPointBytes);
    for (const HermiteControlPoint& point : points) {
        const Eigen::Quaterniond& v = point.value;
        const Eigen::Quaterniond& d = point.derivative;
        const double values[9] = {point.time, v.w(), v.x(), v.y(), v.z(), d.w(), d.x(), d.y(), d.z()};
        appendValues(block, values, 9);
    }
    return block;
}

std::vector<HermiteControlPoint> controlPointsFromBlock(const QByteArray& block, const JsonField& field)
{
    std::vector<HermiteControlPoint> points(static_cast<std::size_t>(block.size() / kControlPointBytes));
    for (std::size_t i = 0; i < points.size(); ++i) {
        const char* bytes = block.constData() + static_cast<qint64>(i) * kControlPointBytes;
        const auto quaternionAt = [bytes](std::size_t first) {
            return Eigen::Quaterniond(doubleAt(bytes, first), doubleAt(bytes, first + 1), doubleAt(bytes, first + 2),
                                      doubleAt(bytes, first + 3));
        };
        HermiteControlPoint& point = points[i];
        try {
            point.time = i == 0 ? timeValue(doubleAt(bytes, 0)) : timeAfter(doubleAt(bytes, 0), points[i - 1].time);
        } catch (const std::invalid_argument& problem) {
            failAtKey(field, i, "time", problem.what());
        }
        try {
            point.value = controlValue(quaternionAt(1));
        } catch (const std::invalid_argument& problem) {
            failAtKey(field, i, "value", problem.what());
        }
        try {
            point.derivative = controlDerivative(quaternionAt(5));
        } catch (const std::invalid_argument& problem) {
            failAtKey(field, i, "derivative", problem.what());
        }
    }
    return points;
}

qint64 MeshCounts::blockBytes() const
{
    const qint64 skinBytes = skinJoints.empty() ? 0
                                                : static_cast<qint64>(skinJoints.size() * kMatrixBytes + positions * kSkinVertexBytes);
    return static_cast<qint64>(positions + normals) * kVectorBytes + static_cast<qint64>(indices * sizeof(std::uint32_t)) +
           skinBytes;
}

QByteArray meshBlock(const Mesh& mesh)
{
    QByteArray block;
    appendValues(block, mesh.positions.empty() ? nullptr : mesh.positions.front().data(), mesh.positions.size() * 3);
    appendValues(block, mesh.normals.empty() ? nullptr : mesh.normals.front().data(), mesh.normals.size() * 3);
    appendValues(block, mesh.indices.data(), mesh.indices.size());
    const Skin& skin = mesh.skin;
    if (!skin.empty()) {
        appendValues(block, skin.inverseBinds.front().data(), skin.inverseBinds.size() * 16);
        appendValues(block, skin.vertexJoints.empty() ? nullptr : skin.vertexJoints.front().data(), skin.vertexJoints.size() * 4);
        appendValues(block, skin.vertexWeights.empty() ? nullptr : skin.vertexWeights.front().data(), skin.vertexWeights.size() * 4);
    }
    return block;
}

std::shared_ptr<const Mesh> meshFromBlock(const QByteArray& block, const MeshCounts& counts, const JsonField& field)
{
    auto mesh = std::make_shared<Mesh>();
    const char* bytes = block.constData();
    mesh->positions = vectorsAt(bytes, counts.positions);
    mesh->normals = vectorsAt(bytes + counts.positions * kVectorBytes, counts.normals);
    mesh->indices.resize(counts.indices);
    if (counts.indices > 0)
        qFromLittleEndian<std::uint32_t>(bytes + (counts.positions + counts.normals) * kVectorBytes,
                                         static_cast<qsizetype>(counts.indices), mesh->indices.data());
    if (!counts.skinJoints.empty()) {
        Skin& skin = mesh->skin;
        const char* at = bytes + (counts.positions + counts.normals) * kVectorBytes + counts.indices * sizeof(std::uint32_t);
        skin.joints = counts.skinJoints;
        skin.inverseBinds.resize(skin.joints.size());
        qFromLittleEndian<float>(at, static_cast<qsizetype>(skin.joints.size() * 16), skin.inverseBinds.front().data());
        at += skin.joints.size() * kMatrixBytes;
        skin.vertexJoints.resize(counts.positions);
        skin.vertexWeights.resize(counts.positions);
        if (counts.positions > 0) {
            qFromLittleEndian<std::uint16_t>(at, static_cast<qsizetype>(counts.positions * 4), skin.vertexJoints.front().data());
            at += counts.positions * 4 * sizeof(std::uint16_t);
            qFromLittleEndian<float>(at, static_cast<qsizetype>(counts.positions * 4), skin.vertexWeights.front().data());
        }
    }
    field.checked([&] { checkMesh(*mesh); });
    return mesh;
}

QByteArray DeviceBlocks::next(qint64 bytes, const JsonField& field)
{
    if (bytes > left_)
        field.fail(FileError::tr("its block needs %1 bytes; the file has %2 left").arg(bytes).arg(left_));
    QByteArray block;
    block.reserve(static_cast<qsizetype>(std::min(bytes, kReadPieceBytes)));
    while (block.size() < bytes) {
        const QByteArray piece = device_.read(std::min(bytes - block.size(), kReadPieceBytes));
        if (piece.isEmpty())
            field.fail(FileError::tr("the file ends %1 bytes into its block of %2").arg(block.size()).arg(bytes));
        block += piece;
    }
    left_ -= bytes;
    return block;
}

void DeviceBlocks::requireEnd()
{
    if (!device_.read(1).isEmpty())
        JsonField(QJsonValue(), QString()).fail(FileError::tr("the file goes on after its last block"));
}

QByteArray WrittenBlocks::next(qint64 bytes, const JsonField& field)
{
    if (next_ == blocks_.size())
        field.fail(FileError::tr("the writer has no block for it"));
    QByteArray block = blocks_[next_++]();
    if (block.size() != bytes)
        field.fail(FileError::tr("its block holds %1 bytes, not %2").arg(block.size()).arg(bytes));
    return block;
}

} // namespace gyre::model
