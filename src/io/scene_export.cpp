#include "io/scene_export.h"

#include "io/assimp_math.h"
#include "io/baked_scene.h"
#include "io/fbx_scene_writer.h"
#include "io/gltf_scene_writer.h"
#include "io/up_axis.h"
#include "core/number_text.h"
#include "model/output_target.h"
#include "model/track_evaluation.h"

#include <assimp/BlobIOSystem.h>
#include <assimp/Exporter.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>

#include <QFile>
#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace gyre::io {

namespace {

using assimp_math::toAssimp;

const char* assimpFormatId(SceneFormat format)
{
    switch (format) {
    case SceneFormat::Collada:
        return "collada";
    case SceneFormat::Obj:
        return "obj";
    case SceneFormat::Gltf: // written by TinyGLTF, and FBX by Gyre itself: see scene_export.h
    case SceneFormat::Glb:
    case SceneFormat::Fbx:
        break;
    }
    return "";
}

// Assimp's Collada writer of 5.2 writes key times as seconds whatever mTicksPerSecond says: one tick
// per second says the same.
constexpr double kTicksPerSecond = 1.0;

const char* const kRootName = "GyreScene";

template <class T>
T* newArray(std::size_t count)
{
    return count == 0 ? nullptr : new T[count];
}

// Node names unique within the file, since animation channels find their nodes by name. A NUL
// character, which ends a name in Assimp's strings and separates name from class in FBX, becomes '_'.
class NodeNames {
public:
    NodeNames() { used_.insert(kRootName); }

    std::string unique(const model::SceneObject& object, QStringList& warnings)
    {
        std::string wanted =
            object.name.isEmpty() ? "object_" + std::to_string(object.id) : object.name.toStdString();
        std::ranges::replace(wanted, '\0', '_');
        std::string name = wanted;
        for (int n = 2; !used_.insert(name).second; ++n)
            name = wanted + '_' + std::to_string(n);
        if (name != object.name.toStdString())
            warnings << gyre::FileError::tr("object %1 '%2' is written as '%3' so that its name is unique")
                            .arg(object.id)
                            .arg(object.name, QString::fromStdString(name));
        return name;
    }

private:
    std::set<std::string> used_;
};

bool hasTriangles(const model::SceneObject& object) { return object.mesh && !object.mesh->indices.empty(); }

bool isAnimated(const model::MotionTrack& track) { return track.keys.size() > 1 || !track.sketch.fittedCurve.empty(); }

// Names, parents, start poses, checked meshes and baked motion of every object (baked_scene.h).
class SceneBaker {
public:
    SceneBaker(const model::Scene& scene, const QString& path, double fps, ExportReport& report)
        : scene_(scene)
        , path_(path)
        , report_(report)
    {
        result_.range = {scene.startTime, scene.endTime, fps};
    }

    BakedScene bake(bool withMotion)
    {
        std::unordered_map<model::ObjectId, std::size_t> indexOfId;
        for (const model::SceneObject& object : scene_.objects) {
            BakedObject baked;
            baked.name = names_.unique(object, report_.warnings);
            baked.parent = parentIndex(object, indexOfId);
            baked.startPose = startPose(object);
            baked.empty = object.empty;
            if (hasTriangles(object))
                baked.mesh = &checkedMesh(*object.mesh, object.name);
            if (withMotion && isAnimated(object.track)) {
                baked.samples = bakeTrack(object);
                std::vector<double> times;
                for (const model::TimedPose& sample : baked.samples)
                    times.push_back(sample.time);
                baked.rotationSpline = rotationSplineOf(object.track, times);
                baked.positionSpline = positionSplineOf(object.track, times);
            }
            indexOfId.emplace(object.id, result_.objects.size());
            result_.objects.push_back(std::move(baked));
        }
        for (std::size_t i = 0; i < result_.objects.size(); ++i)
            if (result_.objects[i].mesh)
                result_.objects[i].skinJoints = skinJoints(scene_.objects[i], indexOfId);
        return std::move(result_);
    }

private:
    // The parent's index, or none for a top-level object or a parent that does not come before it.
    std::optional<std::size_t> parentIndex(const model::SceneObject& object,
                                           const std::unordered_map<model::ObjectId, std::size_t>& indexOfId)
    {
        if (object.parent == model::kNoObject)
            return std::nullopt;
        if (const auto found = indexOfId.find(object.parent); found != indexOfId.end())
            return found->second;
        report_.warnings << FileError::tr("object %1 names parent %2, which does not come before it; "
                                          "it is written at the top level")
                                .arg(object.id)
                                .arg(object.parent);
        return std::nullopt;
    }

    // The index of each joint of the object's skin, the joints coming anywhere in the scene; none for a
    // rigid mesh, or with a warning for a skin whose joint is no object.
    std::vector<std::size_t> skinJoints(const model::SceneObject& object,
                                        const std::unordered_map<model::ObjectId, std::size_t>& indexOfId)
    {
        std::vector<std::size_t> joints;
        for (const model::ObjectId joint : object.mesh->skin.joints) {
            const auto found = indexOfId.find(joint);
            if (found == indexOfId.end()) {
                report_.warnings << FileError::tr("the skin of '%1' names object %2, which the scene does not hold; "
                                                  "its mesh is written rigid")
                                        .arg(object.name)
                                        .arg(joint);
                return {};
            }
            joints.push_back(found->second);
        }
        return joints;
    }

    Pose startPose(const model::SceneObject& object) const
    {
        try {
            const model::TrackMotion motion(object.track, model::flightBodyOf(object), scene_.gravity);
            return model::unitSample(motion.at(scene_.startTime), scene_.startTime);
        } catch (const std::invalid_argument& error) {
            throw OutputError(path_, FileError::tr("the motion of '%1' cannot be evaluated: %2")
                                         .arg(object.name, QString::fromUtf8(error.what()))
                                         .toStdString());
        }
    }

    const model::Mesh& checkedMesh(const model::Mesh& mesh, const QString& objectName) const
    {
        for (const std::uint32_t index : mesh.indices)
            if (index >= mesh.positions.size())
                throw OutputError(path_, gyre::FileError::tr("the mesh of '%1' has an index past its vertices")
                                             .arg(objectName)
                                             .toStdString());
        return mesh;
    }

    std::vector<model::TimedPose> bakeTrack(const model::SceneObject& object)
    {
        // Summed as doubles and compared before any cast: a bound beyond the integer range cannot wrap.
        samples_ += model::bakeSampleBound(result_.range, object.track.keys.size());
        if (!(samples_ <= static_cast<double>(kMaxExportSamples)))
            throw OutputError(path_, FileError::tr("baking at %1 fps gives more than %2 samples")
                                         .arg(QString::fromStdString(formatNumber(result_.range.fps)))
                                         .arg(kMaxExportSamples)
                                         .toStdString());
        try {
            return model::bakeTrack(object.track, result_.range, model::flightBodyOf(object), scene_.gravity);
        } catch (const std::invalid_argument& error) {
            throw OutputError(path_, FileError::tr("the motion of '%1' cannot be baked: %2")
                                         .arg(object.name, QString::fromUtf8(error.what()))
                                         .toStdString());
        }
    }

    const model::Scene& scene_;
    const QString& path_;
    ExportReport& report_;
    NodeNames names_;
    double samples_ = 0.0; // bakeSampleBound summed over the baked objects
    BakedScene result_;
};

aiMesh* assimpMesh(const model::Mesh& mesh)
{
    auto result = std::make_unique<aiMesh>();
    result->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    result->mMaterialIndex = 0;
    result->mNumVertices = static_cast<unsigned>(mesh.positions.size());
    result->mVertices = new aiVector3D[mesh.positions.size()];
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        result->mVertices[i] = {mesh.positions[i].x(), mesh.positions[i].y(), mesh.positions[i].z()};
    if (mesh.normals.size() == mesh.positions.size()) {
        result->mNormals = new aiVector3D[mesh.normals.size()];
        for (std::size_t i = 0; i < mesh.normals.size(); ++i)
            result->mNormals[i] = {mesh.normals[i].x(), mesh.normals[i].y(), mesh.normals[i].z()};
    }
    result->mNumFaces = static_cast<unsigned>(mesh.indices.size() / 3);
    result->mFaces = new aiFace[result->mNumFaces];
    for (unsigned f = 0; f < result->mNumFaces; ++f) {
        result->mFaces[f].mNumIndices = 3;
        result->mFaces[f].mIndices = new unsigned[3]{mesh.indices[3 * f], mesh.indices[3 * f + 1], mesh.indices[3 * f + 2]};
    }
    return result.release();
}

// The bones of a skinned object's own copy of its mesh, from which Assimp's Collada writer writes a skin
// <controller>: one per joint, named as the joint's node (the writer finds the node by that name and makes
// it a JOINT), its offset matrix the inverse bind B_j, its weights the positions' nonzero ones. The writer's
// bind shape matrix is the identity, so Collada's skinning, Σ w · W_j · B_j · v in the world, is Gyre's
// (model/skinning.h). Weights that sum to less than 1 are written as they are: Collada's readers
// normalise them, as Blender's armature and Gyre's import do.
void addBones(aiMesh& mesh, const BakedObject& object, const BakedScene& baked)
{
    const model::Skin& skin = object.mesh->skin;
    const std::vector<std::vector<JointInfluence>> influences = jointInfluences(skin);
    mesh.mNumBones = static_cast<unsigned>(object.skinJoints.size());
    mesh.mBones = new aiBone*[mesh.mNumBones];
    for (std::size_t j = 0; j < object.skinJoints.size(); ++j) {
        auto* bone = new aiBone;
        mesh.mBones[j] = bone;
        bone->mName.Set(baked.objects[object.skinJoints[j]].name);
        const Eigen::Matrix4f& b = skin.inverseBinds[j];
        bone->mOffsetMatrix = aiMatrix4x4(b(0, 0), b(0, 1), b(0, 2), b(0, 3), b(1, 0), b(1, 1), b(1, 2), b(1, 3),
                                          b(2, 0), b(2, 1), b(2, 2), b(2, 3), b(3, 0), b(3, 1), b(3, 2), b(3, 3));
        bone->mNumWeights = static_cast<unsigned>(influences[j].size());
        bone->mWeights = newArray<aiVertexWeight>(influences[j].size());
        std::ranges::transform(influences[j], bone->mWeights, [](const JointInfluence& influence) {
            return aiVertexWeight(influence.vertex, influence.weight);
        });
    }
}

// One node animation channel: the baked poses as rotation and position keys at the same times, each
// quaternion on the side of the one before so that every reader's slerp takes the short arc. Unit
// scaling keys at the same times too: Assimp's Collada writer leaves out a channel whose three key
// lists differ in length.
aiNodeAnim* assimpChannel(const std::string& nodeName, const std::vector<model::TimedPose>& baked)
{
    auto channel = std::make_unique<aiNodeAnim>();
    channel->mNodeName.Set(nodeName);
    channel->mNumRotationKeys = static_cast<unsigned>(baked.size());
    channel->mNumPositionKeys = static_cast<unsigned>(baked.size());
    channel->mRotationKeys = new aiQuatKey[baked.size()];
    channel->mPositionKeys = new aiVectorKey[baked.size()];
    channel->mNumScalingKeys = static_cast<unsigned>(baked.size());
    channel->mScalingKeys = new aiVectorKey[baked.size()];
    Eigen::Quaterniond previous = baked.front().pose.orientation;
    for (std::size_t k = 0; k < baked.size(); ++k) {
        Eigen::Quaterniond q = baked[k].pose.orientation.normalized();
        if (q.coeffs().dot(previous.coeffs()) < 0.0)
            q.coeffs() = -q.coeffs();
        previous = q;
        const double ticks = baked[k].time * kTicksPerSecond;
        channel->mRotationKeys[k] = aiQuatKey(ticks, toAssimp(q));
        channel->mPositionKeys[k] = aiVectorKey(ticks, toAssimp(baked[k].pose.position));
        channel->mScalingKeys[k] = aiVectorKey(ticks, aiVector3D(1, 1, 1));
    }
    return channel.release();
}

aiMaterial* defaultMaterial()
{
    auto material = std::make_unique<aiMaterial>();
    const aiString name("Gyre default");
    material->AddProperty(&name, AI_MATKEY_NAME);
    const aiColor3D grey(0.7f, 0.7f, 0.7f);
    material->AddProperty(&grey, 1, AI_MATKEY_COLOR_DIFFUSE);
    return material.release();
}

// The aiScene of a baked scene: one node per object under a root, the meshes (one aiMesh for rigid objects
// that share a Mesh, one for each skinned object, with its bones), and the baked motion as one animation.
// glTF is Y-up by its specification, Assimp's Collada writer says Y_UP, and OBJ is Y-up by custom:
// Gyre's Z-up scene goes out turned, yUpToZUp()⁻¹ before each top-level pose, which Gyre's import and
// Blender's importers turn back. (FBX says Z-up in its GlobalSettings and goes out as it is.)
void turnZUpToYUp(BakedScene& baked)
{
    const Eigen::Quaterniond turn = yUpToZUp().conjugate();
    const auto turned = [&turn](const Pose& pose) {
        return Pose{(turn * pose.orientation).normalized(), turn * pose.position};
    };
    for (BakedObject& object : baked.objects) {
        if (object.parent)
            continue;
        object.startPose = turned(object.startPose);
        for (model::TimedPose& sample : object.samples)
            sample.pose = turned(sample.pose);
        // The splines are linear in their keys, so turning the keys turns the curves.
        for (SplineKey& key : object.rotationSpline)
            key = {key.time, turn * key.value, turn * key.inDerivative, turn * key.outDerivative};
        for (PositionSplineKey& key : object.positionSpline)
            key = {key.time, turn * key.value, turn * key.inDerivative, turn * key.outDerivative};
    }
}

std::unique_ptr<aiScene> assimpScene(const BakedScene& baked)
{
    auto result = std::make_unique<aiScene>();
    result->mFlags |= AI_SCENE_FLAGS_NON_VERBOSE_FORMAT; // vertices are shared between faces
    result->mRootNode = new aiNode(kRootName);
    result->mNumMaterials = 1;
    result->mMaterials = new aiMaterial*[1]{defaultMaterial()};

    std::vector<std::unique_ptr<aiMesh>> meshes;
    std::unordered_map<const model::Mesh*, unsigned> meshIndices;
    std::vector<std::unique_ptr<aiNode>> nodes;
    std::vector<std::unique_ptr<aiNodeAnim>> channels;
    for (const BakedObject& object : baked.objects) {
        auto node = std::make_unique<aiNode>(object.name);
        node->mTransformation = assimp_math::toAssimpMatrix(object.startPose);
        if (object.mesh) {
            auto index = static_cast<unsigned>(meshes.size());
            if (object.skinJoints.empty()) { // one aiMesh for the rigid objects that share a Mesh
                const auto [entry, isNew] = meshIndices.try_emplace(object.mesh, index);
                index = entry->second;
                if (isNew)
                    meshes.emplace_back(assimpMesh(*object.mesh));
            } else { // an aiMesh holds the bones of one skin: each skinned object has its own
                meshes.emplace_back(assimpMesh(*object.mesh));
                addBones(*meshes.back(), object, baked);
            }
            node->mNumMeshes = 1;
            node->mMeshes = new unsigned[1]{index};
        }
        nodes.push_back(std::move(node));
        if (!object.samples.empty())
            channels.emplace_back(assimpChannel(object.name, object.samples));
    }

    // Each node hangs under its parent's node or the root; the tree then owns the nodes.
    std::vector<std::vector<aiNode*>> children(nodes.size() + 1);
    for (std::size_t i = 0; i < nodes.size(); ++i)
        children[baked.objects[i].parent.value_or(nodes.size())].push_back(nodes[i].get());
    for (std::size_t i = 0; i <= nodes.size(); ++i) {
        aiNode& parent = i == nodes.size() ? *result->mRootNode : *nodes[i];
        parent.addChildren(static_cast<unsigned>(children[i].size()), children[i].data());
    }
    for (std::unique_ptr<aiNode>& node : nodes)
        static_cast<void>(node.release());

    result->mNumMeshes = static_cast<unsigned>(meshes.size());
    result->mMeshes = newArray<aiMesh*>(meshes.size());
    for (std::size_t i = 0; i < meshes.size(); ++i)
        result->mMeshes[i] = meshes[i].release();

    if (!channels.empty()) {
        auto animation = std::make_unique<aiAnimation>();
        animation->mName.Set("Gyre");
        animation->mTicksPerSecond = kTicksPerSecond;
        animation->mDuration = baked.range.end * kTicksPerSecond;
        animation->mNumChannels = static_cast<unsigned>(channels.size());
        animation->mChannels = new aiNodeAnim*[channels.size()];
        for (std::size_t i = 0; i < channels.size(); ++i)
            animation->mChannels[i] = channels[i].release();
        result->mNumAnimations = 1;
        result->mAnimations = new aiAnimation*[1]{animation.release()};
    }
    return result;
}

QByteArray bytesOf(const aiExportDataBlob& blob)
{
    return QByteArray::fromRawData(static_cast<const char*>(blob.data), static_cast<qsizetype>(blob.size));
}

// Assimp writes into memory (a BlobIOSystem named after the destination, so that the files a format
// refers to, such as the .gltf's .bin, are named after it too); the blobs are then written whole.
ExportReport writeWithAssimp(const aiScene& scene, const QString& path, SceneFormat format, ExportReport report)
{
    const std::string target = QFile::encodeName(path).toStdString();
    Assimp::Exporter exporter;
    auto* memory = new Assimp::BlobIOSystem(target);
    exporter.SetIOHandler(memory); // the exporter owns it
    if (exporter.Export(&scene, assimpFormatId(format), target) != aiReturn_SUCCESS) {
        const std::string reason = exporter.GetErrorString();
        throw OutputError(path, reason.empty() ? FileError::tr("Assimp cannot write it").toStdString()
                                               : FileError::tr("Assimp cannot write it: %1")
                                                     .arg(QString::fromStdString(reason))
                                                     .toStdString());
    }
    const std::unique_ptr<aiExportDataBlob> main(memory->GetBlobChain());
    if (!main)
        throw OutputError(path, FileError::tr("Assimp wrote nothing").toStdString());
    std::vector<FileContents> files;
    for (const aiExportDataBlob* other = main->next; other; other = other->next)
        files.push_back({QFile::decodeName(other->name.C_Str()), bytesOf(*other)});
    files.push_back({path, bytesOf(*main)});
    saveFilesTogether(files);
    for (const FileContents& file : files)
        report.files << file.path;
    return report;
}

ExportReport writeGltf(const BakedScene& baked, const QString& path, bool binary, ExportReport report)
{
    const QFileInfo info(path);
    const QString binName = info.completeBaseName() + QStringLiteral(".bin");
    GltfFiles files;
    try {
        files = gltfSceneFiles(baked, binary, binName);
    } catch (const std::runtime_error& error) {
        throw OutputError(path, FileError::tr("cannot be written as glTF: %1").arg(QString::fromUtf8(error.what())).toStdString());
    }
    std::vector<FileContents> written;
    if (!files.bin.isEmpty())
        written.push_back({info.dir().filePath(binName), files.bin});
    written.push_back({path, files.main});
    saveFilesTogether(written);
    for (const FileContents& file : written)
        report.files << file.path;
    return report;
}

} // namespace

std::optional<SceneFormat> sceneFormatOfPath(const QString& path)
{
    return valueNamed(kSceneFormatNames, QFileInfo(path).suffix().toLower().toStdString());
}

bool keepsMotion(SceneFormat format) { return format != SceneFormat::Obj; }

ExportReport exportScene(const model::Scene& scene, const QString& path, SceneFormat format, double fps)
{
    if (!(std::isfinite(fps) && fps > 0.0))
        throw OutputError(path, FileError::tr("the frame rate must be a finite number above zero").toStdString());
    if (!(std::isfinite(scene.startTime) && std::isfinite(scene.endTime) && scene.startTime <= scene.endTime))
        throw OutputError(path, FileError::tr("the scene's time range is empty or not finite").toStdString());
    ExportReport report;
    if (format == SceneFormat::Obj && std::ranges::none_of(scene.objects, hasTriangles))
        throw OutputError(path, FileError::tr("the scene has no meshes, and OBJ holds nothing else").toStdString());
    if (!keepsMotion(format))
        report.warnings << FileError::tr("OBJ holds no motion: the meshes are written as posed at the start time");
    BakedScene baked = SceneBaker(scene, path, fps, report).bake(keepsMotion(format));
    if (format != SceneFormat::Fbx)
        turnZUpToYUp(baked);
    if (format == SceneFormat::Gltf || format == SceneFormat::Glb) {
        report.warnings << prepareGltfTimes(baked, scene); // float32, not negative, increasing
        return writeGltf(baked, path, format == SceneFormat::Glb, std::move(report));
    }
    if (format == SceneFormat::Fbx) {
        std::string bytes;
        try {
            bytes = fbxSceneFile(baked);
        } catch (const std::length_error& error) {
            throw OutputError(path, FileError::tr("cannot be written as FBX: %1")
                                        .arg(QString::fromUtf8(error.what()))
                                        .toStdString());
        }
        saveFileContents(path, QByteArray::fromRawData(bytes.data(), static_cast<qsizetype>(bytes.size())));
        report.files << path;
        return report;
    }
    return writeWithAssimp(*assimpScene(baked), path, format, std::move(report));
}

} // namespace gyre::io
