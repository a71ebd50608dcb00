#include "model/object_mass.h"

#include "model/input_error.h"
#include "model/primitive_meshes.h"

#include <QJsonArray>

#include <memory>
#include <mutex>
#include <stdexcept>
#include <unordered_map>
#include <utility>

namespace gyre::model {

namespace {

ObjectMass fromMesh(const Mesh& mesh)
{
    const MeshMass mass = meshMassProperties(mesh.positions, mesh.indices);
    const MassSource source = mass.model == MassModel::Solid   ? MassSource::Solid
                              : mass.model == MassModel::Shell ? MassSource::Shell
                                                               : MassSource::BoundingBox;
    return {mass.properties, source};
}

// Meshes are shared and never change once made (scene.h), so a mesh's mass is computed once. An entry
// whose mesh is gone is dropped, so a new mesh at the same address is computed afresh.
ObjectMass cachedMass(const std::shared_ptr<const Mesh>& mesh)
{
    static std::mutex mutex;
    static std::unordered_map<const Mesh*, std::pair<std::weak_ptr<const Mesh>, ObjectMass>> cache;
    {
        const std::lock_guard lock(mutex);
        const auto found = cache.find(mesh.get());
        if (found != cache.end() && !found->second.first.expired())
            return found->second.second;
    }
    const ObjectMass mass = fromMesh(*mesh);
    const std::lock_guard lock(mutex);
    std::erase_if(cache, [](const auto& entry) { return entry.second.first.expired(); });
    cache[mesh.get()] = {mesh, mass};
    return mass;
}

QString inertiaProblemText(InertiaProblem problem)
{
    switch (problem) {
    case InertiaProblem::None:
        break;
    case InertiaProblem::NotFinite:
        return FileError::tr("the inertia has a value that is not a finite number");
    case InertiaProblem::NotSymmetric:
        return FileError::tr("the inertia tensor is not symmetric");
    case InertiaProblem::NotPositiveDefinite:
        return FileError::tr("the inertia tensor is not positive definite: every principal moment must be above 0");
    case InertiaProblem::NoSuchBody:
        return FileError::tr("no body has this inertia: its two smaller principal moments add up to less than "
                             "the largest");
    }
    return {};
}

} // namespace

ObjectMass objectMassProperties(const SceneObject& object)
{
    if (object.massOverride)
        return {*object.massOverride, MassSource::Typed};
    if (object.mesh && !object.mesh->positions.empty())
        return cachedMass(object.mesh);
    static const ObjectMass block = fromMesh(primitiveMesh(Primitive::Block));
    return block;
}

QString massSourceText(MassSource source)
{
    switch (source) {
    case MassSource::Typed:
        return FileError::tr("as typed");
    case MassSource::Solid:
        return FileError::tr("from the mesh, solid");
    case MassSource::Shell:
        return FileError::tr("from the mesh, as a thin shell: the mesh is not closed");
    case MassSource::BoundingBox:
        return FileError::tr("from the mesh's bounding box: the mesh has no area");
    }
    return {};
}

void checkMassProperties(const MassProperties& properties)
{
    if (!std::isfinite(properties.mass) || properties.mass <= 0.0)
        throw std::invalid_argument(FileError::tr("the mass must be a number above 0").toStdString());
    if (!properties.centre.allFinite())
        throw std::invalid_argument(FileError::tr("the centre of mass is not a finite point").toStdString());
    if (const InertiaProblem problem = inertiaProblem(properties.inertia); problem != InertiaProblem::None)
        throw std::invalid_argument(inertiaProblemText(problem).toStdString());
}

QJsonObject massPropertiesJson(const MassProperties& properties)
{
    const InertiaComponents inertia = inertiaComponents(properties.inertia);
    return {{"mass", properties.mass},
            {"centre", QJsonArray{properties.centre.x(), properties.centre.y(), properties.centre.z()}},
            {"inertia", QJsonArray{inertia[0], inertia[1], inertia[2], inertia[3], inertia[4], inertia[5]}}};
}

MassProperties massPropertiesIn(const JsonField& field)
{
    MassProperties properties;
    properties.mass = field.member("mass").number();
    properties.centre = field.member("centre").vector3();
    const std::vector<JsonField> moments = field.member("inertia").elements();
    if (moments.size() != 6)
        field.member("inertia").fail(FileError::tr("the inertia needs six numbers: Ixx, Iyy, Izz, Ixy, Ixz, Iyz"));
    InertiaComponents components;
    for (std::size_t i = 0; i < components.size(); ++i)
        components[i] = moments[i].number();
    properties.inertia = inertiaTensor(components);
    field.checked([&] { checkMassProperties(properties); });
    return properties;
}

} // namespace gyre::model
