#include "core/mass_properties.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <unordered_map>

namespace gyre {

namespace {

// Positions closer than this fraction of the mesh's size are one: float rounding is a few 1e-7 of it.
constexpr double kWeldTolerance = 1e-5;

// The moments of a body about the origin: its mass m, first moment ∫ x dm and second moment ∫ x xᵀ dm.
struct Moments {
    double mass = 0.0;
    Eigen::Vector3d first = Eigen::Vector3d::Zero();
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();

    void scale(double factor)
    {
        mass *= factor;
        first *= factor;
        second *= factor;
    }
};

MassProperties aboutCentre(const Moments& moments)
{
    MassProperties properties;
    properties.mass = moments.mass;
    properties.centre = moments.first / moments.mass;
    // Parallel axes: the second moment about the centre is C − m·c·cᵀ.
    const Eigen::Matrix3d second = moments.second - moments.mass * properties.centre * properties.centre.transpose();
    properties.inertia = second.trace() * Eigen::Matrix3d::Identity() - second;
    properties.inertia = 0.5 * (properties.inertia + properties.inertia.transpose()).eval();
    return properties;
}

Eigen::Vector3d positionAt(const std::vector<Eigen::Vector3f>& positions, std::uint32_t index)
{
    return positions[index].cast<double>();
}

// The index of each position's weld: positions within `tolerance` of an earlier one share its index.
// A grid of cells `tolerance` wide finds them, looking in the 27 cells around each position. Cells count
// from `low`, the positions' lowest corner, so that a small mesh far from the origin still has cell
// indices of at most size/tolerance, which an int holds.
std::vector<std::uint32_t> weldedIndices(const std::vector<Eigen::Vector3f>& positions, const Eigen::Vector3d& low,
                                         double tolerance)
{
    struct CellHash {
        std::size_t operator()(const Eigen::Vector3i& cell) const
        {
            return (static_cast<std::size_t>(cell.x()) * 73856093u) ^ (static_cast<std::size_t>(cell.y()) * 19349663u) ^
                   (static_cast<std::size_t>(cell.z()) * 83492791u);
        }
    };
    struct CellEqual {
        bool operator()(const Eigen::Vector3i& a, const Eigen::Vector3i& b) const { return a == b; }
    };
    std::unordered_map<Eigen::Vector3i, std::vector<std::uint32_t>, CellHash, CellEqual> grid;
    std::vector<std::uint32_t> welded(positions.size());
    std::vector<Eigen::Vector3d> representatives;
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const Eigen::Vector3d point = positions[i].cast<double>();
        const Eigen::Vector3i cell = ((point - low) / tolerance).array().floor().cast<int>();
        std::optional<std::uint32_t> found;
        for (int dx = -1; dx <= 1 && !found; ++dx)
            for (int dy = -1; dy <= 1 && !found; ++dy)
                for (int dz = -1; dz <= 1 && !found; ++dz) {
                    const auto entry = grid.find(cell + Eigen::Vector3i(dx, dy, dz));
                    if (entry == grid.end())
                        continue;
                    for (const std::uint32_t candidate : entry->second)
                        if ((representatives[candidate] - point).norm() <= tolerance) {
                            found = candidate;
                            break;
                        }
                }
        if (!found) {
            found = static_cast<std::uint32_t>(representatives.size());
            representatives.push_back(point);
            grid[cell].push_back(*found);
        }
        welded[i] = *found;
    }
    return welded;
}

Moments solidMoments(const std::vector<Eigen::Vector3f>& positions, const std::vector<std::uint32_t>& indices)
{
    const Eigen::Matrix3d canonical = Eigen::Matrix3d::Constant(1.0) + Eigen::Matrix3d::Identity();
    Moments moments;
    for (std::size_t t = 0; t < indices.size(); t += 3) {
        Eigen::Matrix3d corners;
        corners << positionAt(positions, indices[t]), positionAt(positions, indices[t + 1]),
            positionAt(positions, indices[t + 2]);
        const double determinant = corners.determinant();
        moments.mass += determinant / 6.0;
        moments.first += determinant / 24.0 * corners.rowwise().sum();
        moments.second += determinant / 120.0 * corners * canonical * corners.transpose();
    }
    if (moments.mass < 0.0)
        moments.scale(-1.0); // wound inside out
    return moments;
}

Moments shellMoments(const std::vector<Eigen::Vector3f>& positions, const std::vector<std::uint32_t>& indices)
{
    Moments moments;
    for (std::size_t t = 0; t < indices.size(); t += 3) {
        const Eigen::Vector3d a = positionAt(positions, indices[t]);
        const Eigen::Vector3d b = positionAt(positions, indices[t + 1]);
        const Eigen::Vector3d c = positionAt(positions, indices[t + 2]);
        const double area = 0.5 * (b - a).cross(c - a).norm();
        const Eigen::Vector3d sum = a + b + c;
        moments.mass += area;
        moments.first += area / 3.0 * sum;
        moments.second += area / 12.0 *
                          (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose());
    }
    return moments;
}

Moments boxMoments(const std::vector<Eigen::Vector3f>& positions)
{
    Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d high = -low;
    for (const Eigen::Vector3f& position : positions) {
        low = low.cwiseMin(position.cast<double>());
        high = high.cwiseMax(position.cast<double>());
    }
    // A flat or empty box gets a thickness of a thousandth of its size (or 1 mm), so it has a volume.
    const double thickness = std::max(1e-3 * (high - low).maxCoeff(), 1e-3);
    const Eigen::Vector3d size = (high - low).cwiseMax(thickness);
    Moments moments;
    moments.mass = size.prod();
    const Eigen::Vector3d centre = 0.5 * (low + high);
    moments.first = moments.mass * centre;
    // A box's second moment about its centre is m/12·diag(size²).
    moments.second = moments.mass / 12.0 * size.cwiseProduct(size).asDiagonal().toDenseMatrix() +
                     moments.mass * centre * centre.transpose();
    return moments;
}

} // namespace

bool isClosedMesh(const std::vector<Eigen::Vector3f>& positions, const std::vector<std::uint32_t>& indices)
{
    if (positions.empty())
        return false;
    Eigen::Vector3f low = positions.front(), high = positions.front();
    for (const Eigen::Vector3f& position : positions) {
        low = low.cwiseMin(position);
        high = high.cwiseMax(position);
    }
    const double size = (high - low).cast<double>().norm();
    if (!(size > 0.0))
        return false;
    const std::vector<std::uint32_t> weldedIndex = weldedIndices(positions, low.cast<double>(), kWeldTolerance * size);
    // Each directed edge counts +1, its reverse −1: closed and consistently wound iff every sum is 0.
    std::unordered_map<std::uint64_t, int> balance;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
        for (int corner = 0; corner < 3; ++corner) {
            const std::uint64_t from = weldedIndex[indices[t + corner]];
            const std::uint64_t to = weldedIndex[indices[t + (corner + 1) % 3]];
            if (from == to)
                continue;
            if (from < to)
                ++balance[from << 32 | to];
            else
                --balance[to << 32 | from];
        }
    return !balance.empty() && std::all_of(balance.begin(), balance.end(), [](const auto& edge) { return edge.second == 0; });
}

MeshMass meshMassProperties(const std::vector<Eigen::Vector3f>& positions, const std::vector<std::uint32_t>& indices,
                            double density)
{
    if (positions.empty())
        throw std::invalid_argument("a mesh without positions has no mass");
    if (indices.size() % 3 != 0)
        throw std::invalid_argument("the mesh's index count is not a multiple of three");
    for (const std::uint32_t index : indices)
        if (index >= positions.size())
            throw std::invalid_argument("the mesh has an index past its positions");
    for (const Eigen::Vector3f& position : positions)
        if (!position.allFinite())
            throw std::invalid_argument("the mesh has a position that is not finite");

    MeshMass result;
    Moments moments;
    if (isClosedMesh(positions, indices) && (moments = solidMoments(positions, indices)).mass > 0.0) {
        result.model = MassModel::Solid;
        moments.scale(density);
    } else if ((moments = shellMoments(positions, indices)).mass > 0.0) {
        result.model = MassModel::Shell;
        // The shell weighs what a solid sphere of its area would: V = A^{3/2}/(6√π).
        const double area = moments.mass;
        moments.scale(density * std::sqrt(area) / (6.0 * std::sqrt(std::numbers::pi)));
    } else {
        result.model = MassModel::BoundingBox;
        moments = boxMoments(positions);
        moments.scale(density);
    }
    result.properties = aboutCentre(moments);
    return result;
}

PrincipalAxes principalAxes(const Eigen::Matrix3d& inertia)
{
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertia);
    PrincipalAxes principal{solver.eigenvalues(), solver.eigenvectors()};
    if (principal.axes.determinant() < 0.0)
        principal.axes.col(2) *= -1.0;
    return principal;
}

InertiaProblem inertiaProblem(const Eigen::Matrix3d& inertia)
{
    if (!inertia.allFinite())
        return InertiaProblem::NotFinite;
    if ((inertia - inertia.transpose()).cwiseAbs().maxCoeff() > 1e-12 * inertia.cwiseAbs().maxCoeff())
        return InertiaProblem::NotSymmetric;
    const Eigen::Vector3d moments = principalAxes(inertia).moments;
    if (!(moments[0] > 0.0))
        return InertiaProblem::NotPositiveDefinite;
    if (moments[0] + moments[1] < moments[2] * (1.0 - 1e-9))
        return InertiaProblem::NoSuchBody;
    return InertiaProblem::None;
}

Eigen::Matrix3d inertiaTensor(const InertiaComponents& c)
{
    Eigen::Matrix3d inertia;
    inertia << c[0], c[3], c[4], c[3], c[1], c[5], c[4], c[5], c[2];
    return inertia;
}

Eigen::Vector3d angularMomentum(const Eigen::Matrix3d& inertia, const Eigen::Quaterniond& orientation,
                                const Eigen::Vector3d& angularVelocity)
{
    const Eigen::Matrix3d rotation = orientation.toRotationMatrix();
    return rotation * inertia * rotation.transpose() * angularVelocity;
}

InertiaComponents inertiaComponents(const Eigen::Matrix3d& inertia)
{
    return {inertia(0, 0), inertia(1, 1), inertia(2, 2), inertia(0, 1), inertia(0, 2), inertia(1, 2)};
}

} // namespace gyre
