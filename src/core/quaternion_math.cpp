#include "core/quaternion_math.h"

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
    const Eigen::Quaterniond relative = q0.conjugate() * alignedWith(q1, q0);
    return (q0 * quatExp(t * quatLog(relative))).normalized();
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
