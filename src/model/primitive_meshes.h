#pragma once
// The shapes Object ▸ Add makes, each a closed, flat-shaded mesh about the object's origin, its
// size about one unit, as Blender's primitives are. The block is a new project's object, and the shape
// drawn for an object without a mesh (an imported node's): a body with a nose along +x and a fin on top (+z), so that every rotation of it,
// even a half turn about any axis, looks different.

#include "core/name_table.h"
#include "model/scene.h"

#include <QString>

#include <vector>

namespace gyre::model {

enum class Primitive { Block, Box, Disc, Cone, Arrow };

inline constexpr NameTable<Primitive, 5> kPrimitiveNames{{
    {Primitive::Block, "block"},
    {Primitive::Box, "box"},
    {Primitive::Disc, "disc"},
    {Primitive::Cone, "cone"},
    {Primitive::Arrow, "arrow"},
}};

// Each face has its own vertices and normal; the faces are counter-clockwise seen from outside.
Mesh primitiveMesh(Primitive primitive);

// The shape's name as Object ▸ Add shows it and names the new object ("Box"), translated.
QString primitiveName(Primitive primitive);

// Appends a flat convex polygon, its corners counter-clockwise seen from outside, fanned into
// triangles, with its own vertices and normal.
void addFace(Mesh& mesh, const std::vector<Eigen::Vector3f>& corners);

} // namespace gyre::model
