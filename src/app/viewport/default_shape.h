#pragma once
// The shapes drawn for objects without a mesh: a joint's bone (skeleton.h), an empty's plain axes
// (lines, with an octahedron about them that clicks hit), and for any other the block primitive
// (model/primitive_meshes.h), with a nose and a fin so that every rotation of it looks different.

#include "model/scene.h"

namespace gyre::app {

// Built once; flat-shaded (each face has its own vertices and normal).
const model::Mesh& defaultShapeMesh();

// A joint's bone (skeleton.h): an octahedron from the origin to (1, 0, 0), flat-shaded.
const model::Mesh& boneMesh();

// An empty's plain axes run from −kEmptyAxisLength to kEmptyAxisLength along each axis of its frame
// (Blender's default display size).
inline constexpr double kEmptyAxisLength = 1.0;
// The octahedron whose corners are the ends of an empty's axes: what a click on the empty hits, and its
// ghost and control poses.
const model::Mesh& emptyHullMesh();

// The mesh for the object: its own, an empty's hull, or the default shape.
inline const model::Mesh& displayMesh(const model::SceneObject& object)
{
    if (object.mesh)
        return *object.mesh;
    return object.empty ? emptyHullMesh() : defaultShapeMesh();
}

} // namespace gyre::app
