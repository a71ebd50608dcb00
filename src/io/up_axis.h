#pragma once
// Which way is up: Gyre's world is Z-up, and scene files say Y-up or Z-up.

#include "core/name_table.h"

#include <Eigen/Geometry>
#include <QtGlobal>

#include <cmath>

namespace gyre::io {

// The axis a file calls up. Gyre's world is Z-up, as Blender's (the viewport's ground is the xy plane):
// a Y-up file is turned by +90° about X (Y becomes Z, Z becomes -Y) on its top-level objects, as
// Blender's importers turn it, so a character that stands in the file stands in Gyre.
enum class UpAxis : quint8 { Y = 1, Z = 2 };
inline constexpr NameTable<UpAxis, 2> kUpAxisNames{{{UpAxis::Y, "y"}, {UpAxis::Z, "z"}}};

// The turn from a Y-up world to Gyre's Z-up one: +90° about X. Import applies it to a Y-up file's
// top-level objects; export applies its inverse for the Y-up formats (glTF, Collada, OBJ).
inline Eigen::Quaterniond yUpToZUp() { return Eigen::Quaterniond(std::sqrt(0.5), std::sqrt(0.5), 0.0, 0.0); }

} // namespace gyre::io
