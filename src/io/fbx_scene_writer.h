#pragma once
// A baked scene (baked_scene.h) as a binary FBX 7.4 file (fbx_binary.h), the FBX that Blender 3.4
// and Assimp read:
//
// - GlobalSettings: Z up, −Y forward, X to the side (right-handed, Gyre's axes and Blender's, so
//   Blender turns nothing); UnitScaleFactor 100 (one unit is a metre, so a reader that converts to
//   its own metres keeps the sizes); TimeMode the project's frame rate when FBX names it (24, 25,
//   30, 48, 50, 60, 72, 96, 100, 120 fps), else custom, with CustomFrameRate the frame rate either
//   way; TimeSpanStart/Stop the scene's range.
// - One Model per object (Mesh or Null), its parent by an OO connection, its pose at the start time
//   as Lcl Translation and Lcl Rotation; an Empty's Model with a NodeAttribute Null (TypeFlags Null),
//   as Blender writes its Empties; one Geometry per mesh (shared by the objects that share it; a
//   skinned object's its own):
//   Vertices, PolygonVertexIndex (the last corner of each triangle written as −index − 1) and normals
//   by vertex.
// - A skinned mesh (BakedObject::skinJoints): its joints' Models are LimbNodes (with a NodeAttribute
//   LimbNode, TypeFlags Skeleton); a Deformer Skin on its Geometry, a SubDeformer Cluster per joint linked
//   to the joint's Model (Indexes, Weights as the skin has them, Transform the inverse bind B_j as Blender
//   writes it and Assimp reads it, TransformLink the joint's world matrix at binding, M · B_j⁻¹ with M the
//   object's world pose at the start time), and one Pose BindPose of those world matrices. Weights that
//   sum to less than 1 are written so; readers normalise them (Blender's armature, Gyre's import).
// - One AnimationStack "Gyre" with one AnimationLayer; for every moving object an AnimationCurveNode
//   T (Lcl Translation) and R (Lcl Rotation), each with three AnimationCurves d|X, d|Y, d|Z keyed at
//   every baked sample, linear. The stack's span runs from time 0 (or the start, if earlier) to the
//   end: Assimp measures key times from the stack's start, so the keys keep the project's times.
//
// Times are FBX ticks, kFbxTicksPerSecond a second, rounded to the nearest tick: every frame of every
// frame rate FBX names falls on a whole tick. Rotations are FBX's Euler XYZ (RotationOrder 0), which
// means R = Rz(z)·Ry(y)·Rx(x) on column vectors (Gyre's extrinsic xyz), in degrees, unwrapped by
// the Euler filter (core/euler_angles.h) so that consecutive keys differ by at most 180° in each
// angle and a reader that interpolates the angles linearly turns the short way.

#include "io/baked_scene.h"

#include <cstdint>
#include <string>

namespace gyre::io {

inline constexpr std::int64_t kFbxTicksPerSecond = 46'186'158'000;

// The time in FBX ticks, rounded to the nearest.
std::int64_t fbxTicks(double seconds);

// The FBX TimeMode of a frame rate: the mode FBX names it by, else 14 (custom).
int fbxTimeMode(double fps);

// The whole file. Throws std::length_error when the file would pass 4 GiB.
std::string fbxSceneFile(const BakedScene& scene);

} // namespace gyre::io
