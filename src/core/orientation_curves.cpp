#include "core/orientation_curves.h"

#include "core/position_curve.h"
#include "core/quaternion_math.h"
#include "core/timed_keys.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

namespace gyre {

namespace {

// Flips each quaternion into the hemisphere of the one before, so that consecutive keys are joined
// along the short arc.
void alignSigns(std::vector<OrientationKey>& keys)
{
    for (std::size_t i = 1; i < keys.size(); ++i)
        keys[i].rotation = alignedWith(keys[i].rotation, keys[i - 1].rotation);
}

OrientationSample sampleOfRaw(const Eigen::Quaterniond& q, const Eigen::Quaterniond& dq)
{
    return {q.normalized(), normalizedDerivative(q, dq), angularVelocity(q, dq)};
}

const Eigen::Quaterniond kZeroQuaternion(0.0, 0.0, 0.0, 0.0);

} // namespace

OrientationCurve::OrientationCurve(std::vector<OrientationKey> keys)
    : keys_(std::move(keys))
{
    requireIncreasingTimes(keys_);
    for (OrientationKey& key : keys_)
        key.rotation.normalize();
    alignSigns(keys_);
}

OrientationSample OrientationCurve::sample(double time) const
{
    if (keys_.size() == 1 || time < startTime() || time > endTime()) {
        const Eigen::Quaterniond& held = time < startTime() ? keys_.front().rotation : keys_.back().rotation;
        return {held, kZeroQuaternion, Eigen::Vector3d::Zero()};
    }
    const std::size_t segment = segmentAt(keys_, time);
    const double duration = keys_[segment + 1].time - keys_[segment].time;
    return sampleSegment(segment, (time - keys_[segment].time) / duration, duration);
}

// --- slerp ------------------------------------------------------------------------------------------

SlerpCurve::SlerpCurve(std::vector<OrientationKey> keys)
    : OrientationCurve(std::move(keys))
{
}

OrientationSample SlerpCurve::sampleSegment(std::size_t segment, double u, double duration) const
{
    // q(u) = q₀·exp(u·v), v = log(q₀⁻¹q₁); dq/dt = q(u)·v / duration.
    const Eigen::Quaterniond& q0 = keys_[segment].rotation;
    const Eigen::Vector3d v = quatLog(q0.conjugate() * keys_[segment + 1].rotation);
    const Eigen::Quaterniond q = q0 * quatExp(u * v);
    const Eigen::Quaterniond dq = q * pureQuaternion(v / duration);
    return {q, dq, angularVelocity(q, dq)};
}

// --- nlerp ------------------------------------------------------------------------------------------

NlerpCurve::NlerpCurve(std::vector<OrientationKey> keys)
    : OrientationCurve(std::move(keys))
{
}

OrientationSample NlerpCurve::sampleSegment(std::size_t segment, double u, double duration) const
{
    const Eigen::Quaterniond& q0 = keys_[segment].rotation;
    const Eigen::Quaterniond& q1 = keys_[segment + 1].rotation;
    const Eigen::Quaterniond p = linearCombination(1.0 - u, q0, u, q1);
    const Eigen::Quaterniond dp = linearCombination(1.0 / duration, q1, -1.0 / duration, q0);
    return sampleOfRaw(p, dp);
}

// --- squad ------------------------------------------------------------------------------------------

SquadCurve::SquadCurve(std::vector<OrientationKey> keys)
    : OrientationCurve(std::move(keys))
{
    inner_.reserve(keys_.size());
    for (std::size_t i = 0; i < keys_.size(); ++i) {
        const Eigen::Quaterniond& q = keys_[i].rotation;
        if (i == 0 || i + 1 == keys_.size()) {
            inner_.push_back(q);
            continue;
        }
        // The neighbours are on qᵢ's hemisphere (alignSigns), so each logarithm is at most π/2 long
        // and sᵢ lies within π/4 of qᵢ on the sphere, on the same sheet as the keys.
        const Eigen::Vector3d toNext = quatLogOnSphere(q.conjugate() * keys_[i + 1].rotation);
        const Eigen::Vector3d toPrevious = quatLogOnSphere(q.conjugate() * keys_[i - 1].rotation);
        inner_.push_back(q * quatExp(-0.25 * (toNext + toPrevious)));
    }
}

OrientationSample SquadCurve::sampleSegment(std::size_t segment, double u, double duration) const
{
    // Q = slerp(A, B, h) = A·exp(h·L) with A = slerp(qᵢ, qᵢ₊₁, u), B = slerp(sᵢ, sᵢ₊₁, u),
    // h = 2u(1−u), L = log(A⁻¹B). By the chain rule, with ′ = d/du:
    //   A′ = A·vₐ, B′ = B·v_b, C = A⁻¹B, C′ = A′*·B + A*·B′, L′ = dlog_C(C′),
    //   Q′ = A′·exp(hL) + A·dexp_{hL}(h′L + hL′).
    //
    // All four points stay as stored, on one sheet of the 4-sphere: the keys are sign-aligned and
    // each sᵢ lies within π/4 of its qᵢ, so both slerps and the outer one run along the sphere with
    // quatLogOnSphere. A short-arc logarithm there would flip B or L to −B or −L wherever the
    // rotation between them passes 180° (as between sᵢ and sᵢ₊₁ when keys are ~180° apart), and the
    // curve would jump.
    const Eigen::Quaterniond& qa = keys_[segment].rotation;
    const Eigen::Quaterniond& sa = inner_[segment];
    const Eigen::Vector3d va = quatLogOnSphere(qa.conjugate() * keys_[segment + 1].rotation);
    const Eigen::Vector3d vb = quatLogOnSphere(sa.conjugate() * inner_[segment + 1]);
    const Eigen::Quaterniond a = qa * quatExp(u * va);
    const Eigen::Quaterniond b = sa * quatExp(u * vb);
    const Eigen::Quaterniond da = a * pureQuaternion(va);
    const Eigen::Quaterniond db = b * pureQuaternion(vb);

    const double h = 2.0 * u * (1.0 - u);
    const double dh = 2.0 - 4.0 * u;
    const Eigen::Quaterniond c = a.conjugate() * b;
    const Eigen::Quaterniond dc = linearCombination(1.0, da.conjugate() * b, 1.0, a.conjugate() * db);
    const Eigen::Vector3d l = quatLogOnSphere(c);
    const Eigen::Vector3d dl = quatLogOnSphereDerivative(c, dc);

    const Eigen::Quaterniond e = quatExp(h * l);
    const Eigen::Quaterniond de = quatExpDerivative(h * l, dh * l + h * dl);
    const Eigen::Quaterniond q = (a * e).normalized();
    const Eigen::Quaterniond dq = linearCombination(1.0 / duration, da * e, 1.0 / duration, a * de);
    return {q, dq, angularVelocity(q, dq)};
}

// --- Hermite ----------------------------------------------------------------------------------------

HermiteQuaternionSpline::HermiteQuaternionSpline(std::vector<HermiteControlPoint> points)
    : OrientationCurve(keysOf(points))
    , points_(std::move(points))
{
}

std::vector<OrientationKey> HermiteQuaternionSpline::keysOf(const std::vector<HermiteControlPoint>& points)
{
    std::vector<OrientationKey> keys;
    keys.reserve(points.size());
    for (const HermiteControlPoint& point : points) {
        if (point.value.squaredNorm() == 0.0)
            throw std::invalid_argument("a Hermite control point needs a nonzero quaternion");
        keys.push_back({point.time, point.value});
    }
    return keys;
}

HermiteQuaternionSpline HermiteQuaternionSpline::throughKeys(std::vector<OrientationKey> keys, KeyDerivatives rule)
{
    for (OrientationKey& key : keys)
        key.rotation.normalize();
    alignSigns(keys);
    std::vector<HermiteControlPoint> points(keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i) {
        points[i].time = keys[i].time;
        points[i].value = keys[i].rotation;
        if (keys.size() < 2)
            continue;
        const std::size_t before = i == 0 ? 0 : i - 1;
        const std::size_t after = i + 1 == keys.size() ? i : i + 1;
        const double span = keys[after].time - keys[before].time;
        if (rule == KeyDerivatives::Chord) {
            points[i].derivative = linearCombination(1.0 / span, keys[after].rotation, -1.0 / span, keys[before].rotation);
            continue;
        }
        // Half the body angular velocity, (log(qᵢ⁻¹qᵢ₊₁) − log(qᵢ⁻¹qᵢ₋₁))/(tᵢ₊₁ − tᵢ₋₁), times qᵢ.
        const Eigen::Quaterniond inverse = keys[i].rotation.conjugate();
        const Eigen::Vector3d halfOmega =
            (quatLog(inverse * keys[after].rotation) - quatLog(inverse * keys[before].rotation)) / span;
        points[i].derivative = keys[i].rotation * Eigen::Quaterniond(0.0, halfOmega.x(), halfOmega.y(), halfOmega.z());
    }
    return HermiteQuaternionSpline(std::move(points));
}

HermiteQuaternionSpline::RawSample HermiteQuaternionSpline::raw(double time) const
{
    if (points_.size() == 1 || time < startTime() || time > endTime()) {
        const Eigen::Quaterniond& held = time < startTime() ? points_.front().value : points_.back().value;
        return {held, kZeroQuaternion, kZeroQuaternion};
    }
    const std::size_t segment = segmentAt(points_, time);
    const double duration = points_[segment + 1].time - points_[segment].time;
    return rawSegment(segment, (time - points_[segment].time) / duration, duration);
}

HermiteQuaternionSpline::RawSample HermiteQuaternionSpline::rawSegment(std::size_t segment, double u,
                                                                       double duration) const
{
    // p(u) = h₀₀q₀ + h₁₀Δm₀ + h₀₁q₁ + h₁₁Δm₁ with the cubic Hermite basis, and d/dt = (1/Δ) d/du.
    const HermiteControlPoint& p0 = points_[segment];
    const HermiteControlPoint& p1 = points_[segment + 1];
    const HermiteBasis basis = hermiteBasis(u);
    const auto combine = [&](const std::array<double, 4>& w, double scale) {
        Eigen::Quaterniond r;
        r.coeffs() = scale * (w[0] * p0.value.coeffs() + w[1] * duration * p0.derivative.coeffs() +
                              w[2] * p1.value.coeffs() + w[3] * duration * p1.derivative.coeffs());
        return r;
    };
    return {combine(basis.value, 1.0), combine(basis.first, 1.0 / duration),
            combine(basis.second, 1.0 / (duration * duration))};
}

OrientationSample HermiteQuaternionSpline::sampleSegment(std::size_t segment, double u, double duration) const
{
    const RawSample r = rawSegment(segment, u, duration);
    return sampleOfRaw(r.value, r.derivative);
}

// --- Euler angles -----------------------------------------------------------------------------------

namespace {

std::vector<Eigen::Quaterniond> rotationsOf(const std::vector<OrientationKey>& keys)
{
    std::vector<Eigen::Quaterniond> rotations;
    rotations.reserve(keys.size());
    for (const OrientationKey& key : keys)
        rotations.push_back(key.rotation);
    return rotations;
}

} // namespace

namespace {

// The automatic slope of one angle at each key (orientation_curves.h): zero at the ends and at extrema, the
// neighbours' chord (pᵢ₊₁ − pᵢ₋₁)/(tᵢ₊₁ − tᵢ₋₁) elsewhere, at most three times either side's chord slope.
std::vector<Eigen::Vector3d> automaticSlopes(const std::vector<double>& times, const std::vector<Eigen::Vector3d>& angles)
{
    std::vector<Eigen::Vector3d> slopes(angles.size(), Eigen::Vector3d::Zero());
    for (std::size_t i = 1; i + 1 < angles.size(); ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            const double before = (angles[i][axis] - angles[i - 1][axis]) / (times[i] - times[i - 1]);
            const double after = (angles[i + 1][axis] - angles[i][axis]) / (times[i + 1] - times[i]);
            if (before * after <= 0.0)
                continue; // an extremum, or flat on one side
            const double chord = (angles[i + 1][axis] - angles[i - 1][axis]) / (times[i + 1] - times[i - 1]);
            const double limit = 3.0 * std::min(std::abs(before), std::abs(after));
            slopes[i][axis] = std::copysign(std::min(std::abs(chord), limit), chord);
        }
    }
    return slopes;
}

std::vector<OrientationKey> rotationsOfAngles(const std::vector<EulerAngleCurve::AngleKey>& keys,
                                              const EulerConvention& convention)
{
    std::vector<OrientationKey> rotations;
    rotations.reserve(keys.size());
    for (const EulerAngleCurve::AngleKey& key : keys)
        rotations.push_back({key.time, quaternionFromEulerAngles(key.angles, convention)});
    return rotations;
}

std::vector<double> timesOf(const std::vector<OrientationKey>& keys)
{
    std::vector<double> times;
    times.reserve(keys.size());
    for (const OrientationKey& key : keys)
        times.push_back(key.time);
    return times;
}

} // namespace

EulerAngleCurve::EulerAngleCurve(std::vector<OrientationKey> keys, const EulerConvention& convention, Shape shape)
    : OrientationCurve(std::move(keys))
    , convention_(convention)
    , shape_(shape)
    , angles_(unwrappedEulerAngles(rotationsOf(keys_), convention))
    , slopes_(shape == Shape::Cubic ? automaticSlopes(timesOf(keys_), angles_) : std::vector<Eigen::Vector3d>())
{
}

EulerAngleCurve::EulerAngleCurve(std::vector<OrientationKey> keys, const EulerConvention& convention, Shape shape,
                                 std::vector<Eigen::Vector3d> angles)
    : OrientationCurve(std::move(keys))
    , convention_(convention)
    , shape_(shape)
    , angles_(std::move(angles))
    , slopes_(shape == Shape::Cubic ? automaticSlopes(timesOf(keys_), angles_) : std::vector<Eigen::Vector3d>())
{
}

EulerAngleCurve EulerAngleCurve::throughAngles(std::vector<AngleKey> keys, const EulerConvention& convention,
                                               Shape shape)
{
    std::vector<Eigen::Vector3d> angles;
    angles.reserve(keys.size());
    for (const AngleKey& key : keys)
        angles.push_back(key.angles);
    return EulerAngleCurve(rotationsOfAngles(keys, convention), convention, shape, std::move(angles));
}

Eigen::Vector3d EulerAngleCurve::anglesAt(double time) const
{
    if (keys_.size() == 1 || time <= startTime())
        return angles_.front();
    if (time >= endTime())
        return angles_.back();
    const std::size_t segment = segmentAt(keys_, time);
    const double duration = keys_[segment + 1].time - keys_[segment].time;
    return anglesInSegment(segment, (time - keys_[segment].time) / duration, duration).first;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> EulerAngleCurve::anglesInSegment(std::size_t segment, double u,
                                                                             double duration) const
{
    // Linear: the straight line. Cubic: the Hermite basis, p(u) = h₀₀p₀ + h₁₀·T·m₀ + h₀₁p₁ + h₁₁·T·m₁ with T the
    // segment's duration and m the slopes at its keys.
    const Eigen::Vector3d& p0 = angles_[segment];
    const Eigen::Vector3d& p1 = angles_[segment + 1];
    if (shape_ == Shape::Linear)
        return {(1.0 - u) * p0 + u * p1, (p1 - p0) / duration};
    const Eigen::Vector3d m0 = slopes_[segment] * duration;
    const Eigen::Vector3d m1 = slopes_[segment + 1] * duration;
    const double u2 = u * u;
    const double u3 = u2 * u;
    const Eigen::Vector3d value = (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * m0 + (-2 * u3 + 3 * u2) * p1 +
                                  (u3 - u2) * m1;
    const Eigen::Vector3d perU =
        (6 * u2 - 6 * u) * p0 + (3 * u2 - 4 * u + 1) * m0 + (-6 * u2 + 6 * u) * p1 + (3 * u2 - 2 * u) * m1;
    return {value, perU / duration};
}

OrientationSample EulerAngleCurve::sampleSegment(std::size_t segment, double u, double duration) const
{
    // q = f₁·f₂·f₃ with fₙ = (cos(eₙ/2), sin(eₙ/2)·axisₙ) in multiplication order, so dfₙ/dt = fₙ·(0, axisₙ/2)·ėₙ
    // and dq/dt follows by the product rule.
    const auto [angles, rates] = anglesInSegment(segment, u, duration);
    std::array<int, 3> order{0, 1, 2};
    if (convention_.frame == AngleFrame::Extrinsic)
        order = {2, 1, 0};
    std::array<Eigen::Quaterniond, 3> factors;
    std::array<Eigen::Quaterniond, 3> derivatives;
    for (int n = 0; n < 3; ++n) {
        const int which = order[static_cast<std::size_t>(n)];
        Eigen::Vector3d axis = Eigen::Vector3d::Zero();
        axis[convention_.axes[static_cast<std::size_t>(which)]] = 1.0;
        factors[static_cast<std::size_t>(n)] = quatExp(0.5 * angles[which] * axis);
        derivatives[static_cast<std::size_t>(n)] =
            factors[static_cast<std::size_t>(n)] * pureQuaternion(0.5 * rates[which] * axis);
    }
    const Eigen::Quaterniond q = factors[0] * factors[1] * factors[2];
    Eigen::Quaterniond dq;
    dq.coeffs() = (derivatives[0] * factors[1] * factors[2]).coeffs() +
                  (factors[0] * derivatives[1] * factors[2]).coeffs() +
                  (factors[0] * factors[1] * derivatives[2]).coeffs();
    return {q, dq, angularVelocity(q, dq)};
}

// --- factory ----------------------------------------------------------------------------------------


std::optional<InterpolationMethod> parseInterpolationMethod(std::string_view name)
{
    return valueNamed(kInterpolationMethodNames, name);
}

bool interpolatesAngles(InterpolationMethod method)
{
    return method == InterpolationMethod::Euler || method == InterpolationMethod::EulerCubic;
}

std::string_view interpolationMethodName(InterpolationMethod method)
{
    return nameOf(kInterpolationMethodNames, method);
}

std::unique_ptr<OrientationCurve> makeOrientationCurve(InterpolationMethod method, std::vector<OrientationKey> keys,
                                                       const EulerConvention& convention)
{
    switch (method) {
    case InterpolationMethod::Slerp:
        return std::make_unique<SlerpCurve>(std::move(keys));
    case InterpolationMethod::Nlerp:
        return std::make_unique<NlerpCurve>(std::move(keys));
    case InterpolationMethod::Squad:
        return std::make_unique<SquadCurve>(std::move(keys));
    case InterpolationMethod::Hermite:
        return std::make_unique<HermiteQuaternionSpline>(HermiteQuaternionSpline::throughKeys(std::move(keys)));
    case InterpolationMethod::Euler:
        return std::make_unique<EulerAngleCurve>(std::move(keys), convention, EulerAngleCurve::Shape::Linear);
    case InterpolationMethod::EulerCubic:
        return std::make_unique<EulerAngleCurve>(std::move(keys), convention, EulerAngleCurve::Shape::Cubic);
    case InterpolationMethod::Screw:
        throw std::invalid_argument("screw interpolation moves poses, not orientations: use Polyscrew");
    case InterpolationMethod::Ballistic:
        break;
    }
    throw std::invalid_argument("ballistic interpolation is a body's free flight, not an orientation curve");
}

} // namespace gyre
