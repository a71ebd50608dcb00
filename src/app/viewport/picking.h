#pragma once
// What a click hits: rays against triangle meshes placed in the world. No OpenGL, so tests can
// check picking on its own.

#include "app/viewport/ray.h"
#include "core/pose.h"
#include "model/scene.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace gyre::app {

// A mesh drawn at `pose`, scaled by `scale` about its own origin: x ↦ pose.apply(scale·x). A skinned
// mesh is hit where it is drawn: `positions` are then its positions skinned (model::skinnedPositions).
struct MeshPlacement {
    const model::Mesh* mesh = nullptr;
    Pose pose;
    double scale = 1.0;
    const std::vector<Eigen::Vector3f>* positions = nullptr; // the mesh's own when null
};

// The ray parameter t of the hit on triangle (a, b, c), either side (Möller–Trumbore), or nullopt.
std::optional<double> intersectTriangle(const Ray& ray, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                        const Eigen::Vector3d& c);

// The ray parameter of the nearest hit on the placed mesh, or nullopt.
std::optional<double> intersectMesh(const Ray& ray, const MeshPlacement& placement);

// The index of the placement the ray hits first, or nullopt if it hits none.
std::optional<std::size_t> nearestHit(const Ray& ray, const std::vector<MeshPlacement>& placements);

// The distance from `point` to the segment from `a` to `b` (2D screen points).
double distanceToSegment(const Eigen::Vector2d& point, const Eigen::Vector2d& a, const Eigen::Vector2d& b);

// The parameter s of the point axisOrigin + s·axisDirection (unit) nearest to the ray's line, or
// nullopt when the two are nearly parallel and s is ill-defined.
std::optional<double> nearestOnAxis(const Ray& ray, const Eigen::Vector3d& axisOrigin,
                                    const Eigen::Vector3d& axisDirection);

} // namespace gyre::app
