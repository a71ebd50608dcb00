#include "io/scene_import_settings.h"

#include "model/value_checks.h"

#include <assimp/anim.h>
#include <assimp/metadata.h>
#include <assimp/scene.h>

#include <QFile>
#include <QFileInfo>
#include <QXmlStreamReader>

#include <array>
#include <utility>
#include <cmath>
#include <cstring>
#include <string>

namespace gyre::io {

namespace {

// FBX time modes (FbxTime::EMode) and their frame rates; 0 is the application's default, 14 custom.
constexpr std::array<double, 19> kFbxTimeModeRates{0.0,  120.0, 100.0, 60.0, 50.0, 48.0, 30.0,
                                                   30.0, 30000.0 / 1001.0, 30000.0 / 1001.0, 25.0, 24.0, 1000.0,
                                                   24000.0 / 1001.0, 0.0, 96.0, 72.0, 60000.0 / 1001.0,
                                                   120000.0 / 1001.0};
constexpr int kFbxCustomTimeMode = 14;

// The rates tried for keys that come without one, lowest first, then the NTSC ones.
constexpr std::array<double, 14> kCommonRates{24.0,  25.0,  30.0,  48.0,  50.0, 60.0, 72.0, 96.0, 100.0, 120.0,
                                              240.0, 24000.0 / 1001.0, 30000.0 / 1001.0, 60000.0 / 1001.0};
// A key counts as on a frame within this fraction of a frame: far above float32 rounding of glTF's
// times (1e-7 relative) and Collada's six decimals, far below half a frame.
constexpr double kFrameTolerance = 0.005;
constexpr double kDefaultFps = 24.0;

std::optional<double> metadataNumber(const aiScene& scene, const char* key)
{
    const aiMetadata* metadata = scene.mMetaData;
    if (!metadata)
        return std::nullopt;
    for (unsigned i = 0; i < metadata->mNumProperties; ++i) {
        if (std::strcmp(metadata->mKeys[i].C_Str(), key) != 0)
            continue;
        const aiMetadataEntry& entry = metadata->mValues[i];
        switch (entry.mType) {
        case AI_INT32:
            return *static_cast<const int32_t*>(entry.mData);
        case AI_UINT64:
            return static_cast<double>(*static_cast<const uint64_t*>(entry.mData));
        case AI_FLOAT:
            return *static_cast<const float*>(entry.mData);
        case AI_DOUBLE:
            return *static_cast<const double*>(entry.mData);
        default:
            return std::nullopt;
        }
    }
    return std::nullopt;
}

QString metadataText(const aiScene& scene, const char* key)
{
    aiString text;
    if (scene.mMetaData && scene.mMetaData->Get(key, text))
        return QString::fromUtf8(text.C_Str());
    return {};
}

// Assimp's FBX writer (5.2) writes UnitScaleFactor 1 (centimetres) and the time mode of 24 fps whatever
// the scene it writes holds, Gyre's metres and frame rate among them: in its files they say nothing.
bool isWrittenByAssimp(const aiScene& scene)
{
    return metadataText(scene, "SourceAsset_Generator").startsWith(QLatin1String("Open Asset Import Library"));
}

bool isFrameRate(double fps) { return std::isfinite(fps) && fps > 0.0 && fps <= model::kMaxFps; }

// What a Collada file's <asset> says: its unit and its up axis ("Z_UP").
struct ColladaAsset {
    std::optional<double> metresPerUnit;
    QString upAxis;
};

ColladaAsset colladaAsset(const QString& path)
{
    ColladaAsset asset;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return asset;
    QXmlStreamReader xml(&file);
    // The root's <asset> comes first; stop at its end, or at the first element after it.
    int depth = 0;
    bool inAsset = false;
    while (!xml.atEnd()) {
        const QXmlStreamReader::TokenType token = xml.readNext();
        if (token == QXmlStreamReader::StartElement) {
            ++depth;
            if (depth == 2 && xml.name() == QLatin1String("asset"))
                inAsset = true;
            else if (depth == 2)
                break;
            else if (inAsset && depth == 3 && xml.name() == QLatin1String("unit")) {
                bool ok = false;
                const double metre = xml.attributes().value(QLatin1String("meter")).toDouble(&ok);
                if (ok && std::isfinite(metre) && metre > 0.0)
                    asset.metresPerUnit = metre;
            } else if (inAsset && depth == 3 && xml.name() == QLatin1String("up_axis")) {
                asset.upAxis = xml.readElementText().trimmed(); // reads up to its end element
                --depth;
            }
        } else if (token == QXmlStreamReader::EndElement) {
            if (inAsset && depth == 2)
                break;
            --depth;
        }
    }
    return asset;
}

// The lowest common rate on whose frames every key falls.
std::optional<double> rateOfKeys(const std::vector<const aiAnimation*>& animations)
{
    std::vector<double> times;
    for (const aiAnimation* animation : animations) {
        const double ticks = animation->mTicksPerSecond > 0.0 ? animation->mTicksPerSecond : kDefaultTicksPerSecond;
        for (unsigned c = 0; c < animation->mNumChannels; ++c) {
            const aiNodeAnim& channel = *animation->mChannels[c];
            for (unsigned k = 0; k < channel.mNumRotationKeys; ++k)
                times.push_back(channel.mRotationKeys[k].mTime / ticks);
            for (unsigned k = 0; k < channel.mNumPositionKeys; ++k)
                times.push_back(channel.mPositionKeys[k].mTime / ticks);
        }
    }
    if (times.empty())
        return std::nullopt;
    for (const double fps : kCommonRates) {
        bool onFrames = true;
        for (const double time : times) {
            const double frame = time * fps;
            if (!(std::abs(frame - std::round(frame)) <= kFrameTolerance)) {
                onFrames = false;
                break;
            }
        }
        if (onFrames)
            return fps;
    }
    return std::nullopt;
}

void readFrameRate(SceneSource source, const aiScene& scene, const std::vector<const aiAnimation*>& animations,
                   FileSettings& settings)
{
    if (source == SceneSource::Fbx && !isWrittenByAssimp(scene)) {
        if (const std::optional<double> mode = metadataNumber(scene, "FrameRate");
            mode && *mode >= 1 && *mode < static_cast<double>(kFbxTimeModeRates.size())) {
            const int index = static_cast<int>(*mode);
            const double fps = index == kFbxCustomTimeMode ? metadataNumber(scene, "CustomFrameRate").value_or(0.0)
                                                           : kFbxTimeModeRates[static_cast<std::size_t>(index)];
            if (isFrameRate(fps)) {
                settings.values.fps = fps;
                settings.fpsSource = FileError::tr("the FBX time mode");
                return;
            }
        }
    }
    if (source == SceneSource::Bvh && !animations.empty() && isFrameRate(animations.front()->mTicksPerSecond)) {
        settings.values.fps = animations.front()->mTicksPerSecond;
        settings.fpsSource = FileError::tr("the BVH frame time");
        return;
    }
    if (const std::optional<double> fps = rateOfKeys(animations)) {
        settings.values.fps = *fps;
        settings.fpsSource = FileError::tr("every key is on a frame of %1 fps").arg(FileError::number(*fps));
        return;
    }
    settings.values.fps = kDefaultFps;
    settings.fpsSource = animations.empty() ? FileError::tr("no animation; Gyre's default")
                                            : FileError::tr("the keys are on the frames of no common rate; Gyre's default");
}

void readUnit(const QString& path, SceneSource source, const aiScene& scene, FileSettings& settings)
{
    settings.values.metresPerUnit = 1.0;
    if (source == SceneSource::Fbx && isWrittenByAssimp(scene)) {
        settings.unitSource = FileError::tr("written by Assimp, whose FBX unit says nothing; metres assumed");
        return;
    }
    if (source == SceneSource::Fbx) {
        if (const std::optional<double> centimetres = metadataNumber(scene, "UnitScaleFactor");
            centimetres && std::isfinite(*centimetres) && *centimetres > 0.0) {
            settings.values.metresPerUnit = *centimetres / 100.0;
            settings.unitSource = FileError::tr("the FBX UnitScaleFactor, %1 cm").arg(FileError::number(*centimetres));
            return;
        }
        settings.unitSource = FileError::tr("FBX's default, 1 cm");
        settings.values.metresPerUnit = 0.01;
        return;
    }
    if (source == SceneSource::Collada) {
        if (const std::optional<double> metres = colladaMetresPerUnit(path)) {
            settings.values.metresPerUnit = *metres;
            settings.unitSource = FileError::tr("the Collada <unit>");
            return;
        }
        settings.unitSource = FileError::tr("Collada's default, 1 m");
        return;
    }
    settings.unitSource = source == SceneSource::Gltf ? FileError::tr("glTF is in metres")
                                                      : FileError::tr("the format has no unit; metres assumed");
}

// FBX numbers the axes X 0, Y 1, Z 2.
QString fbxAxisName(double axis)
{
    for (const auto& [number, name] : {std::pair{0.0, "X"}, std::pair{1.0, "Y"}, std::pair{2.0, "Z"}})
        if (axis == number)
            return QString::fromLatin1(name);
    return FileError::number(axis);
}

void readUpAxis(const QString& path, SceneSource source, const aiScene& scene, FileSettings& settings,
                QStringList& warnings)
{
    settings.values.up = UpAxis::Y;
    const auto unsupported = [&](const QString& axis) {
        warnings << FileError::tr("the file says its up axis is %1; Gyre converts Y-up and Z-up scenes only, so it is "
                                  "read as Y-up")
                        .arg(axis);
    };
    if (source == SceneSource::Fbx) {
        // Compared as read: a damaged file's number need not fit an int.
        const double axis = metadataNumber(scene, "UpAxis").value_or(1.0);
        const double sign = metadataNumber(scene, "UpAxisSign").value_or(1.0);
        settings.upSource = FileError::tr("the FBX UpAxis");
        if (sign == 1.0 && (axis == 1.0 || axis == 2.0))
            settings.values.up = axis == 2.0 ? UpAxis::Z : UpAxis::Y;
        else
            unsupported(QStringLiteral("%1%2").arg(sign < 0.0 ? "-" : "").arg(fbxAxisName(axis)));
        return;
    }
    if (source == SceneSource::Collada) {
        const QString axis = colladaAsset(path).upAxis;
        settings.upSource = FileError::tr("the Collada <up_axis>");
        if (axis == QLatin1String("Z_UP"))
            settings.values.up = UpAxis::Z;
        else if (axis.isEmpty())
            settings.upSource = FileError::tr("Collada's default, Y");
        else if (axis != QLatin1String("Y_UP"))
            unsupported(axis);
        return;
    }
    settings.upSource = source == SceneSource::Gltf ? FileError::tr("glTF is Y-up") : FileError::tr("Y-up assumed");
}

} // namespace

SceneSource sourceOf(const QString& path, const aiScene& scene)
{
    const QString format = metadataText(scene, "SourceAsset_Format");
    if (format.contains(QLatin1String("FBX")))
        return SceneSource::Fbx;
    if (format.contains(QLatin1String("Collada")))
        return SceneSource::Collada;
    if (format.contains(QLatin1String("glTF")))
        return SceneSource::Gltf;
    if (QFileInfo(path).suffix().compare(QLatin1String("bvh"), Qt::CaseInsensitive) == 0)
        return SceneSource::Bvh;
    return SceneSource::Other;
}

FileSettings fileSettingsOf(const QString& path, SceneSource source, const aiScene& scene,
                            const std::vector<const aiAnimation*>& animations, QStringList& warnings)
{
    FileSettings settings;
    readFrameRate(source, scene, animations, settings);
    readUnit(path, source, scene, settings);
    readUpAxis(path, source, scene, settings, warnings);
    return settings;
}

std::optional<double> colladaMetresPerUnit(const QString& path) { return colladaAsset(path).metresPerUnit; }

} // namespace gyre::io
