#include "io/fbx_scene_writer.h"

#include "core/euler_angles.h"
#include "io/fbx_binary.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace gyre::io {

namespace {

using fbx::Node;

// FBX's TimeMode values of the frame rates it names (FbxTime::EMode).
constexpr std::array<std::pair<double, int>, 10> kTimeModes{{
    {120.0, 1}, {100.0, 2}, {60.0, 3}, {50.0, 4}, {48.0, 5}, {30.0, 6}, {25.0, 10}, {24.0, 11}, {96.0, 15}, {72.0, 16},
}};
constexpr int kCustomTimeMode = 14;

// Version numbers of the FBX 7.4 SDK's nodes, as its files carry them.
constexpr std::int32_t kHeaderVersion = 1003;
constexpr std::int32_t kModelVersion = 232;
constexpr std::int32_t kGeometryVersion = 124;
constexpr std::int32_t kNormalLayerVersion = 101;
constexpr std::int32_t kLayerVersion = 100;
constexpr std::int32_t kKeyVersion = 4008;
constexpr std::int32_t kDeformerVersion = 101;
constexpr std::int32_t kClusterVersion = 100;
constexpr std::int32_t kPoseVersion = 100;

// KeyAttrFlags: eInterpolationLinear. The four KeyAttrDataFloat values (slopes, weights, velocity)
// only matter to cubic keys.
constexpr std::int32_t kLinearKeyFlags = 0x4;

const char* const kTakeName = "Gyre";

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

// "name\0\1Class": how binary FBX writes an object's name and class in one string.
std::string objectName(std::string_view name, std::string_view objectClass)
{
    std::string result(name);
    result += '\0';
    result += '\1';
    result += objectClass;
    return result;
}

// An object of the Objects list: Type id, "name\0\1Class", subclass.
Node& fbxObject(Node& objects, std::string_view type, std::int64_t id, std::string_view name,
                std::string_view objectClass, std::string_view subclass)
{
    return objects.addChild(type).addInt64(id).addString(objectName(name, objectClass)).addString(subclass);
}

// A property of a Properties70 list: P "name", "type", "label", "flags", values...
Node& property(Node& properties, std::string_view name, std::string_view type, std::string_view label,
               std::string_view flags)
{
    return properties.addChild("P").addString(name).addString(type).addString(label).addString(flags);
}

void intProperty(Node& properties, std::string_view name, std::int32_t value)
{
    property(properties, name, "int", "Integer", "").addInt32(value);
}

void timeProperty(Node& properties, std::string_view name, std::int64_t ticks)
{
    property(properties, name, "KTime", "Time", "").addInt64(ticks);
}

void vectorProperty(Node& properties, std::string_view name, const Eigen::Vector3d& value, bool animated)
{
    property(properties, name, name, "", animated ? "A+" : "A")
        .addDouble(value.x())
        .addDouble(value.y())
        .addDouble(value.z());
}

Eigen::Vector3d eulerDegrees(const Eigen::Quaterniond& q)
{
    return eulerAnglesFromQuaternion(q, EulerConvention{}).angles * kDegreesPerRadian;
}

// Unique nonzero ids; 0 is the scene's root.
class Ids {
public:
    std::int64_t next() { return ++last_; }

private:
    std::int64_t last_ = 0;
};

class FbxSceneBuilder {
public:
    explicit FbxSceneBuilder(const BakedScene& scene)
        : scene_(scene)
        , animated_(std::ranges::any_of(scene.objects, [](const BakedObject& o) { return !o.samples.empty(); }))
    {
    }

    std::string file()
    {
        header();
        globalSettings();
        documents();
        root_.addChild("References");
        Node& definitions = root_.addChild("Definitions");
        Node& objects = root_.addChild("Objects");
        connections_ = &root_.addChild("Connections");
        objectsOf(objects);
        definitionsOf(definitions);
        if (animated_)
            takes();
        return fbx::encodeFile(root_);
    }

private:
    void header()
    {
        Node& extension = root_.addChild("FBXHeaderExtension");
        extension.addChild("FBXHeaderVersion").addInt32(kHeaderVersion);
        extension.addChild("FBXVersion").addInt32(static_cast<std::int32_t>(fbx::kVersion));
        extension.addChild("EncryptionType").addInt32(0);
        extension.addChild("Creator").addString("Gyre");
        const fbx::FileIdentity identity = fbx::fileIdentity();
        root_.addChild("FileId").addRaw(identity.fileId);
        root_.addChild("CreationTime").addString(identity.creationTime);
        root_.addChild("Creator").addString("Gyre");
    }

    void globalSettings()
    {
        Node& settings = root_.addChild("GlobalSettings");
        settings.addChild("Version").addInt32(1000);
        Node& properties = settings.addChild("Properties70");
        // Gyre's axes: z up (the viewport's ground is the xy plane), −y forward, x to the side.
        intProperty(properties, "UpAxis", 2);
        intProperty(properties, "UpAxisSign", 1);
        intProperty(properties, "FrontAxis", 1);
        intProperty(properties, "FrontAxisSign", -1);
        intProperty(properties, "CoordAxis", 0);
        intProperty(properties, "CoordAxisSign", 1);
        intProperty(properties, "OriginalUpAxis", 2);
        intProperty(properties, "OriginalUpAxisSign", 1);
        property(properties, "UnitScaleFactor", "double", "Number", "").addDouble(100.0);
        property(properties, "OriginalUnitScaleFactor", "double", "Number", "").addDouble(100.0);
        property(properties, "TimeMode", "enum", "", "").addInt32(fbxTimeMode(scene_.range.fps));
        timeProperty(properties, "TimeSpanStart", fbxTicks(scene_.range.start));
        timeProperty(properties, "TimeSpanStop", fbxTicks(scene_.range.end));
        property(properties, "CustomFrameRate", "double", "Number", "").addDouble(scene_.range.fps);
    }

    void documents()
    {
        Node& documents = root_.addChild("Documents");
        documents.addChild("Count").addInt32(1);
        Node& document = documents.addChild("Document").addInt64(ids_.next()).addString("").addString("Scene");
        Node& properties = document.addChild("Properties70");
        property(properties, "SourceObject", "object", "", "");
        if (animated_)
            property(properties, "ActiveAnimStackName", "KString", "", "").addString(kTakeName);
        document.addChild("RootNode").addInt64(0);
    }

    void connect(std::int64_t child, std::int64_t parent)
    {
        connections_->addChild("C").addString("OO").addInt64(child).addInt64(parent);
    }

    void connect(std::int64_t source, std::int64_t destination, std::string_view property)
    {
        connections_->addChild("C").addString("OP").addInt64(source).addInt64(destination).addString(property);
    }

    void objectsOf(Node& objects)
    {
        std::vector<std::int64_t> modelIds;
        std::unordered_map<const model::Mesh*, std::int64_t> geometryIds;
        std::vector<bool> joints(scene_.objects.size(), false);
        for (const BakedObject& object : scene_.objects)
            for (const std::size_t joint : object.skinJoints)
                joints[joint] = true;
        std::vector<std::pair<std::size_t, std::int64_t>> skinned; // object, its own geometry
        for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
            const BakedObject& object = scene_.objects[i];
            const std::int64_t id = ids_.next();
            modelIds.push_back(id);
            connect(id, object.parent ? modelIds[*object.parent] : 0);
            model(objects, object, id, joints[i] ? "LimbNode" : object.mesh ? "Mesh" : "Null");
            if (object.empty || joints[i])
                connect(nodeAttribute(objects, object.name, joints[i]), id);
            if (object.mesh && !object.skinJoints.empty()) {
                // A skin deforms a geometry: each skinned object has its own.
                skinned.emplace_back(i, geometry(objects, *object.mesh, object.name));
                connect(skinned.back().second, id);
                ++counts_["Geometry"];
            } else if (object.mesh) {
                auto [entry, isNew] = geometryIds.try_emplace(object.mesh, 0);
                if (isNew) {
                    entry->second = geometry(objects, *object.mesh, object.name);
                    ++counts_["Geometry"];
                }
                connect(entry->second, id);
            }
        }
        counts_["Model"] = static_cast<int>(modelIds.size());
        if (!skinned.empty())
            skinsOf(objects, skinned, modelIds);

        if (!animated_)
            return;
        const std::int64_t layer = animationStack(objects);
        for (std::size_t i = 0; i < scene_.objects.size(); ++i)
            if (!scene_.objects[i].samples.empty())
                motion(objects, scene_.objects[i].samples, modelIds[i], layer);
    }

    void model(Node& objects, const BakedObject& object, std::int64_t id, std::string_view subclass)
    {
        const bool animated = !object.samples.empty();
        Node& model = fbxObject(objects, "Model", id, object.name, "Model", subclass);
        model.addChild("Version").addInt32(kModelVersion);
        Node& properties = model.addChild("Properties70");
        vectorProperty(properties, "Lcl Translation", object.startPose.position, animated);
        vectorProperty(properties, "Lcl Rotation", eulerDegrees(object.startPose.orientation), animated);
        vectorProperty(properties, "Lcl Scaling", Eigen::Vector3d::Ones(), false);
        model.addChild("Shading").addBool(true);
        model.addChild("Culling").addString("CullingOff");
    }

    // The NodeAttribute of an Empty (Null, as Blender writes its Empties: its importer makes a Null Model
    // with it an Empty, one without any too) or of a skin's joint (LimbNode, TypeFlags Skeleton: a bone).
    // Assimp reads either Model as a node without meshes.
    std::int64_t nodeAttribute(Node& objects, const std::string& name, bool joint)
    {
        const std::int64_t id = ids_.next();
        Node& attribute = fbxObject(objects, "NodeAttribute", id, name, "NodeAttribute", joint ? "LimbNode" : "Null");
        attribute.addChild("TypeFlags").addString(joint ? "Skeleton" : "Null");
        ++counts_["NodeAttribute"];
        return id;
    }

    // Each object's world pose at the start time, the pose its skin is bound in here.
    std::vector<Pose> startWorldPoses() const
    {
        std::vector<Pose> world;
        for (const BakedObject& object : scene_.objects)
            world.push_back(object.parent ? world[*object.parent] * object.startPose : object.startPose);
        return world;
    }

    static Eigen::Matrix4d poseMatrix(const Pose& pose)
    {
        Eigen::Matrix4d matrix = Eigen::Matrix4d::Identity();
        matrix.topLeftCorner<3, 3>() = pose.orientation.normalized().toRotationMatrix();
        matrix.topRightCorner<3, 1>() = pose.position;
        return matrix;
    }

    static std::vector<double> matrixOf(const Eigen::Matrix4d& matrix)
    {
        return std::vector<double>(matrix.data(), matrix.data() + 16); // column-major: translation at 12, 13, 14
    }

    // For each skinned object and its geometry: a Deformer Skin on the geometry and a SubDeformer Cluster per
    // joint: Indexes and Weights of the positions it moves, Transform the inverse bind B_j (from the mesh's
    // frame to the joint's, as Blender writes it and Assimp reads it as the bone's offset) and TransformLink
    // the joint's world matrix at binding, M · B_j⁻¹ with the mesh's world pose M at the start time; then
    // one BindPose with the world matrices at binding of the meshes and joints.
    void skinsOf(Node& objects, const std::vector<std::pair<std::size_t, std::int64_t>>& skinned,
                 const std::vector<std::int64_t>& modelIds)
    {
        const std::vector<Pose> world = startWorldPoses();
        std::map<std::int64_t, Eigen::Matrix4d> bindMatrices; // model id -> world matrix at binding
        for (const auto& [index, geometryId] : skinned) {
            const BakedObject& object = scene_.objects[index];
            const model::Skin& skin = object.mesh->skin;
            const Eigen::Matrix4d mesh = poseMatrix(world[index]);
            bindMatrices[modelIds[index]] = mesh;
            const std::int64_t skinId = ids_.next();
            Node& deformer = fbxObject(objects, "Deformer", skinId, object.name, "Deformer", "Skin");
            deformer.addChild("Version").addInt32(kDeformerVersion);
            deformer.addChild("Link_DeformAcuracy").addDouble(50.0);
            connect(skinId, geometryId);
            ++counts_["Deformer"];
            const std::vector<std::vector<JointInfluence>> influences = jointInfluences(skin);
            for (std::size_t j = 0; j < object.skinJoints.size(); ++j) {
                std::vector<std::int32_t> indexes;
                std::vector<double> weights;
                for (const JointInfluence& influence : influences[j]) {
                    indexes.push_back(static_cast<std::int32_t>(influence.vertex));
                    weights.push_back(influence.weight);
                }
                const std::size_t joint = object.skinJoints[j];
                const Eigen::Matrix4d link = mesh * skin.inverseBinds[j].cast<double>().inverse();
                bindMatrices[modelIds[joint]] = link;
                const std::int64_t clusterId = ids_.next();
                Node& cluster = fbxObject(objects, "Deformer", clusterId, scene_.objects[joint].name, "SubDeformer", "Cluster");
                cluster.addChild("Version").addInt32(kClusterVersion);
                cluster.addChild("UserData").addString("").addString("");
                cluster.addChild("Indexes").addArray(std::span<const std::int32_t>(indexes));
                cluster.addChild("Weights").addArray(std::span<const double>(weights));
                cluster.addChild("Transform").addArray(std::span<const double>(matrixOf(skin.inverseBinds[j].cast<double>())));
                cluster.addChild("TransformLink").addArray(std::span<const double>(matrixOf(link)));
                connect(clusterId, skinId);
                connect(modelIds[joint], clusterId);
                ++counts_["Deformer"];
            }
        }
        const std::int64_t poseId = ids_.next();
        Node& pose = fbxObject(objects, "Pose", poseId, "BindPose", "Pose", "BindPose");
        pose.addChild("Type").addString("BindPose");
        pose.addChild("Version").addInt32(kPoseVersion);
        pose.addChild("NbPoseNodes").addInt32(static_cast<std::int32_t>(bindMatrices.size()));
        for (const auto& [modelId, matrix] : bindMatrices) {
            Node& poseNode = pose.addChild("PoseNode");
            poseNode.addChild("Node").addInt64(modelId);
            poseNode.addChild("Matrix").addArray(std::span<const double>(matrixOf(matrix)));
        }
        counts_["Pose"] = 1;
    }

    std::int64_t geometry(Node& objects, const model::Mesh& mesh, const std::string& name)
    {
        const std::int64_t id = ids_.next();
        Node& geometry = fbxObject(objects, "Geometry", id, name, "Geometry", "Mesh");
        geometry.addChild("GeometryVersion").addInt32(kGeometryVersion);
        geometry.addChild("Vertices").addArray(std::span<const double>(coordinates(mesh.positions)));
        // Corners are int32 in FBX; whole triangles only.
        if (mesh.positions.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
            throw std::length_error("a mesh has more vertices than FBX can index");
        std::vector<std::int32_t> corners;
        corners.reserve(mesh.indices.size());
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
            for (std::size_t k = i; k < i + 3; ++k)
                corners.push_back(static_cast<std::int32_t>(mesh.indices[k]));
        for (std::size_t last = 2; last < corners.size(); last += 3)
            corners[last] = -corners[last] - 1; // a polygon's last corner is written as its bitwise complement
        geometry.addChild("PolygonVertexIndex").addArray(std::span<const std::int32_t>(corners));
        if (mesh.normals.size() == mesh.positions.size() && !mesh.normals.empty()) {
            Node& normals = geometry.addChild("LayerElementNormal").addInt32(0);
            normals.addChild("Version").addInt32(kNormalLayerVersion);
            normals.addChild("Name").addString("");
            normals.addChild("MappingInformationType").addString("ByVertice");
            normals.addChild("ReferenceInformationType").addString("Direct");
            normals.addChild("Normals").addArray(std::span<const double>(coordinates(mesh.normals)));
            Node& layer = geometry.addChild("Layer").addInt32(0);
            layer.addChild("Version").addInt32(kLayerVersion);
            Node& element = layer.addChild("LayerElement");
            element.addChild("Type").addString("LayerElementNormal");
            element.addChild("TypedIndex").addInt32(0);
        }
        return id;
    }

    static std::vector<double> coordinates(const std::vector<Eigen::Vector3f>& points)
    {
        std::vector<double> result;
        result.reserve(3 * points.size());
        for (const Eigen::Vector3f& p : points)
            result.insert(result.end(), {p.x(), p.y(), p.z()});
        return result;
    }

    // The stack and its one layer; returns the layer's id.
    std::int64_t animationStack(Node& objects)
    {
        const std::int64_t stackId = ids_.next();
        Node& stack = fbxObject(objects, "AnimationStack", stackId, kTakeName, "AnimStack", "");
        Node& properties = stack.addChild("Properties70");
        const auto [start, stop] = stackSpan();
        timeProperty(properties, "LocalStart", start);
        timeProperty(properties, "LocalStop", stop);
        timeProperty(properties, "ReferenceStart", start);
        timeProperty(properties, "ReferenceStop", stop);
        const std::int64_t layerId = ids_.next();
        // An empty property list: the FBX SDK expects a layer's nested list even when it holds nothing.
        fbxObject(objects, "AnimationLayer", layerId, kTakeName, "AnimLayer", "").addChild("Properties70");
        connect(layerId, stackId);
        counts_["AnimationStack"] = 1;
        counts_["AnimationLayer"] = 1;
        return layerId;
    }

    std::pair<std::int64_t, std::int64_t> stackSpan() const
    {
        return {fbxTicks(std::min(0.0, scene_.range.start)), fbxTicks(scene_.range.end)};
    }

    void motion(Node& objects, const std::vector<model::TimedPose>& samples, std::int64_t modelId, std::int64_t layerId)
    {
        std::vector<std::int64_t> times;
        std::vector<Eigen::Quaterniond> rotations;
        times.reserve(samples.size());
        rotations.reserve(samples.size());
        for (const model::TimedPose& sample : samples) {
            times.push_back(fbxTicks(sample.time));
            rotations.push_back(sample.pose.orientation);
        }
        std::vector<Eigen::Vector3d> positions;
        positions.reserve(samples.size());
        for (const model::TimedPose& sample : samples)
            positions.push_back(sample.pose.position);
        std::vector<Eigen::Vector3d> angles = unwrappedEulerAngles(rotations, EulerConvention{});
        for (Eigen::Vector3d& a : angles)
            a *= kDegreesPerRadian;
        curveNode(objects, "T", "Lcl Translation", times, positions, modelId, layerId);
        curveNode(objects, "R", "Lcl Rotation", times, angles, modelId, layerId);
    }

    void curveNode(Node& objects, std::string_view name, std::string_view target, const std::vector<std::int64_t>& times,
                   const std::vector<Eigen::Vector3d>& values, std::int64_t modelId, std::int64_t layerId)
    {
        static constexpr std::array<std::string_view, 3> kChannels{"d|X", "d|Y", "d|Z"};
        const std::int64_t id = ids_.next();
        Node& node = fbxObject(objects, "AnimationCurveNode", id, name, "AnimCurveNode", "");
        Node& properties = node.addChild("Properties70");
        for (int axis = 0; axis < 3; ++axis)
            property(properties, kChannels[axis], "Number", "", "A").addDouble(values.front()[axis]);
        connect(id, layerId);
        connect(id, modelId, target);
        ++counts_["AnimationCurveNode"];
        std::vector<float> channel(values.size());
        for (int axis = 0; axis < 3; ++axis) {
            for (std::size_t k = 0; k < values.size(); ++k)
                channel[k] = static_cast<float>(values[k][axis]);
            connect(curve(objects, times, channel), id, kChannels[axis]);
        }
    }

    std::int64_t curve(Node& objects, const std::vector<std::int64_t>& times, const std::vector<float>& values)
    {
        const std::int64_t id = ids_.next();
        Node& curve = fbxObject(objects, "AnimationCurve", id, "", "AnimCurve", "");
        curve.addChild("Default").addDouble(values.front());
        curve.addChild("KeyVer").addInt32(kKeyVersion);
        curve.addChild("KeyTime").addArray(std::span<const std::int64_t>(times));
        curve.addChild("KeyValueFloat").addArray(std::span<const float>(values));
        // One attribute shared by every key.
        const std::array<std::int32_t, 1> flags{kLinearKeyFlags};
        const std::array<float, 4> data{};
        const std::array<std::int32_t, 1> sharedBy{static_cast<std::int32_t>(values.size())};
        curve.addChild("KeyAttrFlags").addArray(std::span<const std::int32_t>(flags));
        curve.addChild("KeyAttrDataFloat").addArray(std::span<const float>(data));
        curve.addChild("KeyAttrRefCount").addArray(std::span<const std::int32_t>(sharedBy));
        ++counts_["AnimationCurve"];
        return id;
    }

    void definitionsOf(Node& definitions)
    {
        int total = 1; // GlobalSettings
        for (const auto& [type, count] : counts_)
            total += count;
        definitions.addChild("Version").addInt32(100);
        definitions.addChild("Count").addInt32(total);
        definitions.addChild("ObjectType").addString("GlobalSettings").addChild("Count").addInt32(1);
        for (const auto& [type, count] : counts_)
            if (count > 0)
                definitions.addChild("ObjectType").addString(type).addChild("Count").addInt32(count);
    }

    void takes()
    {
        Node& takes = root_.addChild("Takes");
        takes.addChild("Current").addString(kTakeName);
        Node& take = takes.addChild("Take").addString(kTakeName);
        take.addChild("FileName").addString(std::string(kTakeName) + ".tak");
        const auto [start, stop] = stackSpan();
        take.addChild("LocalTime").addInt64(start).addInt64(stop);
        take.addChild("ReferenceTime").addInt64(start).addInt64(stop);
    }

    const BakedScene& scene_;
    const bool animated_; // whether any object moves: then the file has an animation stack
    Node root_{""};
    Node* connections_ = nullptr;
    Ids ids_;
    std::map<std::string, int> counts_; // objects of each type, for Definitions
};

} // namespace

std::int64_t fbxTicks(double seconds) { return std::llround(seconds * static_cast<double>(kFbxTicksPerSecond)); }

int fbxTimeMode(double fps)
{
    for (const auto& [rate, mode] : kTimeModes)
        if (fps == rate)
            return mode;
    return kCustomTimeMode;
}

std::string fbxSceneFile(const BakedScene& scene)
{
    // Ticks are 64-bit integers: about 6 years either side of zero.
    constexpr double kLongestSeconds = 1e8;
    if (!(std::abs(scene.range.start) <= kLongestSeconds && std::abs(scene.range.end) <= kLongestSeconds))
        throw std::length_error("its time range passes 10^8 s, beyond what FBX's 64-bit ticks hold");
    return FbxSceneBuilder(scene).file();
}

} // namespace gyre::io
