#pragma once
// The shapes drawn for objects without a mesh: a joint's bone (skeleton.h), and for any other the
// block primitive (model/primitive_meshes.h), with a nose and a fin so that every rotation of it looks
// different.

#include "model/scene.h"

namespace gyre::app {

// Built once; flat-shaded (each face has its own vertices and normal).
const model::Mesh& defaultShapeMesh();

// A joint's bone (skeleton.h): an octahedron from the origin to (1, 0, 0), flat-shaded.
const model::Mesh& boneMesh();

// The mesh drawn for the object: its own, or the default shape.
inline const model::Mesh& displayMesh(const model::SceneObject& object)
{
    return object.mesh ? *object.mesh : defaultShapeMesh();
}

} // namespace gyre::app
