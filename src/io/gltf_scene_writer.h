#pragma once
// A baked scene (baked_scene.h) as glTF 2.0, built as a TinyGLTF model and written by TinyGLTF:
//
// - One node "GyreScene" holding the objects' nodes, each with its parent kept, its mesh and its pose at
//   the start time (translation, rotation); one mesh per distinct Mesh (POSITION with its bounds,
//   NORMAL when every vertex has one, UNSIGNED_INT indices, triangles) and one grey material. An Empty
//   is a node without a mesh.
// - A skinned mesh (BakedObject::skinJoints) has JOINTS_0 (UNSIGNED_SHORT) and WEIGHTS_0 (FLOAT, each
//   position's four weights summing to 1), and its node a skin: the joints' nodes and their inverse bind
//   matrices (Skin::inverseBinds, MAT4). Where Gyre lets a position's weights sum to less than 1, the rest
//   following the mesh's own object, the object's own node is one more joint of the skin, with the
//   identity as its inverse bind matrix. glTF ignores a skinned mesh node's own transform, as Gyre's
//   skinning applies it only through the weights left to the object (model/skinning.h).
// - One animation "Gyre": for every moving object a translation and a rotation sampler. A squad or
//   hermite track's translation is CUBICSPLINE through BakedObject::positionSpline (its cubic cut at the
//   baked times), a hermite track's rotation CUBICSPLINE through BakedObject::rotationSpline (its
//   spline cut at the baked times), in- and out-tangent the raw cubic's time derivative on either
//   side, which glTF, like HermiteQuaternionSpline and PositionCurve, multiplies by the span's
//   duration (and normalises, for a rotation). Anything else is LINEAR at the baked samples, each
//   quaternion on the side of the one before so that slerp takes the short arc.
// - Values, times and tangents are float32, which is what the glTF format stores.
//
// A .glb holds its buffer in its BIN chunk; a .gltf refers to a .bin beside it, `binName`.

#include "io/baked_scene.h"

#include <QByteArray>
#include <QString>

namespace gyre::io {

struct GltfFiles {
    QByteArray main; // the .gltf or .glb
    QByteArray bin;  // the .gltf's buffer; empty for a .glb
};

// Throws std::runtime_error when TinyGLTF cannot write the model.
GltfFiles gltfSceneFiles(const BakedScene& scene, bool binary, const QString& binName);

} // namespace gyre::io
