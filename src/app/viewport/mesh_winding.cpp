#include "app/viewport/mesh_winding.h"

#include "core/mass_properties.h"

namespace gyre::app {

MeshWinding meshWinding(const model::Mesh& mesh)
{
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0 || !isClosedMesh(mesh.positions, mesh.indices))
        return MeshWinding::Open;
    double sixVolume = 0.0;
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        const Eigen::Vector3d a = mesh.positions[mesh.indices[i]].cast<double>();
        const Eigen::Vector3d b = mesh.positions[mesh.indices[i + 1]].cast<double>();
        const Eigen::Vector3d c = mesh.positions[mesh.indices[i + 2]].cast<double>();
        sixVolume += a.dot(b.cross(c));
    }
    return sixVolume < 0.0 ? MeshWinding::Clockwise : MeshWinding::CounterClockwise;
}

} // namespace gyre::app
