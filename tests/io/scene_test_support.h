#pragma once
// Helpers shared by the scene import and export tests: Assimp scenes written in code (in Assimp's own
// binary format, assbin, which keeps doubles, ticks per second and even NaN exactly as given), scenes
// of Gyre objects, and comparisons of meshes that do not depend on the order of vertices or faces.

#include "core/core_test_support.h"
#include "model/scene.h"

#include <assimp/Exporter.hpp>
#include <assimp/scene.h>

#include <QFile>
#include <QString>
#include <QTest>

#include <algorithm>
#include <array>
#include <memory>
#include <vector>

namespace gyre::test {

// Writes `scene` in Assimp's binary format; fails the test if Assimp cannot.
inline void writeAssbin(const aiScene& scene, const QString& path)
{
    Assimp::Exporter exporter;
    QCOMPARE(exporter.Export(&scene, "assbin", QFile::encodeName(path).toStdString()), aiReturn_SUCCESS);
}

inline aiNode* addNode(aiNode& parent, const char* name, const aiMatrix4x4& transform = {})
{
    auto* node = new aiNode(name);
    node->mTransformation = transform;
    parent.addChildren(1, &node);
    return node;
}

// An empty Assimp scene: a root node and one material, marked incomplete so that it needs no mesh.
inline std::unique_ptr<aiScene> emptyAssimpScene()
{
    auto scene = std::make_unique<aiScene>();
    scene->mRootNode = new aiNode("root");
    scene->mNumMaterials = 1;
    scene->mMaterials = new aiMaterial*[1]{new aiMaterial};
    scene->mFlags |= AI_SCENE_FLAGS_INCOMPLETE;
    return scene;
}

// A single triangle (0,0,0), (1,0,0), (0,1,0) moved by `offset`, facing +z.
inline aiMesh* triangleMesh(const aiVector3D& offset)
{
    auto* mesh = new aiMesh;
    mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    mesh->mNumVertices = 3;
    mesh->mVertices = new aiVector3D[3]{offset, offset + aiVector3D(1, 0, 0), offset + aiVector3D(0, 1, 0)};
    mesh->mNumFaces = 1;
    mesh->mFaces = new aiFace[1];
    mesh->mFaces[0].mNumIndices = 3;
    mesh->mFaces[0].mIndices = new unsigned[3]{0, 1, 2};
    return mesh;
}

inline void setMeshes(aiScene& scene, std::vector<aiMesh*> meshes)
{
    scene.mNumMeshes = static_cast<unsigned>(meshes.size());
    scene.mMeshes = new aiMesh*[meshes.size()];
    std::copy(meshes.begin(), meshes.end(), scene.mMeshes);
    scene.mFlags &= ~static_cast<unsigned>(AI_SCENE_FLAGS_INCOMPLETE);
}

inline void attachMeshes(aiNode& node, std::vector<unsigned> indices)
{
    node.mNumMeshes = static_cast<unsigned>(indices.size());
    node.mMeshes = new unsigned[indices.size()];
    std::copy(indices.begin(), indices.end(), node.mMeshes);
}

inline aiNodeAnim* nodeAnimation(const char* node, std::vector<aiQuatKey> rotations, std::vector<aiVectorKey> positions)
{
    auto* channel = new aiNodeAnim;
    channel->mNodeName.Set(node);
    channel->mNumRotationKeys = static_cast<unsigned>(rotations.size());
    channel->mRotationKeys = new aiQuatKey[rotations.size()];
    std::copy(rotations.begin(), rotations.end(), channel->mRotationKeys);
    channel->mNumPositionKeys = static_cast<unsigned>(positions.size());
    channel->mPositionKeys = new aiVectorKey[positions.size()];
    std::copy(positions.begin(), positions.end(), channel->mPositionKeys);
    return channel;
}

inline aiAnimation* animation(const char* name, double ticksPerSecond, double duration, std::vector<aiNodeAnim*> channels)
{
    auto* result = new aiAnimation;
    result->mName.Set(name);
    result->mTicksPerSecond = ticksPerSecond;
    result->mDuration = duration;
    result->mNumChannels = static_cast<unsigned>(channels.size());
    result->mChannels = new aiNodeAnim*[channels.size()];
    std::copy(channels.begin(), channels.end(), result->mChannels);
    return result;
}

inline void setAnimations(aiScene& scene, std::vector<aiAnimation*> animations)
{
    scene.mNumAnimations = static_cast<unsigned>(animations.size());
    scene.mAnimations = new aiAnimation*[animations.size()];
    std::copy(animations.begin(), animations.end(), scene.mAnimations);
}

inline aiQuaternion aboutZ(double angle)
{
    return aiQuaternion(static_cast<ai_real>(std::cos(angle / 2)), 0, 0, static_cast<ai_real>(std::sin(angle / 2)));
}

// --- comparing meshes -----------------------------------------------------------------------------

using Triangle = std::array<Eigen::Vector3d, 3>;

// The mesh's triangles in `pose`, each started at its lexicographically smallest corner (winding
// kept), sorted: equal for the same surface whatever the vertex and face order.
inline std::vector<Triangle> canonicalTriangles(const model::Mesh& mesh, const Pose& pose = {})
{
    const auto less = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
        return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
    };
    std::vector<Triangle> triangles;
    for (std::size_t f = 0; f + 2 < mesh.indices.size(); f += 3) {
        Triangle t;
        for (std::size_t k = 0; k < 3; ++k)
            t[k] = pose.apply(mesh.positions[mesh.indices[f + k]].cast<double>());
        const auto first = std::min_element(t.begin(), t.end(), less);
        std::rotate(t.begin(), first, t.end());
        triangles.push_back(t);
    }
    std::sort(triangles.begin(), triangles.end(), [&less](const Triangle& a, const Triangle& b) {
        return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), less);
    });
    return triangles;
}

// The largest distance between corresponding corners; infinite when the counts differ.
inline double triangleDistance(const std::vector<Triangle>& a, const std::vector<Triangle>& b)
{
    if (a.size() != b.size())
        return std::numeric_limits<double>::infinity();
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t k = 0; k < 3; ++k)
            worst = std::max(worst, (a[i][k] - b[i][k]).norm());
    return worst;
}

} // namespace gyre::test
