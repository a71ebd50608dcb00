#include "core/torque_free.h"

#include "core/mass_properties.h"
#include "core/quaternion_math.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gyre {

namespace {

// A bound on the steps of one span: a flight so fast or so long that it needs more is refused, not stored.
constexpr std::size_t kMaxSteps = 200000;

// Dormand–Prince 5(4): the stage weights (the equation is autonomous, so the nodes are not needed), the
// fifth-order weights (the seventh stage's row, so its last stage is the next step's first) and the difference
// of the fourth-order weights from them.
constexpr std::array<std::array<double, 6>, 7> kStages{{
    {},
    {1.0 / 5.0},
    {3.0 / 40.0, 9.0 / 40.0},
    {44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0},
    {19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0},
    {9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0},
    {35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0},
}};
constexpr std::array<double, 7> kErrorWeights{71.0 / 57600.0,      0.0,           -71.0 / 16695.0, 71.0 / 1920.0,
                                              -17253.0 / 339200.0, 22.0 / 525.0, -1.0 / 40.0};

// Hamilton product of quaternions stored w, x, y, z.
Eigen::Vector4d product(const Eigen::Vector4d& a, const Eigen::Vector4d& b)
{
    return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
            a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
            a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
            a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

Eigen::Vector4d pure(const Eigen::Vector3d& v) { return {0.0, v.x(), v.y(), v.z()}; }

Eigen::Quaterniond quaternionOf(const Eigen::Vector4d& p)
{
    const Eigen::Vector4d unit = p.normalized();
    return Eigen::Quaterniond(unit[0], unit[1], unit[2], unit[3]);
}

Eigen::Vector4d vectorOf(const Eigen::Quaterniond& q) { return {q.w(), q.x(), q.y(), q.z()}; }

bool finite(const Eigen::Vector3d& v) { return v.allFinite(); }

} // namespace

namespace {

// The tensor's principal frame, after inertiaProblem has passed it. Callers that show the reason check first
// (model::checkMassProperties says it in words).
PrincipalAxes checkedPrincipalAxes(const Eigen::Matrix3d& inertia)
{
    if (inertiaProblem(inertia) != InertiaProblem::None)
        throw std::invalid_argument("the inertia tensor is not one a body can have");
    return principalAxes(inertia);
}

} // namespace

TorqueFreeMotion::TorqueFreeMotion(const Eigen::Matrix3d& inertia, const Eigen::Quaterniond& startOrientation,
                                   const Eigen::Vector3d& startAngularVelocity, double duration, Solver solver,
                                   double tolerance)
    : TorqueFreeMotion(inertia, startOrientation, startAngularVelocity, duration, solver, tolerance, Kept::EveryStep)
{
}

Eigen::Quaterniond TorqueFreeMotion::endOrientation(const Eigen::Matrix3d& inertia,
                                                    const Eigen::Quaterniond& startOrientation,
                                                    const Eigen::Vector3d& startAngularVelocity, double duration,
                                                    double tolerance)
{
    return TorqueFreeMotion(inertia, startOrientation, startAngularVelocity, duration, Solver::Automatic, tolerance,
                            Kept::End)
        .orientation(duration);
}

TorqueFreeMotion::TorqueFreeMotion(const Eigen::Matrix3d& inertia, const Eigen::Quaterniond& startOrientation,
                                   const Eigen::Vector3d& startAngularVelocity, double duration, Solver solver,
                                   double tolerance, Kept kept)
    : start_(startOrientation.normalized())
    , startAngularVelocity_(startAngularVelocity)
    , duration_(duration)
{
    if (!startOrientation.coeffs().allFinite() || !(startOrientation.norm() > 0.0) || !finite(startAngularVelocity))
        throw std::invalid_argument("the start of a free flight is not finite");
    if (!std::isfinite(duration) || duration < 0.0)
        throw std::invalid_argument("a free flight lasts a finite time ≥ 0");
    const PrincipalAxes principal = checkedPrincipalAxes(inertia);
    moments_ = principal.moments;
    axes_ = Eigen::Quaterniond(principal.axes).normalized();
    inverseMoments_ = moments_.cwiseInverse();
    momentum_ = gyre::angularMomentum(inertia, start_, startAngularVelocity);

    const Eigen::Vector3d& d = moments_;
    const bool lowPair = d[1] - d[0] <= kSymmetricMomentTolerance * d[2];
    const bool highPair = d[2] - d[1] <= kSymmetricMomentTolerance * d[2];
    if (solver == Solver::Automatic && (lowPair || highPair)) {
        symmetric_ = true;
        const int distinct = lowPair ? 2 : 0;
        const double a = lowPair ? 0.5 * (d[0] + d[1]) : 0.5 * (d[1] + d[2]);
        const double c = d[distinct];
        symmetryAxis_ = axes_ * Eigen::Vector3d::Unit(distinct);
        precession_ = momentum_ / a;
        spin_ = (1.0 - c / a) * (start_.conjugate() * startAngularVelocity).dot(symmetryAxis_);
        return;
    }

    integrate(tolerance, kept);
}

// The Dormand–Prince integration of p = q·V: seven rate evaluations a step. The first stage is not the last of
// the step before (Dormand–Prince's "first same as last"): that one is at the step's unnormalised end, and each
// accepted p is normalised. The stages run on plain arrays: this loop is all a span's solve does, thousands of
// times. Kept::End keeps the last step alone (orientation() then gives it at every time; only endOrientation
// builds such a motion).
void TorqueFreeMotion::integrate(double tolerance, Kept kept)
{
    Eigen::Vector4d p = vectorOf(start_ * axes_);
    if (kept == Kept::EveryStep || duration_ == 0.0)
        steps_.push_back(stepAt(0.0, p));
    if (duration_ == 0.0)
        return;
    std::size_t stepCount = 1;  // the start is the first
    const double fastest = momentum_.norm() * inverseMoments_.maxCoeff() + 1e-300;  // |ω| ≤ |L|/D_min throughout
    double h = std::min(duration_, 0.05 / fastest);
    double t = 0.0;
    std::array<Quaternion4, 7> k;
    rate(p.data(), k[0].data());
    while (t < duration_) {
        h = std::min(h, duration_ - t);
        Quaternion4 at;
        for (std::size_t stage = 1; stage < 7; ++stage) {
            for (std::size_t c = 0; c < 4; ++c) {
                double sum = 0.0;
                for (std::size_t j = 0; j < stage; ++j)
                    sum += kStages[stage][j] * k[j][c];
                at[c] = p[static_cast<Eigen::Index>(c)] + h * sum;
            }
            rate(at.data(), k[stage].data());
        }
        double size = 0.0;
        for (std::size_t c = 0; c < 4; ++c) {
            double sum = 0.0;
            for (std::size_t j = 0; j < 7; ++j)
                sum += kErrorWeights[j] * k[j][c];
            size = std::max(size, std::abs(h * sum));
        }
        const double factor = std::clamp(0.9 * std::pow(tolerance / std::max(size, 1e-300), 0.2), 0.2, 5.0);
        if (size > tolerance && h > 1e-14 * duration_) {
            h *= factor;
            continue;
        }
        t = (duration_ - (t + h) <= 1e-15 * duration_) ? duration_ : t + h;
        p = Eigen::Vector4d(at[0], at[1], at[2], at[3]).normalized();  // the seventh stage is the fifth-order step
        if (kept == Kept::EveryStep)
            steps_.push_back(stepAt(t, p));
        if (++stepCount > kMaxSteps)
            throw std::invalid_argument("a free flight would need more than " + std::to_string(kMaxSteps) +
                                        " integration steps");
        rate(p.data(), k[0].data());
        h *= factor;
    }
    if (kept == Kept::End)
        steps_.push_back({duration_, p, Eigen::Vector4d::Zero(), Eigen::Vector4d::Zero()});
}

// ṗ = ½·p⊗(0, ω_p) with ω_p = D⁻¹·ℓ, ℓ = p⁻¹·L·p (the rotation by p/|p|: inside a step p strays from unit
// length by O(h²|ω|²)), with p = (w, u):
//     ℓ = L + 2(u × (u × L) − w(u × L))/|p|²,   ṗ = ½(−u·ω_p, w·ω_p + u × ω_p).
void TorqueFreeMotion::rate(const double* p, double* dp) const
{
    const double w = p[0], x = p[1], y = p[2], z = p[3];
    const double lx = momentum_.x(), ly = momentum_.y(), lz = momentum_.z();
    const double cx = y * lz - z * ly, cy = z * lx - x * lz, cz = x * ly - y * lx;  // u × L
    const double scale = 2.0 / (w * w + x * x + y * y + z * z);
    const double ox = (lx + scale * ((y * cz - z * cy) - w * cx)) * inverseMoments_.x();
    const double oy = (ly + scale * ((z * cx - x * cz) - w * cy)) * inverseMoments_.y();
    const double oz = (lz + scale * ((x * cy - y * cx) - w * cz)) * inverseMoments_.z();
    dp[0] = -0.5 * (x * ox + y * oy + z * oz);
    dp[1] = 0.5 * (w * ox + y * oz - z * oy);
    dp[2] = 0.5 * (w * oy + z * ox - x * oz);
    dp[3] = 0.5 * (w * oz + x * oy - y * ox);
}

// The step's ṗ, and p̈ = ½·ṗ⊗(0, ω_p) + ½·p⊗(0, D⁻¹·(ℓ × ω_p)), from
// Euler's ℓ̇ = ℓ × ω_p.
TorqueFreeMotion::Step TorqueFreeMotion::stepAt(double time, const Eigen::Vector4d& p) const
{
    const Eigen::Vector3d body = quaternionOf(p).conjugate() * momentum_;
    const Eigen::Vector3d omega = body.cwiseQuotient(moments_);
    const Eigen::Vector4d dp = 0.5 * product(p, pure(omega));
    const Eigen::Vector3d domega = body.cross(omega).cwiseQuotient(moments_);
    return {time, p, dp, 0.5 * product(dp, pure(omega)) + 0.5 * product(p, pure(domega))};
}

Eigen::Quaterniond TorqueFreeMotion::principalOrientation(double t) const
{
    t = std::clamp(t, 0.0, duration_);
    if (symmetric_)
        return quatExp(0.5 * t * precession_) * start_ * quatExp(0.5 * t * spin_ * symmetryAxis_) * axes_;
    if (steps_.size() == 1)
        return quaternionOf(steps_.front().p);
    const auto after = std::upper_bound(steps_.begin() + 1, steps_.end() - 1, t,
                                        [](double time, const Step& step) { return time < step.time; });
    const Step& a = *(after - 1);
    const Step& b = *after;
    // The quintic Hermite basis on s ∈ [0, 1] for values, first and second derivatives at both ends.
    const double h = b.time - a.time;
    const double s = (t - a.time) / h;
    const double s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
    const double h0 = 1.0 - 10.0 * s3 + 15.0 * s4 - 6.0 * s5;
    const double h1 = s - 6.0 * s3 + 8.0 * s4 - 3.0 * s5;
    const double h2 = 0.5 * s2 - 1.5 * s3 + 1.5 * s4 - 0.5 * s5;
    const double h3 = 10.0 * s3 - 15.0 * s4 + 6.0 * s5;
    const double h4 = -4.0 * s3 + 7.0 * s4 - 3.0 * s5;
    const double h5 = 0.5 * s3 - s4 + 0.5 * s5;
    return quaternionOf(h0 * a.p + h * h1 * a.dp + h * h * h2 * a.ddp + h3 * b.p + h * h4 * b.dp + h * h * h5 * b.ddp);
}

Eigen::Quaterniond TorqueFreeMotion::orientation(double t) const
{
    return (principalOrientation(t) * axes_.conjugate()).normalized();
}

// ω = R_p·D⁻¹·R_pᵀ·L, with R_p the principal frame's orientation.
Eigen::Vector3d TorqueFreeMotion::angularVelocity(double t) const
{
    const Eigen::Quaterniond p = principalOrientation(t);
    return p * (p.conjugate() * momentum_).cwiseQuotient(moments_).eval();
}

double TorqueFreeMotion::kineticEnergy() const { return 0.5 * momentum_.dot(startAngularVelocity_); }

} // namespace gyre
