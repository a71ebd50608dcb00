#pragma once
// The skins of imported meshes: Assimp's bones (a joint node's name, its offset matrix, the weights
// of the vertices it moves) gathered while a node's meshes are merged, and turned into the mesh's
// model::Skin once every node has its object (the joints may come after the mesh in the node tree).

#include "model/scene.h"

#include <assimp/mesh.h>

#include <QString>
#include <QStringList>

#include <Eigen/Core>

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace gyre::io {

// What the scene builder knows of a node once its object is made: the object, and the scale Gyre
// took out of its world transform (the ancestors' uniform scale and the node's own, the file's unit
// included), which its pose no longer carries.
struct JointNode {
    model::ObjectId id = model::kNoObject;
    Eigen::Vector3d scale = Eigen::Vector3d::Ones();
};

class PendingSkin {
public:
    // For `mesh`, whose positions were scaled by `meshScale` (the file's unit included).
    PendingSkin(std::shared_ptr<model::Mesh> mesh, QString name, const Eigen::Vector3d& meshScale)
        : mesh_(std::move(mesh)), name_(std::move(name)), meshScale_(meshScale)
    {
    }

    const QString& name() const { return name_; }

    // Adds the bones of `part`, whose first vertex is position `base` of the mesh. Throws InputError
    // naming `path`, the mesh and the bone for a weight that is not finite and ≥ 0 or a vertex the
    // part does not have.
    void addBones(const aiMesh& part, std::uint32_t base, const QString& path);

    // Sets the mesh's skin: each bone's joint is the first node of its name, and its inverse bind
    // B = S_joint · offset · S_mesh⁻¹ in Gyre's units (S the scales Gyre took out); each vertex keeps
    // its four largest weights, renormalised to sum 1. A bone naming no object, or more bones than
    // model::kMaxSkinJoints, leaves the mesh rigid with a warning.
    void finish(const std::map<std::string, JointNode>& nodes, QStringList& warnings);

private:
    std::shared_ptr<model::Mesh> mesh_;
    QString name_;
    Eigen::Vector3d meshScale_;
    std::vector<std::string> jointNames_;
    std::vector<Eigen::Matrix4d> offsets_;
    std::map<std::uint32_t, std::vector<std::pair<float, std::uint16_t>>> influences_; // by position: (weight, joint)
};

} // namespace gyre::io
