#include "io/gltf_animation.h"

#include "model/input_error.h"
#include "model/track_evaluation.h"

#include <tiny_gltf.h>

#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <map>
#include <set>

namespace gyre::io {

namespace {

// Refuses a file over kMaxGltfBufferBytes before reading it, then reads it as TinyGLTF would.
bool readWholeFileWithinBudget(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                               void* userData)
{
    const QFileInfo info(QFile::decodeName(path.c_str()));
    if (info.exists() && static_cast<std::size_t>(info.size()) > kMaxGltfBufferBytes) {
        if (err)
            *err += FileError::tr("%1 is %2 bytes, over the %3 bytes a glTF buffer may have")
                        .arg(info.fileName())
                        .arg(info.size())
                        .arg(kMaxGltfBufferBytes)
                        .toStdString();
        return false;
    }
    return tinygltf::ReadWholeFile(out, err, path, userData);
}

// Images are never decoded: Gyre keeps no materials.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*)
{
    return true;
}

class SamplerReader {
public:
    SamplerReader(const QString& path, const tinygltf::Model& model)
        : path_(path)
        , model_(model)
    {
    }

    [[noreturn]] void fail(const QString& field, const QString& problem) const
    {
        throw InputError(path_, QStringLiteral("%1: %2").arg(field, problem).toStdString());
    }

    // The accessor's floats, `components` per element, or nullopt for an accessor Gyre leaves to
    // Assimp (sparse, or not float). The budget and the bounds are checked before anything is read.
    std::optional<std::vector<float>> floats(int index, int components, const QString& field) const
    {
        if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size())
            fail(field, FileError::tr("there is no accessor %1").arg(index));
        const tinygltf::Accessor& accessor = model_.accessors[static_cast<std::size_t>(index)];
        const QString where = QStringLiteral("%1 (accessors[%2])").arg(field).arg(index);
        if (accessor.count > kMaxGltfAccessorCount)
            fail(where, FileError::tr("count %1 is over the %2 elements Gyre reads")
                            .arg(accessor.count)
                            .arg(kMaxGltfAccessorCount));
        if (accessor.sparse.isSparse || accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT ||
            tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type)) != components ||
            accessor.bufferView < 0)
            return std::nullopt;
        if (static_cast<std::size_t>(accessor.bufferView) >= model_.bufferViews.size())
            fail(where, FileError::tr("there is no buffer view %1").arg(accessor.bufferView));
        const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
        if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model_.buffers.size())
            fail(where, FileError::tr("its buffer view names no buffer"));
        const std::vector<unsigned char>& data = model_.buffers[static_cast<std::size_t>(view.buffer)].data;
        const std::size_t elementBytes = sizeof(float) * static_cast<std::size_t>(components);
        const std::size_t stride = view.byteStride == 0 ? elementBytes : view.byteStride;
        const std::size_t span = accessor.count == 0 ? 0 : stride * (accessor.count - 1) + elementBytes;
        if (stride < elementBytes || accessor.byteOffset > view.byteLength || span > view.byteLength - accessor.byteOffset)
            fail(where, FileError::tr("%1 elements from byte %2 run past its buffer view's %3 bytes")
                            .arg(accessor.count)
                            .arg(accessor.byteOffset)
                            .arg(view.byteLength));
        if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
            fail(where, FileError::tr("its buffer view runs past the buffer's %1 bytes").arg(data.size()));
        std::vector<float> result(accessor.count * static_cast<std::size_t>(components));
        const unsigned char* first = data.data() + view.byteOffset + accessor.byteOffset;
        for (std::size_t i = 0; i < accessor.count; ++i)
            std::memcpy(result.data() + i * static_cast<std::size_t>(components), first + i * stride, elementBytes);
        return result;
    }

    std::optional<GltfSampler> sampler(std::size_t animation, int index, bool rotation) const
    {
        const tinygltf::Animation& source = model_.animations[animation];
        const QString field = QStringLiteral("animations[%1].samplers[%2]").arg(animation).arg(index);
        if (index < 0 || static_cast<std::size_t>(index) >= source.samplers.size())
            fail(field, FileError::tr("there is no such sampler"));
        const tinygltf::AnimationSampler& sampler = source.samplers[static_cast<std::size_t>(index)];
        GltfSampler result;
        if (sampler.interpolation == "STEP")
            result.interpolation = GltfInterpolation::Step;
        else if (sampler.interpolation == "CUBICSPLINE")
            result.interpolation = GltfInterpolation::CubicSpline;
        else if (sampler.interpolation.empty() || sampler.interpolation == "LINEAR")
            result.interpolation = GltfInterpolation::Linear;
        else
            fail(field + QStringLiteral(".interpolation"),
                 FileError::tr("'%1' is not an interpolation").arg(QString::fromStdString(sampler.interpolation)));
        const auto times = floats(sampler.input, 1, field + QStringLiteral(".input"));
        const int components = rotation ? 4 : 3;
        const auto values = floats(sampler.output, components, field + QStringLiteral(".output"));
        if (!times || !values)
            return std::nullopt;
        const std::size_t count = times->size();
        const std::size_t perKey = result.interpolation == GltfInterpolation::CubicSpline ? 3 : 1;
        if (count == 0 || values->size() != count * perKey * static_cast<std::size_t>(components))
            fail(field, FileError::tr("%1 times need %2 output elements; the output has %3")
                            .arg(count)
                            .arg(count * perKey)
                            .arg(values->size() / static_cast<std::size_t>(components)));
        for (std::size_t k = 0; k < count; ++k) {
            const double time = (*times)[k];
            if (!std::isfinite(time) || (k > 0 && !(time > result.times.back())))
                fail(field + QStringLiteral(".input"),
                     FileError::tr("time %1 is not finite or not after the one before it").arg(k));
            result.times.push_back(time);
        }
        const auto element = [&](std::size_t i) {
            Eigen::Vector4d v = Eigen::Vector4d::Zero();
            for (int c = 0; c < components; ++c)
                v[c] = (*values)[i * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)];
            if (!v.allFinite())
                fail(field + QStringLiteral(".output"), FileError::tr("element %1 is not finite").arg(i));
            return v;
        };
        for (std::size_t k = 0; k < count; ++k) {
            const std::size_t at = k * perKey;
            if (perKey == 3) {
                result.inTangents.push_back(element(at));
                result.outTangents.push_back(element(at + 2));
            }
            result.values.push_back(element(at + perKey / 2));
            if (rotation && result.values.back().squaredNorm() == 0.0)
                fail(field + QStringLiteral(".output"), FileError::tr("rotation %1 is a zero quaternion").arg(k));
        }
        return result;
    }

private:
    const QString& path_;
    const tinygltf::Model& model_;
};

// Node names as Assimp 5.2 gives them, each with its index; a name two nodes share maps to none.
std::map<int, std::string> uniqueNodeNames(const tinygltf::Model& model)
{
    std::map<std::string, int> uses;
    std::map<int, std::string> names;
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        const std::string name = model.nodes[i].name.empty() ? "nodes[" + std::to_string(i) + "]" : model.nodes[i].name;
        names.emplace(static_cast<int>(i), name);
        ++uses[name];
    }
    std::erase_if(names, [&uses](const auto& entry) { return uses[entry.second] > 1; });
    return names;
}

Eigen::Vector4d slerpShortArc(const Eigen::Vector4d& a, const Eigen::Vector4d& b, double u)
{
    const Eigen::Quaterniond qa(a[3], a[0], a[1], a[2]);
    const Eigen::Quaterniond qb(b[3], b[0], b[1], b[2]);
    const Eigen::Quaterniond q = qa.normalized().slerp(u, qb.normalized()); // Eigen takes the short arc
    return {q.x(), q.y(), q.z(), q.w()};
}

} // namespace

Eigen::Vector4d GltfSampler::at(double time) const
{
    if (time <= times.front())
        return values.front();
    if (time >= times.back())
        return values.back();
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), time) - times.begin()) - 1;
    const double duration = times[k + 1] - times[k];
    const double s = (time - times[k]) / duration;
    switch (interpolation) {
    case GltfInterpolation::Step:
        return values[k];
    case GltfInterpolation::Linear:
        return values[k] + s * (values[k + 1] - values[k]);
    case GltfInterpolation::CubicSpline:
        break;
    }
    const double s2 = s * s;
    const double s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * values[k] + duration * (s3 - 2 * s2 + s) * outTangents[k] +
           (-2 * s3 + 3 * s2) * values[k + 1] + duration * (s3 - s2) * inTangents[k + 1];
}

GltfAnimations readGltfAnimations(const QString& path)
{
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&tinygltf::FileExists, &tinygltf::ExpandFilePath, &readWholeFileWithinBudget,
                           &tinygltf::WriteWholeFile, nullptr});
    loader.SetImageLoader(&skipImage, nullptr);
    tinygltf::Model model;
    std::string error;
    std::string warning;
    const std::string file = QFile::encodeName(path).toStdString();
    const bool binary = QFileInfo(path).suffix().compare(QStringLiteral("glb"), Qt::CaseInsensitive) == 0;
    const bool read = binary ? loader.LoadBinaryFromFile(&model, &error, &warning, file)
                             : loader.LoadASCIIFromFile(&model, &error, &warning, file);
    if (!read)
        throw InputError(path, FileError::tr("not a glTF file Gyre can read: %1")
                                   .arg(QString::fromStdString(error).trimmed())
                                   .toStdString());
    const SamplerReader reader(path, model);
    const std::map<int, std::string> names = uniqueNodeNames(model);
    GltfAnimations result(model.animations.size());
    for (std::size_t a = 0; a < model.animations.size(); ++a) {
        for (const tinygltf::AnimationChannel& channel : model.animations[a].channels) {
            const bool rotation = channel.target_path == "rotation";
            if (!rotation && channel.target_path != "translation")
                continue; // scale is Assimp's; weights are not imported
            const auto name = names.find(channel.target_node);
            if (name == names.end())
                continue;
            std::optional<GltfSampler> sampler = reader.sampler(a, channel.sampler, rotation);
            if (!sampler)
                continue;
            GltfNodeMotion& motion = result[a][name->second];
            (rotation ? motion.rotation : motion.translation) = std::move(sampler);
        }
    }
    return result;
}

namespace {

Eigen::Quaterniond quaternionOf(const Eigen::Vector4d& xyzw) { return {xyzw[3], xyzw[0], xyzw[1], xyzw[2]}; }

// The value of a rotation sampler at `time`: LINEAR takes the short arc, every kind is normalised.
Eigen::Quaterniond rotationAt(const GltfSampler& sampler, double time)
{
    if (sampler.interpolation == GltfInterpolation::Linear && time > sampler.times.front() && time < sampler.times.back()) {
        const auto next = std::upper_bound(sampler.times.begin(), sampler.times.end(), time);
        const std::size_t k = static_cast<std::size_t>(next - sampler.times.begin()) - 1;
        const double u = (time - sampler.times[k]) / (sampler.times[k + 1] - sampler.times[k]);
        return quaternionOf(slerpShortArc(sampler.values[k], sampler.values[k + 1], u)).normalized();
    }
    return quaternionOf(sampler.at(time)).normalized();
}

// Whether the in- and out-tangents agree at every inner key, to float32 rounding.
bool hasNoCorners(const GltfSampler& sampler)
{
    for (std::size_t k = 1; k + 1 < sampler.times.size(); ++k)
        if ((sampler.inTangents[k] - sampler.outTangents[k]).norm() > 1e-6 * std::max(1.0, sampler.outTangents[k].norm()))
            return false;
    return true;
}

// Whether every value and tangent is the first value: then every interpolation plays it exactly.
bool isConstant(const GltfSampler& sampler)
{
    const auto same = [&sampler](const Eigen::Vector4d& v) { return v == sampler.values.front(); };
    const auto zero = [](const Eigen::Vector4d& v) { return v.isZero(); };
    return std::ranges::all_of(sampler.values, same) && std::ranges::all_of(sampler.inTangents, zero) &&
           std::ranges::all_of(sampler.outTangents, zero);
}

class KeyTimes {
public:
    KeyTimes(double fps, const QString& path, const QString& node)
        : fps_(fps)
        , path_(path)
        , node_(node)
    {
    }

    // The sampler's own key times.
    void addKeys(const GltfSampler& sampler)
    {
        makeRoom(static_cast<double>(sampler.times.size()));
        times_.insert(sampler.times.begin(), sampler.times.end());
    }

    // Every frame k/fps inside the sampler's span but those the file's float32 times already hold: a
    // frame that rounds to the same float32 as one of the sampler's keys is that key (Gyre's own exports
    // key every frame), not another a float32 step away.
    void addFrames(const GltfSampler& sampler)
    {
        const double first = std::ceil(sampler.times.front() * fps_);
        const double last = std::floor(sampler.times.back() * fps_);
        makeRoom(last - first + 1.0);
        for (double frame = first; frame <= last; ++frame) {
            const double time = frame / fps_;
            const auto after = std::ranges::lower_bound(sampler.times, time);
            const auto sameFloat = [time](double key) { return static_cast<float>(key) == static_cast<float>(time); };
            if ((after != sampler.times.end() && sameFloat(*after)) ||
                (after != sampler.times.begin() && sameFloat(*std::prev(after))))
                continue;
            times_.insert(time);
        }
    }

    // A STEP sampler's hold keys: key k's value at the frame before key k+1.
    void addHolds(const GltfSampler& sampler)
    {
        makeRoom(static_cast<double>(sampler.times.size()));
        for (std::size_t k = 0; k + 1 < sampler.times.size(); ++k)
            if (const double hold = sampler.times[k + 1] - 1.0 / fps_; hold > sampler.times[k] + model::kKeyMergeSeconds)
                times_.insert(hold);
    }

    // Increasing, times closer than kKeyMergeSeconds merged into the first.
    std::vector<double> merged() const
    {
        std::vector<double> result;
        for (const double time : times_)
            if (result.empty() || time - result.back() > model::kKeyMergeSeconds)
                result.push_back(time);
        return result;
    }

private:
    // Refuses, before they are added, `more` times that could take the track past kMaxGltfTrackKeys.
    void makeRoom(double more) const
    {
        if (static_cast<double>(times_.size()) + more > static_cast<double>(kMaxGltfTrackKeys))
            throw InputError(path_, FileError::tr("node '%1': its motion at %2 fps needs more than %3 keys")
                                        .arg(node_, FileError::number(fps_))
                                        .arg(kMaxGltfTrackKeys)
                                        .toStdString());
    }

    std::set<double> times_;
    double fps_;
    const QString& path_;
    const QString& node_;
};

} // namespace

model::MotionTrack gltfTrack(const GltfNodeMotion& motion, const Pose& nodePose, double positionScale, double fps,
                             const QString& path, const QString& nodeName)
{
    const std::optional<GltfSampler>& rotation = motion.rotation;
    const std::optional<GltfSampler>& translation = motion.translation;
    model::MotionTrack track;
    track.interpolation = InterpolationMethod::Slerp;
    const bool cubicRotation = rotation && rotation->interpolation == GltfInterpolation::CubicSpline;
    if (cubicRotation && rotation->times.size() > 1 && hasNoCorners(*rotation)) {
        track.interpolation = InterpolationMethod::Hermite;
        for (std::size_t k = 0; k < rotation->times.size(); ++k) {
            const bool last = k + 1 == rotation->times.size();
            track.sketch.fittedCurve.push_back({rotation->times[k], quaternionOf(rotation->values[k]),
                                                quaternionOf(last ? rotation->inTangents[k] : rotation->outTangents[k])});
        }
    }
    // One key beside several is a constant (Blender's glTF exporter writes an unchanging translation as
    // one key at time 0): it gives its value at the other's times and adds no time of its own.
    const std::size_t rotations = rotation ? rotation->times.size() : 0;
    const std::size_t translations = translation ? translation->times.size() : 0;
    KeyTimes times(fps, path, nodeName);
    if (rotation && !(rotations == 1 && translations > 1)) {
        times.addKeys(*rotation);
        if (rotation->interpolation == GltfInterpolation::Step)
            times.addHolds(*rotation);
        else if (cubicRotation && track.sketch.fittedCurve.empty())
            times.addFrames(*rotation);
    }
    if (translation && !(translations == 1 && rotations > 1)) {
        times.addKeys(*translation);
        if (translation->interpolation == GltfInterpolation::Step && track.interpolation == InterpolationMethod::Slerp)
            times.addHolds(*translation);
        else if (!isConstant(*translation) && (translation->interpolation == GltfInterpolation::CubicSpline ||
                                               track.interpolation == InterpolationMethod::Hermite))
            times.addFrames(*translation);
    }
    const std::optional<HermiteQuaternionSpline> spline =
        track.sketch.fittedCurve.empty() ? std::nullopt : std::optional(HermiteQuaternionSpline(track.sketch.fittedCurve));
    std::vector<model::Keyframe> keys;
    for (const double time : times.merged()) {
        Pose pose = nodePose;
        if (spline)
            pose.orientation = spline->sample(time).value;
        else if (rotation)
            pose.orientation = rotationAt(*rotation, time);
        if (translation)
            pose.position = translation->at(time).head<3>();
        pose.position *= positionScale;
        keys.push_back({time, pose, true});
    }
    track.keys = std::move(keys);
    return track;
}

} // namespace gyre::io
