#include "io/scene_import.h"

#include "io/assimp_math.h"
#include "io/gltf_animation.h"
#include "io/scene_import_settings.h"
#include "io/scene_import_skin.h"
#include "model/scene_joints.h"
#include "model/value_checks.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/version.h>

#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <unordered_map>
#include <utility>

namespace gyre::io {

namespace {

using assimp_math::toEigen;

// Steps that make meshes displayable and refuse inconsistent data. None of them touches node
// animation; steps that would (PreTransformVertices, OptimizeGraph, MakeLeftHanded, GlobalScale) are
// left out on purpose.
constexpr unsigned kPostProcessing = aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                                     aiProcess_JoinIdenticalVertices | aiProcess_ValidateDataStructure;

// Scales closer than this, relatively, count as equal: files from 3ds Max carry scales such as
// (1.00005, 1.00004, 1) that are single-precision noise, not intent.
constexpr double kScaleTolerance = 1e-3;

QString nameOf(const aiString& name) { return QString::fromUtf8(name.data, static_cast<qsizetype>(name.length)); }

std::string_view viewOf(const aiString& name) { return {name.data, name.length}; }

void requireReadableFile(const QString& path)
{
    const QFileInfo info(path);
    if (!info.exists())
        throw InputError(path, FileError::tr("no such file").toStdString());
    if (info.isDir())
        throw InputError(path, FileError::tr("is a directory, not a scene file").toStdString());
    if (!info.isReadable())
        throw InputError(path, FileError::tr("cannot be read (permission denied)").toStdString());
    if (info.size() == 0)
        throw InputError(path, FileError::tr("the file is empty").toStdString());
}

const aiScene& readWithAssimp(Assimp::Importer& importer, const QString& path)
{
    // Without pivots FBX gives one node per model instead of a chain of $AssimpFbx$ helper nodes.
    importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, false);
    // BVH would get a stick-figure mesh on its root joint; Gyre draws each joint as an object instead.
    importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
    // Gyre turns Z-up scenes itself, on its top-level objects, as for every format (ImportSettings).
    importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
    const aiScene* scene = importer.ReadFile(QFile::encodeName(path).toStdString(), 0);
    if (scene && scene->mNumMeshes == 0 && scene->mNumAnimations == 0)
        throw InputError(path, FileError::tr("the file holds no meshes and no animation").toStdString());
    if (scene && scene->mNumMeshes == 0) {
        // A skeleton with its motion and no mesh is a whole scene to Gyre. Assimp's flag for such
        // files lets validation pass them; the importer owns the scene and allows changing it.
        const_cast<aiScene*>(scene)->mFlags |= AI_SCENE_FLAGS_INCOMPLETE;
    }
    if (scene)
        scene = importer.ApplyPostProcessing(kPostProcessing);
    if (!scene)
        throw InputError(path, FileError::tr("not a scene Gyre can read: %1")
                                   .arg(QString::fromUtf8(importer.GetErrorString()))
                                   .toStdString());
    if (!scene->mRootNode)
        throw InputError(path, FileError::tr("the file holds no scene nodes").toStdString());
    return *scene;
}

double ticksPerSecond(const aiAnimation& animation)
{
    const double ticks = animation.mTicksPerSecond;
    return std::isfinite(ticks) && ticks > 0.0 ? ticks : kDefaultTicksPerSecond;
}

std::vector<AnimationSummary> summariesOf(const aiScene& scene)
{
    std::vector<AnimationSummary> summaries;
    for (unsigned i = 0; i < scene.mNumAnimations; ++i) {
        const aiAnimation& animation = *scene.mAnimations[i];
        QStringList nodes;
        for (unsigned c = 0; c < animation.mNumChannels; ++c)
            if (const QString node = nameOf(animation.mChannels[c]->mNodeName); !nodes.contains(node))
                nodes << node;
        summaries.push_back({nameOf(animation.mName), animation.mDuration / ticksPerSecond(animation), nodes});
    }
    return summaries;
}

// --- keys -------------------------------------------------------------------------------------------


bool isFinite(const aiVector3D& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool isFinite(const aiQuaternion& q)
{
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

// Empty when the keys are finite, rotations nonzero and times strictly increasing; else what is wrong.
// `kind` names the keys, marked with QT_TRANSLATE_NOOP("gyre::FileError", ...).
template <class Key>
QString keyProblem(const Key* keys, unsigned count, const char* kind)
{
    for (unsigned i = 0; i < count; ++i) {
        const auto problem = [&](const char* text) { return FileError::tr(text).arg(FileError::tr(kind)).arg(i); };
        if (!std::isfinite(keys[i].mTime) || !isFinite(keys[i].mValue))
            return problem(QT_TRANSLATE_NOOP("gyre::FileError", "%1 key %2 is not finite"));
        if constexpr (std::is_same_v<Key, aiQuatKey>) {
            if (toEigen(keys[i].mValue).squaredNorm() == 0.0)
                return problem(QT_TRANSLATE_NOOP("gyre::FileError", "%1 key %2 is not a rotation (a zero quaternion)"));
        }
        if (i > 0 && !(keys[i].mTime > keys[i - 1].mTime))
            return problem(QT_TRANSLATE_NOOP("gyre::FileError", "%1 key %2 is not after the key before it"));
    }
    return {};
}

// The error for a node whose keys keyProblem() refuses, or whose mesh checkMesh() refuses:
// "node 'name': what is wrong".
InputError nodeError(const QString& path, const aiNode& node, const QString& problem)
{
    return InputError(path, FileError::tr("node '%1': %2").arg(nameOf(node.mName), problem).toStdString());
}

// A node's local transform split into the parts Gyre keeps: a rigid pose and a scale.
struct NodeTransform {
    Pose pose;
    Eigen::Vector3d scale = Eigen::Vector3d::Ones();
};

NodeTransform decompose(const aiMatrix4x4& matrix)
{
    aiVector3D scale;
    aiQuaternion rotation;
    aiVector3D position;
    matrix.Decompose(scale, rotation, position);
    return {{toEigen(rotation).normalized(), toEigen(position)}, toEigen(scale)};
}

// Where a key sequence is at `ticks`, given the index `next` of its first key after `ticks`: held
// before the first and after the last key, interpolated in between by `blend(a, b, u)`.
template <class Key, class Blend>
auto valueBetween(const Key* keys, unsigned count, unsigned next, double ticks, Blend blend)
{
    if (next == 0)
        return toEigen(keys[0].mValue);
    if (next == count)
        return toEigen(keys[count - 1].mValue);
    const Key& before = keys[next - 1];
    const Key& after = keys[next];
    return blend(toEigen(before.mValue), toEigen(after.mValue), (ticks - before.mTime) / (after.mTime - before.mTime));
}

Eigen::Quaterniond rotationAt(const aiNodeAnim& channel, unsigned next, double ticks)
{
    const auto slerp = [](const Eigen::Quaterniond& a, const Eigen::Quaterniond& b, double u) {
        return a.normalized().slerp(u, b.normalized()); // the short arc, as aiQuaternion::Interpolate
    };
    return valueBetween(channel.mRotationKeys, channel.mNumRotationKeys, next, ticks, slerp).normalized();
}

Eigen::Vector3d positionAt(const aiNodeAnim& channel, unsigned next, double ticks)
{
    const auto lerp = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b, double u) -> Eigen::Vector3d {
        return a + u * (b - a);
    };
    return valueBetween(channel.mPositionKeys, channel.mNumPositionKeys, next, ticks, lerp);
}

// The keyframes of an animated node at the union of its rotation and position key times. Each
// file key keeps its value; the other value comes from rotationAt or positionAt. A value the channel
// does not animate is the node's own.
std::vector<model::Keyframe> keyframesOf(const aiNodeAnim& channel, double ticksPerSecond, const Pose& nodePose,
                                         double positionScale)
{
    const unsigned rotations = channel.mNumRotationKeys;
    const unsigned positions = channel.mNumPositionKeys;
    std::vector<model::Keyframe> keys;
    keys.reserve(std::size_t{rotations} + positions);
    // One key beside several is a constant (Blender's glTF exporter writes an unchanging translation as
    // one key at time 0): it gives its value at the other's times and adds no time of its own.
    const unsigned timedRotations = rotations == 1 && positions > 1 ? 0 : rotations;
    const unsigned timedPositions = positions == 1 && rotations > 1 ? 0 : positions;
    unsigned r = 0;
    unsigned p = 0;
    constexpr double kNever = std::numeric_limits<double>::infinity();
    while (r < timedRotations || p < timedPositions) {
        const double ticks = std::min(r < timedRotations ? channel.mRotationKeys[r].mTime : kNever,
                                      p < timedPositions ? channel.mPositionKeys[p].mTime : kNever);
        Pose pose = nodePose;
        if (rotations > 0) {
            const bool atKey = r < timedRotations && channel.mRotationKeys[r].mTime == ticks;
            pose.orientation = atKey ? toEigen(channel.mRotationKeys[r++].mValue).normalized()
                                     : rotationAt(channel, r, ticks);
        }
        if (positions > 0) {
            const bool atKey = p < timedPositions && channel.mPositionKeys[p].mTime == ticks;
            pose.position = atKey ? toEigen(channel.mPositionKeys[p++].mValue) : positionAt(channel, p, ticks);
        }
        pose.position *= positionScale;
        keys.push_back({ticks / ticksPerSecond, pose, true});
    }
    return keys;
}

// --- meshes -----------------------------------------------------------------------------------------

// The meshes of a node, merged and scaled: positions by s, normals by the inverse transpose s⁻¹. A
// merged mesh with bones is skinned once every node has its object (finishSkins).
class MeshConverter {
public:
    MeshConverter(const QString& path, const aiScene& scene) : path_(path), scene_(scene) {}

    std::shared_ptr<const model::Mesh> meshOf(const aiNode& node, const Eigen::Vector3d& scale)
    {
        if (node.mNumMeshes == 0)
            return nullptr;
        Key key{std::vector<unsigned>(node.mMeshes, node.mMeshes + node.mNumMeshes), {scale.x(), scale.y(), scale.z()}};
        auto [entry, isNew] = converted_.try_emplace(std::move(key));
        if (isNew)
            entry->second = merged(node, scale);
        return entry->second;
    }

    // Gives each skinned mesh its skin, `nodes` naming the objects of the joints, and checks it.
    void finishSkins(const std::map<std::string, JointNode>& nodes, QStringList& warnings)
    {
        for (auto& [mesh, skin] : skins_) {
            skin.finish(nodes, warnings);
            try {
                model::checkSkin(mesh->skin, mesh->positions.size());
            } catch (const std::invalid_argument& problem) {
                throw InputError(path_, FileError::tr("mesh '%1': %2").arg(skin.name(), QString::fromUtf8(problem.what())).toStdString());
            }
        }
    }

private:
    // Nodes that hold the same meshes at the same scale share one Mesh.
    using Key = std::pair<std::vector<unsigned>, std::array<double, 3>>;

    std::shared_ptr<const model::Mesh> merged(const aiNode& node, const Eigen::Vector3d& scale)
    {
        auto mesh = std::make_shared<model::Mesh>();
        std::optional<PendingSkin> skin;
        bool allHaveNormals = true;
        for (unsigned i = 0; i < node.mNumMeshes; ++i) {
            const aiMesh& part = *scene_.mMeshes[node.mMeshes[i]];
            if (!(part.mPrimitiveTypes & aiPrimitiveType_TRIANGLE))
                continue; // points and lines: nothing to shade
            if (part.mNumBones > 0) {
                if (!skin)
                    skin.emplace(mesh, nameOf(part.mName), scale);
                skin->addBones(part, static_cast<std::uint32_t>(mesh->positions.size()), path_);
            }
            allHaveNormals = allHaveNormals && part.mNormals;
            append(part, scale, *mesh);
        }
        if (!allHaveNormals)
            mesh->normals.clear();
        if (mesh->indices.empty())
            return nullptr;
        if (skin)
            skins_.emplace_back(mesh.get(), std::move(*skin));
        return mesh;
    }

    static void append(const aiMesh& part, const Eigen::Vector3d& scale, model::Mesh& mesh)
    {
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        const Eigen::Vector3f positionScale = scale.cast<float>();
        const Eigen::Vector3f normalScale = scale.cwiseInverse().cast<float>();
        for (unsigned v = 0; v < part.mNumVertices; ++v) {
            mesh.positions.push_back(toEigen(part.mVertices[v]).cast<float>().cwiseProduct(positionScale));
            if (part.mNormals)
                mesh.normals.push_back(toEigen(part.mNormals[v]).cast<float>().cwiseProduct(normalScale).normalized());
        }
        for (unsigned f = 0; f < part.mNumFaces; ++f) {
            const aiFace& face = part.mFaces[f];
            if (face.mNumIndices == 3)
                for (unsigned k = 0; k < 3; ++k)
                    mesh.indices.push_back(base + face.mIndices[k]);
        }
    }

    const QString& path_;
    const aiScene& scene_;
    std::map<Key, std::shared_ptr<const model::Mesh>> converted_;
    std::vector<std::pair<const model::Mesh*, PendingSkin>> skins_;
};

// --- nodes ------------------------------------------------------------------------------------------

bool isUniform(const Eigen::Vector3d& scale)
{
    return (scale.maxCoeff() - scale.minCoeff()) <= kScaleTolerance * scale.cwiseAbs().maxCoeff();
}

// Builds the scene from the node tree, depth first so that parents come before children.
// Makes every object without a mesh that is no joint (model/scene_joints.h) an Empty: a pivot, a target,
// the node of a camera or a light. None is an Empty before, so the rule sees the file's hierarchy alone.
void markEmpties(model::Scene& scene)
{
    const std::vector<bool> joints = model::findJoints(scene);
    for (std::size_t i = 0; i < joints.size(); ++i)
        scene.objects[i].empty = scene.objects[i].mesh == nullptr && !joints[i];
}

class SceneBuilder {
public:
    // `animations` are merged in their order: a node that several move takes the last one's channel.
    // `gltf`, for a glTF file, holds its samplers as the file means them (gltf_animation.h), indexed as
    // the file's animations; `indices` are the chosen animations' indices in the file.
    SceneBuilder(const QString& path, const aiScene& scene, const std::vector<const aiAnimation*>& animations,
                 const std::vector<std::size_t>& indices, const GltfAnimations* gltf, SceneImport& result)
        : path_(path)
        , meshes_(path, scene)
        , gltf_(gltf)
        , result_(result)
    {
        for (std::size_t i = 0; i < animations.size(); ++i)
            indexChannels(*animations[i], indices[i]);
    }

    // The objects built, `metresPerUnit` scaling every position and mesh.
    void build(const aiNode& root, double metresPerUnit)
    {
        struct Pending {
            const aiNode* node;
            model::ObjectId parent;
            double inheritedScale; // the uniform scale of the ancestors, baked into this node
        };
        std::vector<Pending> pending;
        const auto pushChildren = [&pending](const aiNode& node, model::ObjectId parent, double scale) {
            for (unsigned i = node.mNumChildren; i-- > 0;)
                pending.push_back({node.mChildren[i], parent, scale});
        };
        if (carriesNothing(root))
            pushChildren(root, model::kNoObject, metresPerUnit);
        else
            pending.push_back({&root, model::kNoObject, metresPerUnit});
        while (!pending.empty()) {
            const Pending next = pending.back();
            pending.pop_back();
            const auto [id, childScale] = addObject(*next.node, next.parent, next.inheritedScale);
            pushChildren(*next.node, id, childScale);
        }
        meshes_.finishSkins(nodes_, result_.warnings);
        markEmpties(result_.scene);
        reportUnusedChannels();
    }

    // The ids of the objects that have a channel.
    const std::set<model::ObjectId>& animatedObjects() const { return animated_; }

private:
    struct Channel {
        const aiNodeAnim* keys;
        const aiAnimation* animation;
        std::size_t fileIndex; // of the animation
    };

    void indexChannels(const aiAnimation& animation, std::size_t fileIndex)
    {
        std::set<std::string_view> inThisAnimation;
        for (unsigned i = 0; i < animation.mNumChannels; ++i) {
            const aiNodeAnim& channel = *animation.mChannels[i];
            const std::string_view node = viewOf(channel.mNodeName);
            if (!inThisAnimation.insert(node).second) {
                result_.warnings << FileError::tr("node '%1' has more than one channel in animation '%2'; the first is used")
                                        .arg(nameOf(channel.mNodeName), nameOf(animation.mName));
                continue;
            }
            const auto [entry, isNew] = channels_.insert_or_assign(node, Channel{&channel, &animation, fileIndex});
            if (!isNew)
                result_.warnings << FileError::tr("node '%1' is moved by more than one of the chosen animations; "
                                                  "the later one, '%2', is used")
                                        .arg(nameOf(channel.mNodeName), nameOf(animation.mName));
        }
    }

    const Channel* channelOf(const aiNode& node) const
    {
        const auto found = channels_.find(viewOf(node.mName));
        return found == channels_.end() ? nullptr : &found->second;
    }

    bool carriesNothing(const aiNode& node) const
    {
        return node.mNumMeshes == 0 && node.mTransformation.IsIdentity() && !channelOf(node);
    }

    // Adds the object of `node`; returns its id and the uniform scale its children inherit.
    std::pair<model::ObjectId, double> addObject(const aiNode& node, model::ObjectId parent, double inheritedScale)
    {
        model::SceneObject object;
        object.id = result_.scene.nextObjectId++;
        object.name = nameOf(node.mName);
        object.parent = parent;
        const NodeTransform transform = decompose(node.mTransformation);
        const Channel* channel = channelOf(node);
        Eigen::Vector3d scale = transform.scale;
        if (channel) {
            used_.insert(viewOf(node.mName));
            animated_.insert(object.id);
            object.track = animatedTrack(node, *channel, transform.pose, inheritedScale);
            scale = animatedScale(node, *channel->keys, scale);
        } else {
            Pose pose = transform.pose;
            pose.position *= inheritedScale;
            object.track.keys = {{0.0, pose, true}};
            object.track.interpolation = InterpolationMethod::Slerp;
        }
        object.mesh = meshes_.meshOf(node, inheritedScale * scale);
        nodes_.try_emplace(std::string(viewOf(node.mName)), JointNode{object.id, inheritedScale * scale});
        // The rule every document's mesh keeps (value_checks.h), said of the node here: the parent
        // applies it again to the reply, where a breach could only read as a malformed reply.
        if (object.mesh) {
            try {
                model::checkMesh(*object.mesh);
            } catch (const std::invalid_argument& problem) {
                throw nodeError(path_, node, QString::fromUtf8(problem.what()));
            }
        }
        if (!isUniform(scale) && node.mNumChildren > 0)
            result_.warnings << FileError::tr("node '%1' has a non-uniform scale; its children get the mean scale")
                                    .arg(object.name);
        const double childScale = inheritedScale * std::cbrt(scale.prod());
        result_.scene.objects.push_back(std::move(object));
        return {result_.scene.objects.back().id, childScale};
    }

    // A glTF node's track from its samplers; any other's keys from Assimp's channel, played by slerp.
    model::MotionTrack animatedTrack(const aiNode& node, const Channel& animated, const Pose& nodePose,
                                     double positionScale) const
    {
        if (gltf_) {
            const auto& nodes = gltf_->at(animated.fileIndex);
            if (const auto found = nodes.find(std::string(viewOf(node.mName))); found != nodes.end())
                return gltfTrack(found->second, nodePose, positionScale, result_.applied.fps, path_, nameOf(node.mName));
        }
        const aiNodeAnim& channel = *animated.keys;
        QString problem =
            keyProblem(channel.mRotationKeys, channel.mNumRotationKeys, QT_TRANSLATE_NOOP("gyre::FileError", "rotation"));
        if (problem.isEmpty())
            problem = keyProblem(channel.mPositionKeys, channel.mNumPositionKeys,
                                 QT_TRANSLATE_NOOP("gyre::FileError", "position"));
        if (!problem.isEmpty())
            throw nodeError(path_, node, problem);
        model::MotionTrack track;
        track.keys = keyframesOf(channel, ticksPerSecond(*animated.animation), nodePose, positionScale);
        track.interpolation = InterpolationMethod::Slerp;
        return track;
    }

    // The first scaling key, or the node's own scale when the channel has none.
    Eigen::Vector3d animatedScale(const aiNode& node, const aiNodeAnim& channel, const Eigen::Vector3d& nodeScale)
    {
        if (channel.mNumScalingKeys == 0)
            return nodeScale;
        const QString problem =
            keyProblem(channel.mScalingKeys, channel.mNumScalingKeys, QT_TRANSLATE_NOOP("gyre::FileError", "scaling"));
        if (!problem.isEmpty())
            throw nodeError(path_, node, problem);
        const Eigen::Vector3d first = toEigen(channel.mScalingKeys[0].mValue);
        for (unsigned i = 1; i < channel.mNumScalingKeys; ++i)
            if ((toEigen(channel.mScalingKeys[i].mValue) - first).norm() > kScaleTolerance * first.norm()) {
                result_.warnings << gyre::FileError::tr("node '%1': its scale changes over time; Gyre's motion is rigid, "
                                                        "so the scale of its first key is kept")
                                        .arg(nameOf(node.mName));
                break;
            }
        return first;
    }

    void reportUnusedChannels()
    {
        for (const auto& [name, channel] : channels_)
            if (!used_.contains(name))
                result_.warnings << FileError::tr("animation '%1' moves '%2', which is not in the scene")
                                        .arg(nameOf(channel.animation->mName), nameOf(channel.keys->mNodeName));
    }

    const QString& path_;
    MeshConverter meshes_;
    const GltfAnimations* gltf_;
    SceneImport& result_;
    std::unordered_map<std::string_view, Channel> channels_;
    std::set<std::string_view> used_;
    std::set<model::ObjectId> animated_;
    std::map<std::string, JointNode> nodes_; // the first node of each name
};

// The takes the options name, each checked against the file, or the automatic choice.
TakePlan chosenTakes(const QString& path, const std::vector<AnimationSummary>& animations, const ImportOptions& options)
{
    switch (options.takeSelection) {
    case TakeSelection::Automatic:
        return planTakes(animations);
    case TakeSelection::All: {
        TakePlan plan{{}, TakeRule::Chosen, {}};
        for (std::size_t i = 0; i < animations.size(); ++i)
            plan.takes.push_back(i);
        return plan;
    }
    case TakeSelection::Listed:
        break;
    }
    for (const std::size_t index : options.takes)
        if (index >= animations.size())
            throw InputError(path, FileError::tr("the file has %n animation(s); there is no animation %1", nullptr,
                                                 static_cast<int>(animations.size()))
                                       .arg(index)
                                       .toStdString());
    return {options.takes, TakeRule::Chosen, {}};
}

void warnAboutWhatIsLeftOut(const aiScene& scene, const std::vector<const aiAnimation*>& animations,
                            QStringList& warnings)
{
    if (std::any_of(animations.begin(), animations.end(), [](const aiAnimation* animation) {
            return animation->mNumMeshChannels > 0 || animation->mNumMorphMeshChannels > 0;
        }))
        warnings << FileError::tr("mesh and morph animation is not imported; only node motion is");
    if (scene.mNumCameras > 0 || scene.mNumLights > 0)
        warnings << FileError::tr("cameras and lights are not imported");
}

// The options' settings, each the file's where the options leave it; refuses values out of range.
ImportSettings appliedSettings(const QString& path, const ImportOptions& options, const FileSettings& file)
{
    ImportSettings applied = file.values;
    if (options.fps) {
        if (!(std::isfinite(*options.fps) && *options.fps > 0.0 && *options.fps <= model::kMaxFps))
            throw InputError(path, FileError::tr("the frame rate %1 is not in (0, %2]")
                                       .arg(FileError::number(*options.fps), FileError::number(model::kMaxFps))
                                       .toStdString());
        applied.fps = *options.fps;
    }
    if (options.metresPerUnit) {
        if (!(std::isfinite(*options.metresPerUnit) && *options.metresPerUnit > 0.0))
            throw InputError(path, FileError::tr("the unit %1 m is not a positive length")
                                       .arg(FileError::number(*options.metresPerUnit))
                                       .toStdString());
        applied.metresPerUnit = *options.metresPerUnit;
    }
    applied.up = options.up.value_or(applied.up);
    return applied;
}

// Assimp scales a Collada scene's root node by the file's <unit>; Gyre applies the unit itself.
void undoColladaUnit(const QString& path, const aiScene& scene)
{
    const std::optional<double> unit = colladaMetresPerUnit(path);
    if (!unit || *unit == 1.0)
        return;
    aiMatrix4x4 inverse;
    aiMatrix4x4::Scaling(aiVector3D(static_cast<ai_real>(1.0 / *unit)), inverse);
    // The importer owns the scene and allows changing it.
    aiNode& root = *scene.mRootNode;
    root.mTransformation = inverse * root.mTransformation;
}

// Moves the animated objects' keys, and the control points of a glTF spline, by `shift` seconds.
void shiftTimes(model::Scene& scene, const std::set<model::ObjectId>& animated, double shift)
{
    for (model::SceneObject& object : scene.objects)
        if (animated.contains(object.id)) {
            for (model::Keyframe& key : object.track.keys)
                key.time += shift;
            for (HermiteControlPoint& point : object.track.sketch.fittedCurve)
                point.time += shift;
        }
}

// A Y-up scene turned Z-up, Gyre's world: yUpToZUp() before each top-level pose.
void turnYUpToZUp(model::Scene& scene)
{
    const Eigen::Quaterniond turn = yUpToZUp();
    for (model::SceneObject& object : scene.objects)
        if (object.parent == model::kNoObject) {
            for (model::Keyframe& key : object.track.keys)
                key.pose = {(turn * key.pose.orientation).normalized(), turn * key.pose.position};
            // The spline is linear in its control points, so turning them turns the curve.
            for (HermiteControlPoint& point : object.track.sketch.fittedCurve)
                point = {point.time, turn * point.value, turn * point.derivative};
        }
}

// The span of the motion: from the earliest key to the latest key or the animations' end; a still
// scene gets the span of a new project.
void setTimeRange(const std::vector<const aiAnimation*>& animations, double shift, model::Scene& scene)
{
    double start = std::numeric_limits<double>::infinity();
    double end = -std::numeric_limits<double>::infinity();
    for (const aiAnimation* animation : animations)
        end = std::max(end, animation->mDuration / ticksPerSecond(*animation) + shift);
    for (const model::SceneObject& object : scene.objects) {
        start = std::min(start, object.track.keys.front().time);
        end = std::max(end, object.track.keys.back().time);
    }
    scene.startTime = std::isfinite(start) ? start : 0.0;
    scene.endTime = std::isfinite(end) ? std::max(end, scene.startTime) : scene.startTime;
    if (!(scene.endTime > scene.startTime)) // a still scene: the span a new project has, to key in
        scene.endTime = scene.startTime + (model::Scene{}.endTime - model::Scene{}.startTime);
    scene.currentTime = scene.startTime;
}

double earliestKey(const model::Scene& scene, const std::set<model::ObjectId>& animated)
{
    double earliest = std::numeric_limits<double>::infinity();
    for (const model::SceneObject& object : scene.objects)
        if (animated.contains(object.id))
            earliest = std::min(earliest, object.track.keys.front().time);
    return earliest;
}

} // namespace

SceneImport importScene(const QString& path, const ImportOptions& options)
{
    requireReadableFile(path);
    Assimp::Importer importer;
    const aiScene& scene = readWithAssimp(importer, path);
    SceneImport result;
    result.animations = summariesOf(scene);
    TakePlan plan = chosenTakes(path, result.animations, options);
    result.takes = plan.takes;
    result.takeRule = plan.rule;
    result.warnings << plan.warnings;
    std::vector<const aiAnimation*> animations;
    for (const std::size_t index : plan.takes)
        animations.push_back(scene.mAnimations[index]);

    const SceneSource source = sourceOf(path, scene);
    result.file = fileSettingsOf(path, source, scene, animations, result.warnings);
    result.applied = appliedSettings(path, options, result.file);
    if (source == SceneSource::Collada)
        undoColladaUnit(path, scene);
    warnAboutWhatIsLeftOut(scene, animations, result.warnings);

    // TinyGLTF reads the samplers here, in the worker process like Assimp (scene_worker.h).
    const std::optional<GltfAnimations> gltf =
        source == SceneSource::Gltf && !animations.empty() ? std::optional(readGltfAnimations(path)) : std::nullopt;
    if (gltf && gltf->size() != scene.mNumAnimations)
        throw InputError(path, FileError::tr("Assimp reads %1 animations and TinyGLTF %2")
                                   .arg(scene.mNumAnimations)
                                   .arg(gltf->size())
                                   .toStdString());
    SceneBuilder builder(path, scene, animations, plan.takes, gltf ? &*gltf : nullptr, result);
    builder.build(*scene.mRootNode, result.applied.metresPerUnit);
    const double earliest = earliestKey(result.scene, builder.animatedObjects());
    if (options.timeOrigin == TimeOrigin::FirstKey && std::isfinite(earliest))
        result.timeShift = -earliest;
    shiftTimes(result.scene, builder.animatedObjects(), result.timeShift);
    if (result.applied.up == UpAxis::Y)
        turnYUpToZUp(result.scene);
    result.scene.fps = result.applied.fps;
    setTimeRange(animations, result.timeShift, result.scene);
    return result;
}

unsigned readWithAssimpOnly(const QString& path)
{
    requireReadableFile(path);
    Assimp::Importer importer;
    return readWithAssimp(importer, path).mNumAnimations;
}

QString assimpVersion()
{
    return QStringLiteral("%1.%2.%3").arg(aiGetVersionMajor()).arg(aiGetVersionMinor()).arg(aiGetVersionPatch());
}

} // namespace gyre::io
