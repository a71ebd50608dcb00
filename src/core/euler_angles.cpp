#include "core/euler_angles.h"

#include "core/euler_filter.h"
#include "core/fast_trig.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace gyre {

namespace {

constexpr double kPi = std::numbers::pi;

// Below this norm of the quaternion pair that fixes e1 − e3 (or e1 + e3), the rotation is at gimbal
// lock to within about 1e-12 rad: the split between e1 and e3 is then a convention, and e3 = 0.
constexpr double kLockPairNorm = 1e-12;

Eigen::Quaterniond axisRotation(int axis, double angle)
{
    const SinCos half = fastSinCos(0.5 * angle);
    Eigen::Quaterniond q(half.cos, 0.0, 0.0, 0.0);
    q.vec()[axis] = half.sin;
    return q;
}

double component(const Eigen::Quaterniond& q, int axis)
{
    return q.vec()[axis];
}

// +1 if (i, j, k) is a cyclic permutation of (x, y, z), −1 otherwise: eᵢeⱼ = parity·eₖ.
double parity(int i, int j)
{
    return (j - i + 3) % 3 == 1 ? 1.0 : -1.0;
}

// Which angle takes the whole turn about the locked axis at exact gimbal lock; the other is 0.
enum class LockedTurn { First, Last };

// A pair of quaternion components (x, y) = r·(cos φ, sin φ) that carries a half-sum or half-difference
// φ of e1 and e3, with its length r, which also gives the middle angle.
struct ComponentPair {
    double x;
    double y;
    double length;
};

ComponentPair componentPair(double x, double y)
{
    return {x, y, std::sqrt(x * x + y * y)};
}

// π − kPi, to 17 digits.
constexpr double kPiTail = 1.2246467991473532e-16;

// An angle halfTurns·π + tableAngle + correction, halfTurns ∈ {−1, 0, 1}, tableAngle exactly a double
// and |correction| < 0.006, kept unrounded so that two can be added with one rounding.
struct UnroundedAngle {
    double halfTurns;
    double tableAngle;
    double correction;
};

// m·angle for m ∈ {−1, 0, 1}, exactly.
UnroundedAngle times(double m, const UnroundedAngle& angle)
{
    return {m * angle.halfTurns, m * angle.tableAngle, m * angle.correction};
}

// atan2(y, x) ∈ (−π, π], unrounded: (|x|, |y|) folded into the first quadrant for
// preciseAngleInFirstQuadrant, then unfolded, a → π − a for x < 0 and a → −a for y < 0. The signs are
// random from call to call, so the unfolding is arithmetic, not branches. Unlike atan2 it gives π,
// not −π, for y = −0 and x < 0.
UnroundedAngle angleOf(const ComponentPair& pair)
{
    const TableAngleSum a = preciseAngleInFirstQuadrant(std::abs(pair.x), std::abs(pair.y), pair.length);
    const double leftHalf = pair.x < 0.0 ? 1.0 : 0.0;
    const double fold = 1.0 - 2.0 * leftHalf;
    return times(pair.y < 0.0 ? -1.0 : 1.0, {leftHalf, fold * a.tableAngle, fold * a.correction});
}

// a + b = head + tail exactly, for any two finite doubles (Knuth's two-sum).
struct ExactSum {
    double head;
    double tail;
};

ExactSum exactSum(double a, double b)
{
    const double head = a + b;
    const double bPart = head - a;
    return {head, (a - (head - bPart)) + (b - bPart)};
}

// The outer angle a + b, each in (−π, π], wrapped into (−π, π] and rounded once: within about 1e-17
// beyond half an ulp of the exact sum, where a sum of two rounded half angles and a turn of the rounded
// 2π would be off by up to 2 ulp of 2π. The three large terms, the table angles and halfTurns·kPi (exact,
// halfTurns an integer of at most 2), are added exactly, and the small ones after. The turn comes from
// an estimate; where the estimate and the exact sum fall on either side of ±π, the sum is taken again
// with the other turn.
double wrappedSum(const UnroundedAngle& a, const UnroundedAngle& b)
{
    const ExactSum tables = exactSum(a.tableAngle, b.tableAngle);
    const double corrections = a.correction + b.correction;
    const auto withHalfTurns = [&](double halfTurns) {
        const ExactSum sum = exactSum(tables.head, halfTurns * kPi);
        return sum.head + (sum.tail + (tables.tail + (halfTurns * kPiTail + corrections)));
    };
    const double estimate = (a.halfTurns + b.halfTurns) * kPi + tables.head + corrections;
    const double halfTurns = a.halfTurns + b.halfTurns - ((estimate > kPi ? 2.0 : 0.0) - (estimate <= -kPi ? 2.0 : 0.0));
    double angle = withHalfTurns(halfTurns);
    if (angle > kPi) [[unlikely]]
        angle = withHalfTurns(halfTurns - 2.0);
    else if (angle <= -kPi) [[unlikely]]
        angle = withHalfTurns(halfTurns + 2.0);
    // Still outside only for an exact sum within an ulp or so of ±π, for which kPi stands.
    return angle > -kPi && angle <= kPi ? angle : kPi;
}

// The half-sum and half-difference of e1 and e3, from the two quaternion pairs that carry them. At
// exact lock one of them is undetermined and is chosen so that the angle that does not take the turn
// is 0: e3 = 0 means sum = difference, e1 = 0 means sum = −difference.
struct HalfAngles {
    UnroundedAngle sum;
    UnroundedAngle difference;
};

HalfAngles halfAngles(const ComponentPair& sumPair, const ComponentPair& differencePair, LockedTurn lockedTurn)
{
    const double sign = lockedTurn == LockedTurn::First ? 1.0 : -1.0;
    if (differencePair.length < kLockPairNorm) {
        const UnroundedAngle sum = angleOf(sumPair);
        return {sum, times(sign, sum)};
    }
    if (sumPair.length < kLockPairNorm) {
        const UnroundedAngle difference = angleOf(differencePair);
        return {times(sign, difference), difference};
    }
    return {angleOf(sumPair), angleOf(differencePair)};
}

// Intrinsic decomposition q = q_i(e1)·q_j(e2)·q_k(e3) of a unit q. With half angles A, B, C:
//   proper (k = i, m the third axis, ε = parity(i, j)):
//     q = (cos B cos(A+C), cos B sin(A+C)·e_i, sin B cos(A−C)·e_j, ε sin B sin(A−C)·e_m)
//   Tait-Bryan (ε = parity(i, j), C′ = εC), with w, x = q_i, y = q_j, z = ε q_k:
//     w + y = (cos B + sin B) cos(A+C′),  x + z = (cos B + sin B) sin(A+C′)
//     w − y = (cos B − sin B) cos(A−C′),  x − z = (cos B − sin B) sin(A−C′)
// The pairs' lengths give B: (cos B, sin B) for proper, √2·(cos(B − π/4), sin(π/4 − B)) for Tait-Bryan.
EulerAngles intrinsicAngles(const Eigen::Quaterniond& q, int i, int j, int k, LockedTurn lockedTurn)
{
    const double epsilon = parity(i, j);
    const double w = q.w();
    const double x = component(q, i);
    const double y = component(q, j);
    EulerAngles result;
    if (i == k) {
        const int m = 3 - i - j;
        const double z = epsilon * component(q, m);
        const ComponentPair sumPair = componentPair(w, x);
        const ComponentPair differencePair = componentPair(y, z);
        const HalfAngles h = halfAngles(sumPair, differencePair, lockedTurn);
        const double middle = 2.0 * fastAngleOnUnitCircle(sumPair.length, differencePair.length);
        result.angles = {wrappedSum(h.sum, h.difference), middle, wrappedSum(h.sum, times(-1.0, h.difference))};
        result.gimbalLockDistance = std::min(middle, kPi - middle);
    } else {
        const double z = epsilon * component(q, k);
        const ComponentPair sumPair = componentPair(w + y, x + z);
        const ComponentPair differencePair = componentPair(w - y, x - z);
        const HalfAngles h = halfAngles(sumPair, differencePair, lockedTurn);
        constexpr double kHalfSqrt2 = std::numbers::sqrt2 / 2.0;
        const double middle = 0.5 * kPi - 2.0 * fastAngleOnUnitCircle(kHalfSqrt2 * sumPair.length, kHalfSqrt2 * differencePair.length);
        result.angles = {wrappedSum(h.sum, h.difference), middle, wrappedSum(times(epsilon, h.sum), times(-epsilon, h.difference))};
        result.gimbalLockDistance = 0.5 * kPi - std::abs(middle);
    }
    return result;
}

} // namespace

std::optional<EulerConvention> EulerConvention::parse(std::string_view order, AngleFrame frame)
{
    if (order.size() != 3)
        return std::nullopt;
    EulerConvention convention;
    convention.frame = frame;
    for (std::size_t n = 0; n < 3; ++n) {
        const char c = order[n];
        if (c == 'x' || c == 'X')
            convention.axes[n] = 0;
        else if (c == 'y' || c == 'Y')
            convention.axes[n] = 1;
        else if (c == 'z' || c == 'Z')
            convention.axes[n] = 2;
        else
            return std::nullopt;
    }
    if (convention.axes[0] == convention.axes[1] || convention.axes[1] == convention.axes[2])
        return std::nullopt;
    return convention;
}

std::vector<EulerConvention> EulerConvention::all()
{
    std::vector<EulerConvention> conventions;
    for (AngleFrame frame : {AngleFrame::Intrinsic, AngleFrame::Extrinsic})
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                for (int k = 0; k < 3; ++k)
                    if (i != j && j != k)
                        conventions.push_back({{i, j, k}, frame});
    return conventions;
}

std::string EulerConvention::order() const
{
    std::string text;
    for (int axis : axes)
        text += static_cast<char>('x' + axis);
    return text;
}

std::string EulerConvention::name() const
{
    return (frame == AngleFrame::Intrinsic ? "intrinsic " : "extrinsic ") + order();
}

Eigen::Quaterniond quaternionFromEulerAngles(const Eigen::Vector3d& angles, const EulerConvention& convention)
{
    const Eigen::Quaterniond q1 = axisRotation(convention.axes[0], angles[0]);
    const Eigen::Quaterniond q2 = axisRotation(convention.axes[1], angles[1]);
    const Eigen::Quaterniond q3 = axisRotation(convention.axes[2], angles[2]);
    return convention.frame == AngleFrame::Intrinsic ? q1 * q2 * q3 : q3 * q2 * q1;
}

EulerAngles eulerAnglesFromQuaternion(const Eigen::Quaterniond& q, const EulerConvention& convention)
{
    const Eigen::Quaterniond unit = q.normalized();
    const auto& a = convention.axes;
    if (convention.frame == AngleFrame::Intrinsic)
        return intrinsicAngles(unit, a[0], a[1], a[2], LockedTurn::First);
    // Extrinsic ijk with (e1, e2, e3) is intrinsic kji with (e3, e2, e1).
    EulerAngles reversed = intrinsicAngles(unit, a[2], a[1], a[0], LockedTurn::Last);
    std::swap(reversed.angles[0], reversed.angles[2]);
    return reversed;
}

Eigen::Vector3d nearestEquivalentAngles(const Eigen::Vector3d& angles, const Eigen::Vector3d& previous,
                                        const EulerConvention& convention)
{
    // The second solution: R_i(e1+π)·R_j(π−e2)·R_k(e3+π) for Tait-Bryan, R_i(e1+π)·R_j(−e2)·R_i(e3+π)
    // for proper Euler (the π turns about i and k conjugate R_j into its mirror).
    const double mirroredMiddle = convention.isProperEuler() ? -angles[1] : kPi - angles[1];
    const Eigen::Vector3d candidates[2] = {angles, {angles[0] + kPi, mirroredMiddle, angles[2] + kPi}};
    Eigen::Vector3d best = angles;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& candidate : candidates) {
        Eigen::Vector3d shifted;
        for (int n = 0; n < 3; ++n)
            shifted[n] = previous[n] + wrapAngle(candidate[n] - previous[n]);
        const double distance = (shifted - previous).squaredNorm();
        if (distance < bestDistance) {
            bestDistance = distance;
            best = shifted;
        }
    }
    return best;
}

std::vector<Eigen::Vector3d> unwrappedEulerAngles(const std::vector<Eigen::Quaterniond>& rotations,
                                                  const EulerConvention& convention,
                                                  const std::optional<Eigen::Vector3d>& before)
{
    std::vector<Eigen::Vector3d> angles;
    angles.reserve(rotations.size());
    for (const Eigen::Quaterniond& q : rotations)
        angles.push_back(eulerAnglesFromQuaternion(q, convention).angles);
    return continuousEulerAngles(std::move(angles), convention, before);
}

double wrapAngle(double e)
{
    if (e > -kPi && e <= kPi)
        return e;
    // Within 2.5π of 0 (every sum of two angles in [−π, π]) one turn added or taken away is exact by
    // Sterbenz's lemma and is what std::remainder gives, at a fraction of its cost.
    if (e > kPi && e < 2.5 * kPi)
        return e - 2.0 * kPi;
    if (e <= -kPi && e > -2.5 * kPi)
        return e + 2.0 * kPi;
    const double wrapped = std::remainder(e, 2.0 * kPi);
    return wrapped <= -kPi ? wrapped + 2.0 * kPi : wrapped;
}

} // namespace gyre
