#pragma once
// Three-angle sequences: the 6 Tait-Bryan orders (xyz, …) and the 6 proper Euler orders (xyx, …),
// each about moving axes (intrinsic) or fixed axes (extrinsic). Radians throughout.
//
// Intrinsic `ijk` is R = R_i(e1)·R_j(e2)·R_k(e3); extrinsic `ijk` is R = R_k(e3)·R_j(e2)·R_i(e1).
// So e1 is always the angle about the first axis named in the order.

#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gyre {

enum class AngleFrame { Intrinsic, Extrinsic };

struct EulerConvention {
    std::array<int, 3> axes{0, 1, 2}; // 0 = x, 1 = y, 2 = z
    AngleFrame frame = AngleFrame::Extrinsic;

    // Parses an order such as "xyz" or "ZXZ"; nullopt unless it names three axes with no axis
    // twice in a row.
    static std::optional<EulerConvention> parse(std::string_view order, AngleFrame frame);

    // All 24 conventions: 12 orders, each intrinsic and extrinsic.
    static std::vector<EulerConvention> all();

    bool isProperEuler() const { return axes[0] == axes[2]; }
    std::string order() const;            // "xyz"
    std::string name() const;             // "intrinsic xyz"
    bool operator==(const EulerConvention&) const = default;
};

struct EulerAngles {
    Eigen::Vector3d angles = Eigen::Vector3d::Zero(); // e1, e2, e3 in radians, each in (−π, π]
    // Angular distance in radians of the middle angle from its gimbal-lock value (±π/2 for
    // Tait-Bryan, 0 or π for proper Euler). Near zero, e1 and e3 turn about nearly the same axis and
    // only their sum or difference is well defined; the angles still rebuild the rotation to rounding,
    // except within 1e-12 rad of lock, where e3 is set to 0 and the rebuild is off by at most that.
    double gimbalLockDistance = 0.0;
};

Eigen::Quaterniond quaternionFromEulerAngles(const Eigen::Vector3d& angles, const EulerConvention& convention);

// The angles of q in the convention. The middle angle is in [−π/2, π/2] (Tait-Bryan) or [0, π]
// (proper Euler). At exact gimbal lock e3 is 0 and e1 carries the whole turn about the locked axis.
EulerAngles eulerAnglesFromQuaternion(const Eigen::Quaterniond& q, const EulerConvention& convention);

// Of all angle triples that give the same rotation as `angles` (each angle ± multiples of 2π, and
// the second solution with the middle angle mirrored), the one nearest to `previous`.
Eigen::Vector3d nearestEquivalentAngles(const Eigen::Vector3d& angles, const Eigen::Vector3d& previous,
                                        const EulerConvention& convention);

// The Euler filter: the angle triples of a sequence of rotations, each chosen nearest to the one
// before it so that the curves have no 2π jumps or flips. Where `before` is given, the first is
// chosen nearest to it, so that a long sequence filtered block by block reads as one.
std::vector<Eigen::Vector3d> unwrappedEulerAngles(const std::vector<Eigen::Quaterniond>& rotations,
                                                  const EulerConvention& convention,
                                                  const std::optional<Eigen::Vector3d>& before = std::nullopt);

// The angle e wrapped into (−π, π].
double wrapAngle(double e);

} // namespace gyre
