#include "io/scene_export.h"

#include "io/assimp_math.h"
#include "core/number_text.h"
#include "model/output_target.h"
#include "model/track_evaluation.h"

#include <assimp/BlobIOSystem.h>
#include <assimp/Exporter.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>

#include <QFile>
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

namespace gyre {

namespace {

using assimp_math::toAssimp;

const char* assimpFormatId(SceneFormat format)
{
    switch (format) {
    case SceneFormat::Gltf:
        return "gltf2";
    case SceneFormat::Glb:
        return "glb2";
    case SceneFormat::Collada:
        return "collada";
    case SceneFormat::Fbx:
        return "fbxa"; // ASCII: see scene_export.h
    case SceneFormat::Obj:
        return "obj";
    }
    return "";
}

// Assimp's Collada and FBX writers of 5.2 write key times as seconds whatever mTicksPerSecond says,
// and its glTF writer divides them by it: with one tick per second all three write the same times.
constexpr double kTicksPerSecond = 1.0;

const char* const kRootName = "GyreScene";

template <class T>
T* newArray(std::size_t count)
{
    return count == 0 ? nullptr : new T[count];
}

// Node names unique within the file, since animation channels find their nodes by name.
class NodeNames {
public:
    NodeNames() { used_.insert(kRootName); }

    std::string unique(const model::SceneObject& object, QStringList& warnings)
    {
        const std::string wanted =
            object.name.isEmpty() ? "object_" + std::to_string(object.id) : object.name.toStdString();
        std::string name = wanted;
        for (int n = 2; !used_.insert(name).second; ++n)
            name = wanted + '_' + std::to_string(n);
        if (name != wanted || object.name.isEmpty())
            warnings << gyre::FileError::tr("object %1 '%2' is written as '%3' so that its name is unique")
                            .arg(object.id)
                            .arg(object.name, QString::fromStdString(name));
        return name;
    }

private:
    std::set<std::string> used_;
};

aiMesh* assimpMesh(const model::Mesh& mesh, const QString& objectName, const QString& path)
{
    for (const std::uint32_t index : mesh.indices)
        if (index >= mesh.positions.size())
            throw OutputError(
                path, FileError::tr("the mesh of '%1' has an index past its vertices").arg(objectName).toStdString());
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

bool hasTriangles(const model::SceneObject& object) { return object.mesh && !object.mesh->indices.empty(); }

aiMaterial* defaultMaterial()
{
    auto material = std::make_unique<aiMaterial>();
    const aiString name("Gyre default");
    material->AddProperty(&name, AI_MATKEY_NAME);
    const aiColor3D grey(0.7f, 0.7f, 0.7f);
    material->AddProperty(&grey, 1, AI_MATKEY_COLOR_DIFFUSE);
    return material.release();
}

// Builds the aiScene of a Gyre scene: one node per object under a root, the meshes, and the baked
// motion as one animation.
class AssimpSceneBuilder {
public:
    AssimpSceneBuilder(const model::Scene& scene, const QString& path, double fps, ExportReport& report)
        : scene_(scene)
        , path_(path)
        , range_{scene.startTime, scene.endTime, fps}
        , report_(report)
    {
    }

    std::unique_ptr<aiScene> build(bool withMotion)
    {
        auto result = std::make_unique<aiScene>();
        result->mFlags |= AI_SCENE_FLAGS_NON_VERBOSE_FORMAT; // vertices are shared between faces
        result->mRootNode = new aiNode(kRootName);
        result->mNumMaterials = 1;
        result->mMaterials = new aiMaterial*[1]{defaultMaterial()};
        std::vector<std::unique_ptr<aiNodeAnim>> channels;
        std::vector<std::unique_ptr<aiNode>> nodes;
        for (const model::SceneObject& object : scene_.objects) {
            const std::string name = names_.unique(object, report_.warnings);
            nodes.push_back(nodeOf(object, name));
            if (withMotion && isAnimated(object.track))
                channels.emplace_back(assimpChannel(name, bake(object)));
        }
        attachNodes(*result->mRootNode, nodes);
        moveMeshes(*result);
        if (!channels.empty())
            addAnimation(*result, channels);
        return result;
    }

private:
    static bool isAnimated(const model::MotionTrack& track)
    {
        return track.keys.size() > 1 || !track.sketch.fittedCurve.empty();
    }

    std::vector<model::TimedPose> bake(const model::SceneObject& object)
    {
        // Summed as doubles and compared before any cast: a bound beyond the integer range cannot wrap.
        samples_ += model::bakeSampleBound(range_, object.track.keys.size());
        if (!(samples_ <= static_cast<double>(kMaxExportSamples)))
            throw OutputError(path_, FileError::tr("baking at %1 fps gives more than %2 samples")
                                         .arg(QString::fromStdString(formatNumber(range_.fps)))
                                         .arg(kMaxExportSamples)
                                         .toStdString());
        try {
            return model::bakeTrack(object.track, range_);
        } catch (const std::invalid_argument& error) {
            throw OutputError(path_, FileError::tr("the motion of '%1' cannot be baked: %2")
                                         .arg(object.name, QString::fromUtf8(error.what()))
                                         .toStdString());
        }
    }

    std::unique_ptr<aiNode> nodeOf(const model::SceneObject& object, const std::string& name)
    {
        auto node = std::make_unique<aiNode>(name);
        try {
            node->mTransformation = assimp_math::toAssimpMatrix(model::unitSample(
                model::TrackMotion(object.track).at(scene_.startTime), scene_.startTime));
        } catch (const std::invalid_argument& error) {
            throw OutputError(path_, FileError::tr("the motion of '%1' cannot be evaluated: %2")
                                         .arg(object.name, QString::fromUtf8(error.what()))
                                         .toStdString());
        }
        if (hasTriangles(object)) {
            node->mNumMeshes = 1;
            node->mMeshes = new unsigned[1]{meshIndex(*object.mesh, object.name)};
        }
        parentOf_.push_back(object.parent);
        idOf_.push_back(object.id);
        return node;
    }

    // Objects that share a Mesh share one aiMesh.
    unsigned meshIndex(const model::Mesh& mesh, const QString& objectName)
    {
        const auto [entry, isNew] = meshIndices_.try_emplace(&mesh, static_cast<unsigned>(meshes_.size()));
        if (isNew)
            meshes_.emplace_back(assimpMesh(mesh, objectName, path_));
        return entry->second;
    }

    // Hangs each node under its parent's node, or under the root for a top-level object or a parent
    // that does not come before it. The tree then owns the nodes.
    void attachNodes(aiNode& root, std::vector<std::unique_ptr<aiNode>>& nodes)
    {
        const std::size_t rootIndex = nodes.size();
        std::vector<std::vector<aiNode*>> children(nodes.size() + 1);
        std::unordered_map<model::ObjectId, std::size_t> indexOfId;
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            std::size_t parent = rootIndex;
            if (parentOf_[i] != model::kNoObject) {
                if (const auto found = indexOfId.find(parentOf_[i]); found != indexOfId.end())
                    parent = found->second;
                else
                    report_.warnings << FileError::tr("object %1 names parent %2, which does not come before it; "
                                                      "it is written at the top level")
                                            .arg(idOf_[i])
                                            .arg(parentOf_[i]);
            }
            children[parent].push_back(nodes[i].get());
            indexOfId.emplace(idOf_[i], i);
        }
        for (std::size_t i = 0; i <= nodes.size(); ++i) {
            aiNode& parent = i == rootIndex ? root : *nodes[i];
            parent.addChildren(static_cast<unsigned>(children[i].size()), children[i].data());
        }
        for (std::unique_ptr<aiNode>& node : nodes)
            static_cast<void>(node.release());
    }

    void moveMeshes(aiScene& result)
    {
        result.mNumMeshes = static_cast<unsigned>(meshes_.size());
        result.mMeshes = newArray<aiMesh*>(meshes_.size());
        for (std::size_t i = 0; i < meshes_.size(); ++i)
            result.mMeshes[i] = meshes_[i].release();
    }

    void addAnimation(aiScene& result, std::vector<std::unique_ptr<aiNodeAnim>>& channels) const
    {
        auto animation = std::make_unique<aiAnimation>();
        animation->mName.Set("Gyre");
        animation->mTicksPerSecond = kTicksPerSecond;
        animation->mDuration = range_.end * kTicksPerSecond;
        animation->mNumChannels = static_cast<unsigned>(channels.size());
        animation->mChannels = new aiNodeAnim*[channels.size()];
        for (std::size_t i = 0; i < channels.size(); ++i)
            animation->mChannels[i] = channels[i].release();
        result.mNumAnimations = 1;
        result.mAnimations = new aiAnimation*[1]{animation.release()};
    }

    const model::Scene& scene_;
    const QString& path_;
    model::BakeRange range_;
    ExportReport& report_;
    NodeNames names_;
    double samples_ = 0.0; // bakeSampleBound summed over the baked objects
    std::vector<model::ObjectId> parentOf_;
    std::vector<model::ObjectId> idOf_;
    std::vector<std::unique_ptr<aiMesh>> meshes_;
    std::unordered_map<const model::Mesh*, unsigned> meshIndices_;
};

void writeWhole(const QString& path, const aiExportDataBlob& blob)
{
    saveFileContents(path, QByteArray::fromRawData(static_cast<const char*>(blob.data), static_cast<qsizetype>(blob.size)));
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
    for (const aiExportDataBlob* other = main->next; other; other = other->next) {
        const QString otherPath = QFile::decodeName(other->name.C_Str());
        writeWhole(otherPath, *other);
        report.files << otherPath;
    }
    writeWhole(path, *main);
    report.files << path;
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
    const std::unique_ptr<const aiScene> assimpScene =
        AssimpSceneBuilder(scene, path, fps, report).build(keepsMotion(format));
    return writeWithAssimp(*assimpScene, path, format, std::move(report));
}

} // namespace gyre
