#include "app/viewport/picking.h"

#include <algorithm>
#include <cmath>

namespace gyre::app {

std::optional<double> intersectTriangle(const Ray& ray, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                        const Eigen::Vector3d& c)
{
    // Solve origin + t·d = a + u·(b − a) + v·(c − a) by Cramer's rule, with u, v ≥ 0, u + v ≤ 1.
    constexpr double kParallel = 1e-12;
    const Eigen::Vector3d edge1 = b - a;
    const Eigen::Vector3d edge2 = c - a;
    const Eigen::Vector3d p = ray.direction.cross(edge2);
    const double determinant = edge1.dot(p);
    if (std::abs(determinant) < kParallel)
        return std::nullopt;
    const Eigen::Vector3d s = ray.origin - a;
    const double u = s.dot(p) / determinant;
    if (u < 0 || u > 1)
        return std::nullopt;
    const Eigen::Vector3d q = s.cross(edge1);
    const double v = ray.direction.dot(q) / determinant;
    if (v < 0 || u + v > 1)
        return std::nullopt;
    const double t = edge2.dot(q) / determinant;
    if (t < 0)
        return std::nullopt;
    return t;
}

std::optional<double> intersectMesh(const Ray& ray, const MeshPlacement& placement)
{
    // Into the mesh's frame, where a world distance t is t/scale: the ray's direction stays unit.
    const Pose toLocal = placement.pose.inverse();
    const Ray local{toLocal.apply(ray.origin) / placement.scale, toLocal.orientation * ray.direction};
    const model::Mesh& mesh = *placement.mesh;
    const std::vector<Eigen::Vector3f>& positions = placement.positions ? *placement.positions : mesh.positions;
    std::optional<double> nearest;
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const auto corner = [&](std::size_t k) { return positions[mesh.indices[i + k]].cast<double>(); };
        const std::optional<double> t = intersectTriangle(local, corner(0), corner(1), corner(2));
        if (t && (!nearest || *t < *nearest))
            nearest = t;
    }
    if (nearest)
        return *nearest * placement.scale;
    return std::nullopt;
}

std::optional<std::size_t> nearestHit(const Ray& ray, const std::vector<MeshPlacement>& placements)
{
    std::optional<std::size_t> hit;
    double nearest = 0.0;
    for (std::size_t i = 0; i < placements.size(); ++i) {
        const std::optional<double> t = intersectMesh(ray, placements[i]);
        if (t && (!hit || *t < nearest)) {
            hit = i;
            nearest = *t;
        }
    }
    return hit;
}

double distanceToSegment(const Eigen::Vector2d& point, const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
    const Eigen::Vector2d ab = b - a;
    const double lengthSquared = ab.squaredNorm();
    const double t = lengthSquared > 0 ? std::clamp((point - a).dot(ab) / lengthSquared, 0.0, 1.0) : 0.0;
    return (a + t * ab - point).norm();
}

std::optional<double> nearestOnAxis(const Ray& ray, const Eigen::Vector3d& axisOrigin,
                                    const Eigen::Vector3d& axisDirection)
{
    // The closest points of lines a + s·u and o + t·d (u, d unit): with w = a − o, b = u·d,
    // s = (b·(d·w) − u·w) / (1 − b²).
    constexpr double kNearlyParallel = 1e-6;
    const double b = axisDirection.dot(ray.direction);
    const double denominator = 1 - b * b;
    if (denominator < kNearlyParallel)
        return std::nullopt;
    const Eigen::Vector3d w = axisOrigin - ray.origin;
    return (b * ray.direction.dot(w) - axisDirection.dot(w)) / denominator;
}

} // namespace gyre::app
