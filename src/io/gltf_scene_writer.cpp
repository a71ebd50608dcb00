#include "io/gltf_scene_writer.h"

#include <tiny_gltf.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QUrl>

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace gyre::io {

namespace {

// The glTF buffer view targets of vertex attributes and of indices.
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

// As glTF orders them: a quaternion x, y, z, w; a vector x, y, z.
std::vector<double> components(const Eigen::Quaterniond& q) { return {q.x(), q.y(), q.z(), q.w()}; }
std::vector<double> components(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

// JOINTS_0 and WEIGHTS_0 of a skinned mesh, four of each per position, and whether a position uses the
// extra joint: glTF asks that a position's weights sum to 1, and Skin lets the rest of the weight, where
// they sum to less, follow the mesh's own object. That rest goes to joint skin.joints.size(), which each
// skin of the mesh makes the object's own node, with the identity as its inverse bind matrix: glTF moves
// it by that node's world pose, as Gyre does. A position with no free slot for it (four joints summing to
// less than 1, which no import makes) has its weights scaled to sum 1.
struct SkinAttributes {
    std::vector<std::uint16_t> joints;
    std::vector<float> weights;
    bool ownJoint = false;
};

SkinAttributes skinAttributes(const model::Skin& skin)
{
    // A rest below this is float32 rounding of weights that sum to 1, which the largest weight absorbs.
    constexpr double kRounding = 1e-6;
    SkinAttributes result;
    for (std::size_t v = 0; v < skin.vertexWeights.size(); ++v) {
        std::array<std::uint16_t, 4> joints = skin.vertexJoints[v];
        Eigen::Vector4f weights = skin.vertexWeights[v];
        const double rest = 1.0 - static_cast<double>(weights.sum());
        const auto free = std::find(weights.data(), weights.data() + 4, 0.0F) - weights.data();
        if (rest > kRounding && free < 4) {
            joints[static_cast<std::size_t>(free)] = static_cast<std::uint16_t>(skin.joints.size());
            weights[free] = static_cast<float>(rest);
            result.ownJoint = true;
        } else if (rest > kRounding) {
            weights /= weights.sum();
        }
        // The largest weight takes what float32 rounding left over.
        Eigen::Index largest = 0;
        weights.maxCoeff(&largest);
        weights[largest] = static_cast<float>(static_cast<double>(weights[largest]) + 1.0 -
                                              static_cast<double>(weights.cast<double>().sum()));
        for (int k = 0; k < 4; ++k) {
            result.joints.push_back(weights[k] > 0.0F ? joints[static_cast<std::size_t>(k)] : 0);
            result.weights.push_back(weights[k]);
        }
    }
    return result;
}

// The model under construction: one buffer, one buffer view per accessor.
class GltfModelBuilder {
public:
    GltfModelBuilder()
    {
        model_.asset.version = "2.0";
        model_.asset.generator = "Gyre";
        model_.buffers.emplace_back();
    }

    // An accessor over `floats`, `components` per element (TINYGLTF_TYPE_* in `type`), with the
    // per-component bounds when `bounds` (positions and animation inputs must have them).
    int floatAccessor(const std::vector<float>& floats, int components, int type, bool bounds, int target = 0)
    {
        const std::size_t count = floats.size() / static_cast<std::size_t>(components);
        const int view = addView(floats.data(), floats.size() * sizeof(float), target);
        tinygltf::Accessor accessor;
        accessor.bufferView = view;
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.count = count;
        accessor.type = type;
        if (bounds) {
            accessor.minValues.assign(static_cast<std::size_t>(components), std::numeric_limits<double>::infinity());
            accessor.maxValues.assign(static_cast<std::size_t>(components), -std::numeric_limits<double>::infinity());
            for (std::size_t i = 0; i < floats.size(); ++i) {
                const std::size_t c = i % static_cast<std::size_t>(components);
                accessor.minValues[c] = std::min(accessor.minValues[c], static_cast<double>(floats[i]));
                accessor.maxValues[c] = std::max(accessor.maxValues[c], static_cast<double>(floats[i]));
            }
        }
        model_.accessors.push_back(std::move(accessor));
        return static_cast<int>(model_.accessors.size()) - 1;
    }

    int indexAccessor(const std::vector<std::uint32_t>& indices)
    {
        tinygltf::Accessor accessor;
        accessor.bufferView = addView(indices.data(), indices.size() * sizeof(std::uint32_t), kElementArrayBuffer);
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        accessor.count = indices.size();
        accessor.type = TINYGLTF_TYPE_SCALAR;
        model_.accessors.push_back(std::move(accessor));
        return static_cast<int>(model_.accessors.size()) - 1;
    }

    // A vertex attribute of VEC4 elements over `values`, of `componentType` (TINYGLTF_COMPONENT_TYPE_*).
    template <class Value>
    int vertexAccessor(const std::vector<Value>& values, int componentType)
    {
        tinygltf::Accessor accessor;
        accessor.bufferView = addView(values.data(), values.size() * sizeof(Value), kArrayBuffer);
        accessor.componentType = componentType;
        accessor.count = values.size() / 4;
        accessor.type = TINYGLTF_TYPE_VEC4;
        model_.accessors.push_back(std::move(accessor));
        return static_cast<int>(model_.accessors.size()) - 1;
    }

    // The mesh, with JOINTS_0 and WEIGHTS_0 when `skinned` (skinAttributes); returns its index and whether
    // its skins need the extra joint of the mesh's own node.
    std::pair<int, bool> mesh(const model::Mesh& source, bool skinned)
    {
        std::vector<float> positions;
        for (const Eigen::Vector3f& p : source.positions)
            positions.insert(positions.end(), {p.x(), p.y(), p.z()});
        tinygltf::Primitive primitive;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        primitive.material = 0;
        primitive.attributes["POSITION"] = floatAccessor(positions, 3, TINYGLTF_TYPE_VEC3, true, kArrayBuffer);
        if (source.normals.size() == source.positions.size()) {
            std::vector<float> normals;
            for (const Eigen::Vector3f& n : source.normals)
                normals.insert(normals.end(), {n.x(), n.y(), n.z()});
            primitive.attributes["NORMAL"] = floatAccessor(normals, 3, TINYGLTF_TYPE_VEC3, false, kArrayBuffer);
        }
        primitive.indices = indexAccessor(source.indices);
        bool ownJoint = false;
        if (skinned) {
            SkinAttributes skin = skinAttributes(source.skin);
            primitive.attributes["JOINTS_0"] = vertexAccessor(skin.joints, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
            primitive.attributes["WEIGHTS_0"] = vertexAccessor(skin.weights, TINYGLTF_COMPONENT_TYPE_FLOAT);
            ownJoint = skin.ownJoint;
        }
        tinygltf::Mesh mesh;
        mesh.primitives.push_back(std::move(primitive));
        model_.meshes.push_back(std::move(mesh));
        return {static_cast<int>(model_.meshes.size()) - 1, ownJoint};
    }

    tinygltf::Model& model() { return model_; }

private:
    // A buffer view over a copy of `bytes`, starting on a 4-byte boundary as glTF asks.
    int addView(const void* bytes, std::size_t size, int target)
    {
        std::vector<unsigned char>& data = model_.buffers[0].data;
        data.resize((data.size() + 3) / 4 * 4, 0);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = data.size();
        view.byteLength = size;
        view.target = target;
        data.resize(data.size() + size);
        if (size > 0)
            std::memcpy(data.data() + view.byteOffset, bytes, size);
        model_.bufferViews.push_back(std::move(view));
        return static_cast<int>(model_.bufferViews.size()) - 1;
    }

    tinygltf::Model model_;
};

// A sampler of `input` times and `output` values, and the channel that drives the node's `path` with it.
void addChannel(tinygltf::Animation& animation, int input, int output, const char* interpolation, int node,
                const char* path)
{
    tinygltf::AnimationSampler sampler;
    sampler.input = input;
    sampler.output = output;
    sampler.interpolation = interpolation;
    animation.samplers.push_back(std::move(sampler));
    tinygltf::AnimationChannel channel;
    channel.sampler = static_cast<int>(animation.samplers.size()) - 1;
    channel.target_node = node;
    channel.target_path = path;
    animation.channels.push_back(std::move(channel));
}

// A CUBICSPLINE channel through `keys`: their times, and for each key its in-tangent, value and
// out-tangent, `count` components each (TINYGLTF_TYPE_* in `type`).
template <class Value>
void addSplineChannel(GltfModelBuilder& builder, tinygltf::Animation& animation,
                      const std::vector<SplineKeyOf<Value>>& keys, int count, int type, int node, const char* path)
{
    std::vector<float> times;
    std::vector<float> values;
    for (const SplineKeyOf<Value>& key : keys) {
        times.push_back(static_cast<float>(key.time));
        for (const Value* part : {&key.inDerivative, &key.value, &key.outDerivative})
            for (const double c : components(*part))
                values.push_back(static_cast<float>(c));
    }
    const int input = builder.floatAccessor(times, 1, TINYGLTF_TYPE_SCALAR, true);
    const int output = builder.floatAccessor(values, count, type, false);
    addChannel(animation, input, output, "CUBICSPLINE", node, path);
}

// The object's motion as samplers and channels of `animation`: each of translation and rotation as its
// spline where the object has one, else LINEAR at the baked samples.
void addMotion(GltfModelBuilder& builder, tinygltf::Animation& animation, const BakedObject& object, int node)
{
    std::vector<float> times;
    std::vector<float> positions;
    std::vector<float> rotations;
    Eigen::Quaterniond previous = object.samples.front().pose.orientation;
    for (const model::TimedPose& sample : object.samples) {
        times.push_back(static_cast<float>(sample.time));
        for (const double c : components(sample.pose.position))
            positions.push_back(static_cast<float>(c));
        Eigen::Quaterniond q = sample.pose.orientation.normalized();
        if (q.coeffs().dot(previous.coeffs()) < 0.0)
            q.coeffs() = -q.coeffs();
        previous = q;
        for (const double c : components(q))
            rotations.push_back(static_cast<float>(c));
    }
    const bool sampled = object.positionSpline.empty() || object.rotationSpline.empty();
    const int input = sampled ? builder.floatAccessor(times, 1, TINYGLTF_TYPE_SCALAR, true) : -1;
    if (object.positionSpline.empty())
        addChannel(animation, input, builder.floatAccessor(positions, 3, TINYGLTF_TYPE_VEC3, false), "LINEAR", node,
                   "translation");
    else
        addSplineChannel(builder, animation, object.positionSpline, 3, TINYGLTF_TYPE_VEC3, node, "translation");
    if (object.rotationSpline.empty())
        addChannel(animation, input, builder.floatAccessor(rotations, 4, TINYGLTF_TYPE_VEC4, false), "LINEAR", node,
                   "rotation");
    else
        addSplineChannel(builder, animation, object.rotationSpline, 4, TINYGLTF_TYPE_VEC4, node, "rotation");
}

// The skin of the object at node `node`: its joints' nodes (node i + 1 is object i) and their inverse bind
// matrices, then its own node with the identity when `ownJoint` (skinAttributes). Returns its index.
int addSkin(GltfModelBuilder& builder, const BakedObject& object, int node, bool ownJoint)
{
    tinygltf::Skin skin;
    std::vector<float> inverseBinds;
    const auto addJoint = [&](int jointNode, const Eigen::Matrix4f& inverseBind) {
        skin.joints.push_back(jointNode);
        inverseBinds.insert(inverseBinds.end(), inverseBind.data(), inverseBind.data() + 16); // column-major, as glTF
    };
    for (std::size_t j = 0; j < object.skinJoints.size(); ++j)
        addJoint(static_cast<int>(object.skinJoints[j] + 1), object.mesh->skin.inverseBinds[j]);
    if (ownJoint)
        addJoint(node, Eigen::Matrix4f::Identity());
    skin.inverseBindMatrices = builder.floatAccessor(inverseBinds, 16, TINYGLTF_TYPE_MAT4, false);
    tinygltf::Model& model = builder.model();
    model.skins.push_back(std::move(skin));
    return static_cast<int>(model.skins.size()) - 1;
}

tinygltf::Model modelOf(const BakedScene& baked)
{
    GltfModelBuilder builder;
    tinygltf::Model& model = builder.model();
    tinygltf::Material material;
    material.name = "Gyre default";
    material.pbrMetallicRoughness.baseColorFactor = {0.7, 0.7, 0.7, 1.0};
    model.materials.push_back(std::move(material));

    tinygltf::Node root;
    root.name = "GyreScene";
    model.nodes.push_back(std::move(root));
    // Each mesh once, and once more for the objects that skin it.
    std::map<std::pair<const model::Mesh*, bool>, std::pair<int, bool>> meshes;
    for (std::size_t i = 0; i < baked.objects.size(); ++i) {
        const BakedObject& object = baked.objects[i];
        tinygltf::Node node;
        node.name = object.name;
        node.translation = {object.startPose.position.x(), object.startPose.position.y(), object.startPose.position.z()};
        node.rotation = components(object.startPose.orientation.normalized());
        if (object.mesh) {
            const bool skinned = !object.skinJoints.empty();
            const auto [entry, isNew] = meshes.try_emplace({object.mesh, skinned});
            if (isNew)
                entry->second = builder.mesh(*object.mesh, skinned);
            node.mesh = entry->second.first;
            if (skinned)
                node.skin = addSkin(builder, object, static_cast<int>(i + 1), entry->second.second);
        }
        model.nodes.push_back(std::move(node));
    }
    // Node i + 1 is object i; the root is node 0.
    for (std::size_t i = 0; i < baked.objects.size(); ++i) {
        const std::size_t parent = baked.objects[i].parent ? *baked.objects[i].parent + 1 : 0;
        model.nodes[parent].children.push_back(static_cast<int>(i + 1));
    }
    tinygltf::Scene scene;
    scene.nodes = {0};
    model.scenes.push_back(std::move(scene));
    model.defaultScene = 0;

    tinygltf::Animation animation;
    animation.name = "Gyre";
    for (std::size_t i = 0; i < baked.objects.size(); ++i)
        if (!baked.objects[i].samples.empty())
            addMotion(builder, animation, baked.objects[i], static_cast<int>(i + 1));
    if (!animation.channels.empty())
        model.animations.push_back(std::move(animation));
    if (model.buffers[0].data.empty())
        model.buffers.clear();
    return std::move(model);
}

} // namespace

GltfFiles gltfSceneFiles(const BakedScene& baked, bool binary, const QString& binName)
{
    tinygltf::Model model = modelOf(baked);
    std::vector<unsigned char> bin;
    if (!binary && !model.buffers.empty())
        bin.swap(model.buffers[0].data);
    std::ostringstream stream;
    tinygltf::TinyGLTF writer;
    // TinyGLTF would embed the buffer as a data URI: it is written empty and then named in the JSON.
    if (!writer.WriteGltfSceneToStream(&model, stream, !binary, binary))
        throw std::runtime_error("TinyGLTF cannot write the model");
    const std::string text = stream.str();
    GltfFiles files{QByteArray(text.data(), static_cast<qsizetype>(text.size())), {}};
    if (binary || model.buffers.empty())
        return files;
    QJsonObject json = QJsonDocument::fromJson(files.main).object();
    const QJsonObject buffer{{QStringLiteral("byteLength"), static_cast<qint64>(bin.size())},
                             {QStringLiteral("uri"), QString::fromLatin1(QUrl::toPercentEncoding(binName))}};
    json[QStringLiteral("buffers")] = QJsonArray{buffer};
    files.main = QJsonDocument(json).toJson(QJsonDocument::Indented);
    files.bin = QByteArray(reinterpret_cast<const char*>(bin.data()), static_cast<qsizetype>(bin.size()));
    return files;
}

} // namespace gyre::io
