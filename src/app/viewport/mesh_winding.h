#pragma once
// Whether the viewport may leave out a mesh's back faces. A mesh whose triangles close up, every
// edge walked once in each direction, shows an eye outside it only its front faces: culling the
// back ones changes nothing drawn opaque, and spares the translucent trail, control poses and ghost
// the far wall of every copy, half of what a stroboscopic trail of thousands of copies costs to fill.
// Imported meshes are not all closed, nor all wound the same way, so each is checked once.

#include "model/scene.h"

namespace gyre::app {

enum class MeshWinding {
    Open,             // some edge is not walked once each way: back faces may be in sight
    CounterClockwise, // closed, its triangles counter-clockwise seen from outside
    Clockwise,        // closed, wound the other way (inside out)
};

// Closed as the mass properties count it (isClosedMesh, core/mass_properties.h): vertices at one position,
// to rounding, count as one, as a flat-shaded mesh repeats them per face. The side is the sign of the
// enclosed volume, V = Σ a·(b×c)/6 over the triangles (a, b, c).
MeshWinding meshWinding(const model::Mesh& mesh);

} // namespace gyre::app
