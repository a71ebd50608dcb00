#include "io/scene_import_skin.h"

#include "io/scene_import.h"
#include "model/value_checks.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace gyre::io {

namespace {

Eigen::Matrix4d toEigen(const aiMatrix4x4& m)
{
    Eigen::Matrix4d matrix;
    matrix << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
    return matrix;
}

Eigen::Matrix4d scaling(const Eigen::Vector3d& scale)
{
    return Eigen::Vector4d(scale.x(), scale.y(), scale.z(), 1.0).asDiagonal();
}

QString nameOf(const aiString& name) { return QString::fromUtf8(name.data, static_cast<qsizetype>(name.length)); }

} // namespace

void PendingSkin::addBones(const aiMesh& part, std::uint32_t base, const QString& path)
{
    for (unsigned b = 0; b < part.mNumBones; ++b) {
        const aiBone& bone = *part.mBones[b];
        const std::string name(bone.mName.data, bone.mName.length);
        const auto known = std::find(jointNames_.begin(), jointNames_.end(), name);
        const auto joint = static_cast<std::size_t>(known - jointNames_.begin());
        if (known == jointNames_.end()) {
            jointNames_.push_back(name);
            offsets_.push_back(toEigen(bone.mOffsetMatrix));
        }
        const auto fail = [&](const QString& problem) {
            return InputError(path, FileError::tr("mesh '%1', bone '%2': %3")
                                        .arg(nameOf(part.mName), nameOf(bone.mName), problem)
                                        .toStdString());
        };
        if (!offsets_[joint].allFinite())
            throw fail(FileError::tr("its offset matrix is not finite"));
        for (unsigned w = 0; w < bone.mNumWeights; ++w) {
            const aiVertexWeight& weight = bone.mWeights[w];
            if (weight.mVertexId >= part.mNumVertices)
                throw fail(FileError::tr("weight %1 names vertex %2 of %3").arg(w).arg(weight.mVertexId).arg(part.mNumVertices));
            if (!(std::isfinite(weight.mWeight) && weight.mWeight >= 0.0F))
                throw fail(FileError::tr("weight %1 is not a finite number ≥ 0").arg(w));
            if (weight.mWeight > 0.0F) // joint fits 16 bits whenever finish keeps the skin
                influences_[base + weight.mVertexId].emplace_back(weight.mWeight, static_cast<std::uint16_t>(joint));
        }
    }
}

void PendingSkin::finish(const std::map<std::string, JointNode>& nodes, QStringList& warnings)
{
    if (jointNames_.size() > model::kMaxSkinJoints) {
        warnings << FileError::tr("mesh '%1' has %2 bones, more than the %3 Gyre can skin; it shows in its bind pose")
                        .arg(name_)
                        .arg(jointNames_.size())
                        .arg(model::kMaxSkinJoints);
        return;
    }
    model::Skin skin;
    const Eigen::Matrix4d fromMesh = scaling(meshScale_.cwiseInverse());
    for (std::size_t j = 0; j < jointNames_.size(); ++j) {
        const auto node = nodes.find(jointNames_[j]);
        if (node == nodes.end()) {
            warnings << FileError::tr("mesh '%1': its bone '%2' is not a node of the scene; it shows in its bind pose")
                            .arg(name_, QString::fromStdString(jointNames_[j]));
            return;
        }
        skin.joints.push_back(node->second.id);
        Eigen::Matrix4f inverseBind = (scaling(node->second.scale) * offsets_[j] * fromMesh).cast<float>();
        inverseBind.row(3) << 0.0F, 0.0F, 0.0F, 1.0F; // exactly affine, as the offset is up to rounding
        skin.inverseBinds.push_back(inverseBind);
    }
    const std::size_t positions = mesh_->positions.size();
    skin.vertexJoints.assign(positions, {0, 0, 0, 0});
    skin.vertexWeights.assign(positions, Eigen::Vector4f::Zero());
    for (auto& [vertex, influences] : influences_) {
        // The four largest; their sum is > 0, since only positive weights were kept.
        const std::size_t kept = std::min<std::size_t>(4, influences.size());
        std::partial_sort(influences.begin(), influences.begin() + static_cast<std::ptrdiff_t>(kept), influences.end(),
                          std::greater<>());
        float sum = 0.0F;
        for (std::size_t k = 0; k < kept; ++k)
            sum += influences[k].first;
        for (std::size_t k = 0; k < kept; ++k) {
            skin.vertexJoints[vertex][k] = influences[k].second;
            skin.vertexWeights[vertex][static_cast<int>(k)] = influences[k].first / sum;
        }
    }
    mesh_->skin = std::move(skin);
}

} // namespace gyre::io
