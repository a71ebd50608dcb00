#pragma once
// glTF 2.0 animation samplers read by TinyGLTF as the file means them, and turned into Gyre tracks.
// Assimp 5.2 keeps no interpolation kind, so it plays STEP and CUBICSPLINE samplers as slerp; the
// import (scene_import.h) takes a glTF node's rotation and translation from here instead.
//
// A sampler plays as the glTF specification says (§3.11, Appendix C): STEP holds key k until key k+1;
// LINEAR is slerp for rotations (the short arc) and lerp for translations; CUBICSPLINE is the Hermite
// cubic p(s) = (2s³−3s²+1)vₖ + tₔ(s³−2s²+s)bₖ + (−2s³+3s²)vₖ₊₁ + tₔ(s³−s²)aₖ₊₁ with s = (t−tₖ)/tₔ,
// tₔ = tₖ₊₁ − tₖ, out-tangent bₖ and in-tangent aₖ₊₁ (so the tangents are time derivatives), a rotation
// normalised after it.
//
// A track holds (gltfTrack):
// - a rotation that is LINEAR, or STEP, or absent: a slerp track through the keys, exact; a STEP
//   sampler gets one more key, holding key k's value, at the frame before key k+1 (tₖ₊₁ − 1/fps when
//   that is after tₖ), so it plays as a step at every frame and ramps only within the last frame;
// - a CUBICSPLINE rotation whose in- and out-tangents agree at every inner key: a hermite track whose
//   applied fit (SketchState::fittedCurve) is the file's spline, value vₖ and derivative bₖ at each key:
//   HermiteQuaternionSpline is the same cubic, normalised, so it plays exactly;
// - a CUBICSPLINE rotation with a corner (aₖ ≠ bₖ): baked, a slerp key at every frame of its span;
// - a translation is exact at every key; between keys it is exact when it is LINEAR or STEP on a slerp
//   track, or when it never changes; otherwise (CUBICSPLINE, or under a hermite track, whose positions
//   are cubic) it gets a key at every frame of its span, exact at the frames.
// Frames are k/fps in the file's time.

#include "core/pose.h"
#include "model/scene.h"

#include <Eigen/Core>
#include <QString>
#include <QStringList>

#include <cstddef>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace gyre::io {

// Budgets for a glTF file, checked before anything is read or allocated from them.
inline constexpr std::size_t kMaxGltfAccessorCount = std::size_t{1} << 24; // elements of one accessor
inline constexpr std::size_t kMaxGltfBufferBytes = std::size_t{1} << 30;   // one external buffer or image file
inline constexpr std::size_t kMaxGltfTrackKeys = std::size_t{1} << 22;     // keys of one imported track

enum class GltfInterpolation { Step, Linear, CubicSpline };

struct GltfSampler {
    GltfInterpolation interpolation = GltfInterpolation::Linear;
    std::vector<double> times;                  // seconds, finite, strictly increasing
    std::vector<Eigen::Vector4d> values;        // a rotation as (x, y, z, w); a translation with w = 0
    std::vector<Eigen::Vector4d> inTangents;    // CUBICSPLINE only: aₖ
    std::vector<Eigen::Vector4d> outTangents;   // CUBICSPLINE only: bₖ

    // The sampler's value at `time` (held outside its keys), as the specification plays it.
    Eigen::Vector4d at(double time) const;
};

struct GltfNodeMotion {
    std::optional<GltfSampler> rotation;
    std::optional<GltfSampler> translation;
};

// The node motion of each of the file's animations, in the file's order, found by the node's name as
// Assimp names it (its "name", or "nodes[<index>]" for a node without one). A node whose name is not
// unique, and a channel whose accessors are sparse or not float, are left out: Assimp's keys stand.
using GltfAnimations = std::vector<std::unordered_map<std::string, GltfNodeMotion>>;

// Reads a .gltf or .glb file's animations. Throws InputError, naming the file and the field
// ("animations[0].samplers[1].input: ..."), for a file TinyGLTF cannot parse, a buffer file over
// kMaxGltfBufferBytes, an accessor over kMaxGltfAccessorCount or past its buffer view or buffer, times
// that are not finite or do not increase, values that are not finite, and a zero rotation.
GltfAnimations readGltfAnimations(const QString& path);

// The track of a node moved by `motion` (see above); `nodePose` gives what the motion does not animate,
// `positionScale` scales positions. Throws InputError naming the file and node when the track would need
// more than kMaxGltfTrackKeys keys.
model::MotionTrack gltfTrack(const GltfNodeMotion& motion, const Pose& nodePose, double positionScale, double fps,
                             const QString& path, const QString& nodeName);

} // namespace gyre::io
