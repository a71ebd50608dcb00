#pragma once
// An object's mass properties as the physics uses them (angular momentum, free flight): the ones the
// artist typed (SceneObject::massOverride), else its mesh's, solid and of uniform density
// (core/mass_properties.h), else those of the block drawn for an object without a mesh: an empty's too,
// so that a ballistic empty flies as that block would (a flight needs a body's inertia). Imported
// meshes are in metres (docs/scene-files.md), so the mass is in kilograms.

#include "core/mass_properties.h"
#include "model/json_field.h"
#include "model/scene.h"

#include <QJsonObject>
#include <QString>

namespace gyre::model {

enum class MassSource { Typed, Solid, Shell, BoundingBox };

struct ObjectMass {
    MassProperties properties;
    MassSource source = MassSource::Solid;
};

// Computed once per mesh and kept while the mesh lives, so every view and motion build may ask often.
ObjectMass objectMassProperties(const SceneObject& object);

// Where the properties came from, translated, for the inspector ("from the mesh, as a thin shell").
QString massSourceText(MassSource source);

// Throws std::invalid_argument, with a translated message, unless the mass is finite and positive,
// the centre finite, and the inertia a body's (inertiaProblem).
void checkMassProperties(const MassProperties& properties);

// The project file's `massProperties` member: {"mass", "centre": [x, y, z], "inertia": [Ixx, Iyy, Izz,
// Ixy, Ixz, Iyz]}, the inertia about the centre in the object's frame.
QJsonObject massPropertiesJson(const MassProperties& properties);
MassProperties massPropertiesIn(const JsonField& field);

} // namespace gyre::model
