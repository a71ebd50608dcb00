#include "core/quaternion_math.h"

#include "core/fast_trig.h"

#include <cmath>

namespace gyre {

namespace {

// Below this |v| the Taylor series of sin θ/θ and its derivative are exact to double precision.
constexpr double kSeriesThreshold = 1e-4;

// sin θ / θ
double sinc(double theta)
{
    if (theta < kSeriesThreshold)
        return 1.0 - theta * theta / 6.0;
    return std::sin(theta) / theta;
}

// (θ cos θ − sin θ) / θ³, the derivative of sinc divided by θ.
double sincDerivativeOverTheta(double theta)
{
    if (theta < kSeriesThreshold)
        return -1.0 / 3.0 + theta * theta / 30.0;
    return (theta * std::cos(theta) - std::sin(theta)) / (theta * theta * theta);
}

// 1/√x. For x within 1e-8 of 1, as the squared norm of a unit quaternion is after rounding, it is
// 1 − (x − 1)/2, off by less than (3/8)·(1e-8)² < 4e-17, which spares a square root and a division.
double inverseSqrt(double x)
{
    if (std::abs(x - 1.0) < 1e-8) [[likely]]
        return 1.5 - 0.5 * x;
    return 1.0 / std::sqrt(x);
}

} // namespace

Eigen::Quaterniond quatExp(const Eigen::Vector3d& v)
{
    const double theta = v.norm();
    const Eigen::Vector3d vec = sinc(theta) * v;
    return Eigen::Quaterniond(std::cos(theta), vec.x(), vec.y(), vec.z());
}

Eigen::Vector3d quatLog(const Eigen::Quaterniond& q)
{
    return quatLogOnSphere(shortArc(q));
}

Eigen::Vector3d quatLogOnSphere(const Eigen::Quaterniond& q)
{
    const double s = q.vec().norm();
    if (s == 0.0)
        return Eigen::Vector3d::Zero();
    // atan2 keeps the angle exact for tiny s (≈ s/w), for w near 0 (angle near π/2) and past it.
    return (std::atan2(s, q.w()) / s) * q.vec();
}

Eigen::Quaterniond quatExpDerivative(const Eigen::Vector3d& v, const Eigen::Vector3d& dv)
{
    // exp(v) = (cos θ, sinc θ · v), θ = |v|, dθ = v·dv/θ:
    // d exp = (−sinc θ (v·dv), (sinc′θ/θ)(v·dv) v + sinc θ dv)
    const double theta = v.norm();
    const double projection = v.dot(dv);
    const double f = sinc(theta);
    const Eigen::Vector3d vec = sincDerivativeOverTheta(theta) * projection * v + f * dv;
    return Eigen::Quaterniond(-f * projection, vec.x(), vec.y(), vec.z());
}

Eigen::Vector3d quatLogDerivative(const Eigen::Quaterniond& q, const Eigen::Quaterniond& dq)
{
    // quatLog(q) = quatLogOnSphere(±q) with the sign that makes w ≥ 0; the same sign applies to dq.
    return q.w() < 0.0 ? quatLogOnSphereDerivative(scaled(q, -1.0), scaled(dq, -1.0))
                       : quatLogOnSphereDerivative(q, dq);
}

Eigen::Vector3d quatLogOnSphereDerivative(const Eigen::Quaterniond& q, const Eigen::Quaterniond& dq)
{
    // log(q) = k(s, w)·vec with k = atan2(s, w)/s, s = |vec|:
    //   ∂k/∂w = −1/(w² + s²),   (∂k/∂s)/s = (s w/(w² + s²) − atan2(s, w))/s³ =: m
    //   d log = (∂k/∂w · dw + m · (vec·dvec))·vec + k·dvec
    const double w = q.w();
    const Eigen::Vector3d vec = q.vec();
    const double dw = dq.w();
    const Eigen::Vector3d dvec = dq.vec();

    const double s = vec.norm();
    const double r2 = w * w + s * s;
    const double theta = std::atan2(s, w);
    double k = 0.0;
    double m = 0.0;
    if (s < kSeriesThreshold * w) {
        // x = s/w small: k = (1 − x²/3)/w, m = (−2/3 + 4x²/5)/w³ (series of atan x and x/(1 + x²)).
        const double x2 = (s / w) * (s / w);
        k = (1.0 - x2 / 3.0) / w;
        m = (-2.0 / 3.0 + 0.8 * x2) / (w * w * w);
    } else {
        k = theta / s;
        m = (s * w / r2 - theta) / (s * s * s);
    }
    return (-dw / r2 + m * vec.dot(dvec)) * vec + k * dvec;
}

Eigen::Quaterniond slerp(const Eigen::Quaterniond& q0, const Eigen::Quaterniond& q1, double t)
{
    // q0·exp(t·log r) over |q0|, for r = q0⁻¹q1 on q0's side. Written with r = (w, v)/|q0|², whose
    // w = q0·q1 ≥ 0 once q1 is aligned: if r/|r| = (cos θ, sin θ·n), exp(t·log r) = (cos tθ, sin tθ·n),
    // and q0·(0, v) = |q0|²·q1 − w·q0 =: d, so that
    //   slerp = (cos tθ·q0 + (sin tθ/s)·d)/|q0|,   s = |v| = |d|/|q0|,   θ = angle of (w, s).
    // No quaternion product is needed; θ comes from the core's fast arctangent, cos tθ and sin tθ from
    // its fast sine and cosine, so that one square root and one division remain.
    //
    // alignedWith(q1, q0) is a sign taken by copysign, with no branch: q1 is on either side of q0 as
    // often as not, and a branch would be mispredicted every other call. Adding +0 turns a dot product
    // of −0 into +0, which alignedWith does not flip either.
    const double dot = q1.coeffs().dot(q0.coeffs());
    const double side = std::copysign(1.0, dot + 0.0);
    const double w = side * dot;
    const double n0 = q0.squaredNorm();
    const double inverseNorm = inverseSqrt(n0);
    const Eigen::Vector4d d = (side * n0) * q1.coeffs() - w * q0.coeffs();
    const double s2 = d.squaredNorm() * (inverseNorm * inverseNorm);
    if (s2 == 0.0)
        return q0.normalized();
    const double s = std::sqrt(s2);
    const double inverseS = 1.0 / s;
    const double inverseRadius = inverseSqrt(w * w + s2);
    const double theta = fastAngleOnUnitCircle(w * inverseRadius, s * inverseRadius);
    const SinCos turn = fastSinCos(t * theta);
    Eigen::Quaterniond result;
    result.coeffs() = (inverseNorm * turn.cos) * q0.coeffs() + (inverseNorm * turn.sin * inverseS) * d;
    return result;
}

Eigen::Quaterniond nlerp(const Eigen::Quaterniond& q0, const Eigen::Quaterniond& q1, double t)
{
    return linearCombination(1.0 - t, q0, t, alignedWith(q1, q0)).normalized();
}

Eigen::Vector3d angularVelocity(const Eigen::Quaterniond& q, const Eigen::Quaterniond& dq)
{
    return 2.0 * (dq * q.conjugate()).vec() / q.squaredNorm();
}

Eigen::Quaterniond normalizedDerivative(const Eigen::Quaterniond& q, const Eigen::Quaterniond& dq)
{
    const double norm = q.norm();
    const double radial = q.coeffs().dot(dq.coeffs()) / (norm * norm * norm);
    return linearCombination(1.0 / norm, dq, -radial, q);
}

} // namespace gyre
