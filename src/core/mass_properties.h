#pragma once
// The mass, centre of mass and inertia tensor of a rigid body given as a triangle mesh of uniform
// density, for the angular momentum L = R·I·Rᵀ·ω and the torque-free motion of a keyed object.
//
// A closed mesh is a solid: its volume integrals come from the divergence theorem, as a sum over the
// signed tetrahedra joining the origin to each triangle (the covariance form of Blow and Binstock,
// "How to find the inertia tensor of a 3D solid body", 2004): for the tetrahedron (0, a, b, c) with
// A = [a b c], d = det A,
//     volume = d/6,   ∫ x dV = d/24·(a + b + c),   ∫ x xᵀ dV = d/120·A·(𝟙 + Id)·Aᵀ
// (𝟙 the all-ones matrix), and I = tr(C)·Id − C for the second moment C about the centre. An open
// mesh has no inside: it is taken as a thin shell of uniform surface density, each triangle (a, b, c)
// of area s adding ∫ x xᵀ dA = s/12·(aaᵀ + bbᵀ + ccᵀ + (a+b+c)(a+b+c)ᵀ). A mesh without area is
// taken as its bounding box, solid.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <vector>

namespace gyre {

struct MassProperties {
    double mass = 1.0;                                  // kg
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();   // centre of mass, in the body's frame
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity(); // about the centre, in the body's frame, kg·m²
    bool operator==(const MassProperties&) const = default;
};

// How mass properties were found.
enum class MassModel {
    Solid,        // a closed mesh, filled
    Shell,        // an open mesh, as a thin shell
    BoundingBox,  // a mesh without area, as its box
};

struct MeshMass {
    MassProperties properties;
    MassModel model = MassModel::Solid;
};

// Uniform density of the solid, kg/m³ (water's), with positions in metres. A shell has the same mass as
// the solid its area would enclose were it a sphere, so switching a mesh between closed and open does
// not change its mass by orders of magnitude.
inline constexpr double kDefaultDensity = 1000.0;

// The mesh's mass properties. A mesh is closed when every edge, its end points matched by position, is
// shared by exactly two triangles that run it in opposite directions; a closed mesh wound inside out is
// turned. Throws std::invalid_argument for an index past the positions, a count of indices not a multiple
// of three, no positions, or a non-finite position.
MeshMass meshMassProperties(const std::vector<Eigen::Vector3f>& positions, const std::vector<std::uint32_t>& indices,
                            double density = kDefaultDensity);

// Whether the mesh is closed: every edge, its ends welded by position within 1e-5 of the mesh's size (faces
// with their own vertices, or a seam whose copies differ by float rounding, still join), run once in each
// direction. Indices must be within the positions and a multiple of three.
bool isClosedMesh(const std::vector<Eigen::Vector3f>& positions, const std::vector<std::uint32_t>& indices);

// Principal moments (increasing) and the rotation from the principal frame to the body frame (its
// columns the principal axes, a right-handed frame).
struct PrincipalAxes {
    Eigen::Vector3d moments;
    Eigen::Matrix3d axes;
};
PrincipalAxes principalAxes(const Eigen::Matrix3d& inertia);

// Whether `inertia` can be the inertia tensor of a body: finite, symmetric, positive definite, and its
// principal moments meet the triangle inequality I₁ + I₂ ≥ I₃ (relative tolerance 1e-9).
enum class InertiaProblem { None, NotFinite, NotSymmetric, NotPositiveDefinite, NoSuchBody };
InertiaProblem inertiaProblem(const Eigen::Matrix3d& inertia);

// A symmetric tensor as six numbers, in the order the project file, the inspector and `gyre-cli --inertia`
// give them: Ixx, Iyy, Izz, Ixy, Ixz, Iyz.
using InertiaComponents = std::array<double, 6>;
Eigen::Matrix3d inertiaTensor(const InertiaComponents& components);
InertiaComponents inertiaComponents(const Eigen::Matrix3d& inertia);

// The world angular momentum L = R·I·Rᵀ·ω of a body of `inertia` (body frame) turned by the unit `orientation`
// R, spinning at the world angular velocity ω; its rotational energy is ½·L·ω.
Eigen::Vector3d angularMomentum(const Eigen::Matrix3d& inertia, const Eigen::Quaterniond& orientation,
                                const Eigen::Vector3d& angularVelocity);

} // namespace gyre
