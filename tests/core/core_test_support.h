#pragma once
// Helpers shared by the motion-core tests: seeded random rotations and poses, comparisons that treat
// q and −q as the same rotation, and reference constructions written independently of src/core
// (elementary rotation matrices, Rodrigues' formula, the rotation vector of a quaternion, and the
// SE(3) exponential and logarithm with 3×3 and 4×4 matrices). None of them calls gyre code, so the
// tests compare the core against mathematics, not against itself.

#include "core/euler_angles.h"
#include "core/orientation_curves.h"
#include "core/pose.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <QString>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

// Fails the current test function with `message` (a QString expression, built only on failure)
// unless `condition` holds. Use it in the test function itself, or check QTest::currentTestFailed()
// after calling a helper that uses it.
#define GYRE_CHECK(condition, message)                                                                   \
    do {                                                                                                 \
        if (!(condition)) {                                                                              \
            QFAIL(qPrintable(QStringLiteral("%1\n   check: %2").arg(QString(message), QStringLiteral(#condition)))); \
        }                                                                                                \
    } while (false)

namespace gyre::test {

inline constexpr double kPi = std::numbers::pi;

using Vector6d = Eigen::Matrix<double, 6, 1>;

// ---------------------------------------------------------------------------------------------
// Formatting for failure messages: full precision, quaternions as w, x, y, z.

inline QString str(double x) { return QString::number(x, 'g', 17); }

inline QString str(const Eigen::Vector3d& v)
{
    return QStringLiteral("(%1, %2, %3)").arg(str(v.x()), str(v.y()), str(v.z()));
}

inline QString str(const Eigen::Quaterniond& q)
{
    return QStringLiteral("[w %1, x %2, y %3, z %4]").arg(str(q.w()), str(q.x()), str(q.y()), str(q.z()));
}

inline QString str(const Pose& p)
{
    return QStringLiteral("{orientation %1, position %2}").arg(str(p.orientation), str(p.position));
}

// ---------------------------------------------------------------------------------------------
// Reference rotation constructions.

// The unit quaternion (cos(θ/2), sin(θ/2)·n) of a rotation by θ about the unit vector n.
inline Eigen::Quaterniond axisAngleQuaternion(const Eigen::Vector3d& unitAxis, double angle)
{
    const double s = std::sin(0.5 * angle);
    return Eigen::Quaterniond(std::cos(0.5 * angle), s * unitAxis.x(), s * unitAxis.y(), s * unitAxis.z());
}

// The rotation vector θ·n of a unit quaternion on the short arc (θ ∈ [0, π]), accurate for tiny and
// near-π angles: θ = 2·atan2(|v|, |w|), and θ/|v| is well conditioned as |v| → 0.
inline Eigen::Vector3d rotationVectorOf(const Eigen::Quaterniond& q)
{
    Eigen::Vector3d v = q.vec();
    double w = q.w();
    if (w < 0.0) {
        v = -v;
        w = -w;
    }
    const double n = v.norm();
    if (n == 0.0)
        return Eigen::Vector3d::Zero();
    return (2.0 * std::atan2(n, w) / n) * v;
}

// The quaternion of a rotation vector r: (cos(|r|/2), sin(|r|/2)·r/|r|), with sin(x)/x by series.
inline Eigen::Quaterniond quaternionOfRotationVector(const Eigen::Vector3d& r)
{
    const double theta = r.norm();
    const double half = 0.5 * theta;
    const double sinHalfOverTheta =
        theta < 1e-4 ? 0.5 - half * half / 12.0 + half * half * half * half / 240.0 : std::sin(half) / theta;
    const Eigen::Vector3d v = sinHalfOverTheta * r;
    return Eigen::Quaterniond(std::cos(half), v.x(), v.y(), v.z());
}

// The angle of the rotation a⁻¹b, in [0, π] (a and b unit).
inline double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    const Eigen::Quaterniond d = a.conjugate() * b;
    return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

// min(|a − b|, |a + b|) over the four coefficients: zero iff a and b are the same rotation.
inline double distanceUpToSign(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    return std::min((a.coeffs() - b.coeffs()).norm(), (a.coeffs() + b.coeffs()).norm());
}

// b or −b, whichever is nearer a in R⁴.
inline Eigen::Quaterniond sameHemisphere(const Eigen::Quaterniond& b, const Eigen::Quaterniond& a)
{
    if (a.coeffs().dot(b.coeffs()) >= 0.0)
        return b;
    Eigen::Quaterniond r;
    r.coeffs() = -b.coeffs();
    return r;
}

inline Eigen::Quaterniond negated(const Eigen::Quaterniond& q)
{
    Eigen::Quaterniond r;
    r.coeffs() = -q.coeffs();
    return r;
}

inline Eigen::Quaterniond combination(double a, const Eigen::Quaterniond& p, double b, const Eigen::Quaterniond& q)
{
    Eigen::Quaterniond r;
    r.coeffs() = a * p.coeffs() + b * q.coeffs();
    return r;
}

// The pure quaternion (0, v).
inline Eigen::Quaterniond pure(const Eigen::Vector3d& v) { return Eigen::Quaterniond(0.0, v.x(), v.y(), v.z()); }

inline Eigen::Matrix3d hat(const Eigen::Vector3d& v)
{
    Eigen::Matrix3d m;
    m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
    return m;
}

// Rotation about coordinate axis `axis` (0 = x, 1 = y, 2 = z) by `angle`, written out.
inline Eigen::Matrix3d elementaryRotation(int axis, double angle)
{
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    Eigen::Matrix3d m;
    switch (axis) {
    case 0:
        m << 1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c;
        break;
    case 1:
        m << c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c;
        break;
    default:
        m << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
        break;
    }
    return m;
}

// Rodrigues: R = I + (sin θ/θ)·Φ + ((1 − cos θ)/θ²)·Φ², Φ = hat(r), θ = |r|, with 1 − cos θ written
// as 2 sin²(θ/2) (no cancellation) and series for small θ.
inline Eigen::Matrix3d rodrigues(const Eigen::Vector3d& r)
{
    const double theta = r.norm();
    const double t2 = theta * theta;
    double a = 0.0;
    double b = 0.0;
    if (theta < 1e-4) {
        a = 1.0 - t2 / 6.0 + t2 * t2 / 120.0;
        b = 0.5 - t2 / 24.0 + t2 * t2 / 720.0;
    } else {
        const double s = std::sin(0.5 * theta);
        a = std::sin(theta) / theta;
        b = 2.0 * s * s / t2;
    }
    const Eigen::Matrix3d phi = hat(r);
    return Eigen::Matrix3d::Identity() + a * phi + b * phi * phi;
}

// ---------------------------------------------------------------------------------------------
// SE(3) with homogeneous 4×4 matrices; a twist ξ = (ρ, φ), translation part first.

inline Eigen::Matrix4d poseMatrix(const Pose& pose)
{
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = pose.orientation.normalized().toRotationMatrix();
    m.topRightCorner<3, 1>() = pose.position;
    return m;
}

inline Eigen::Matrix4d inverseRigid(const Eigen::Matrix4d& m)
{
    Eigen::Matrix4d r = Eigen::Matrix4d::Identity();
    const Eigen::Matrix3d rt = m.topLeftCorner<3, 3>().transpose();
    r.topLeftCorner<3, 3>() = rt;
    r.topRightCorner<3, 1>() = -rt * m.topRightCorner<3, 1>();
    return r;
}

// V = I + ((1 − cos θ)/θ²)·Φ + ((θ − sin θ)/θ³)·Φ², series below θ = 1e-2 (the first terms left
// out are below 1e-17 there).
inline Eigen::Matrix3d se3V(const Eigen::Vector3d& phi)
{
    const double theta = phi.norm();
    const double t2 = theta * theta;
    double b = 0.0;
    double c = 0.0;
    if (theta < 1e-2) {
        b = 0.5 - t2 / 24.0 + t2 * t2 / 720.0 - t2 * t2 * t2 / 40320.0;
        c = 1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0 - t2 * t2 * t2 / 362880.0;
    } else {
        const double s = std::sin(0.5 * theta);
        b = 2.0 * s * s / t2;
        c = (theta - std::sin(theta)) / (t2 * theta);
    }
    const Eigen::Matrix3d h = hat(phi);
    return Eigen::Matrix3d::Identity() + b * h + c * h * h;
}

// V⁻¹ = I − Φ/2 + (1/θ²)·(1 − (θ/2)·cot(θ/2))·Φ², series below θ = 1e-2.
inline Eigen::Matrix3d se3VInverse(const Eigen::Vector3d& phi)
{
    const double theta = phi.norm();
    const double t2 = theta * theta;
    double c = 0.0;
    if (theta < 1e-2)
        c = 1.0 / 12.0 + t2 / 720.0 + t2 * t2 / 30240.0 + t2 * t2 * t2 / 1209600.0;
    else
        c = (1.0 - 0.5 * theta / std::tan(0.5 * theta)) / t2;
    const Eigen::Matrix3d h = hat(phi);
    return Eigen::Matrix3d::Identity() - 0.5 * h + c * h * h;
}

inline Eigen::Matrix4d se3Exp(const Vector6d& xi)
{
    const Eigen::Vector3d rho = xi.head<3>();
    const Eigen::Vector3d phi = xi.tail<3>();
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = rodrigues(phi);
    m.topRightCorner<3, 1>() = se3V(phi) * rho;
    return m;
}

// The principal logarithm (rotation angle in [0, π]); φ comes from the quaternion of the rotation
// block, which stays well conditioned near 0 and near π.
inline Vector6d se3Log(const Eigen::Matrix4d& m)
{
    const Eigen::Matrix3d r = m.topLeftCorner<3, 3>();
    const Eigen::Vector3d phi = rotationVectorOf(Eigen::Quaterniond(r));
    Vector6d xi;
    xi.head<3>() = se3VInverse(phi) * m.topRightCorner<3, 1>();
    xi.tail<3>() = phi;
    return xi;
}

// The SE(3) geodesic La·exp(t·log(La⁻¹Lb)).
inline Eigen::Matrix4d geodesic(const Pose& a, const Pose& b, double t)
{
    const Eigen::Matrix4d ma = poseMatrix(a);
    const Vector6d xi = se3Log(inverseRigid(ma) * poseMatrix(b));
    return ma * se3Exp(t * xi);
}

// How far pose p is from the homogeneous matrix m: the larger of the rotation blocks' max-abs
// difference and the translation difference relative to max(1, |translation|).
inline double poseMatrixDistance(const Pose& p, const Eigen::Matrix4d& m)
{
    const Eigen::Matrix3d r = p.orientation.toRotationMatrix();
    const double rotation = (r - m.topLeftCorner<3, 3>()).cwiseAbs().maxCoeff();
    const Eigen::Vector3d t = m.topRightCorner<3, 1>();
    const double translation = (p.position - t).norm() / std::max(1.0, t.norm());
    return std::max(rotation, translation);
}

// Orientation up to sign and position (absolute) of two poses.
inline double poseDistance(const Pose& a, const Pose& b)
{
    return std::max(distanceUpToSign(a.orientation, b.orientation), (a.position - b.position).norm());
}

// A rotation by `angle` about the line through `centre` with unit direction `axis`, followed by a
// slide `slide` along the axis, applied (on the left, in world) to `pose`.
inline Pose helicalMotion(const Pose& pose, const Eigen::Vector3d& centre, const Eigen::Vector3d& axis, double angle,
                          double slide)
{
    const Eigen::Quaterniond q = axisAngleQuaternion(axis, angle);
    Pose moved;
    moved.orientation = q * pose.orientation;
    moved.position = centre + q * (pose.position - centre) + slide * axis;
    return moved;
}

// ---------------------------------------------------------------------------------------------
// Seeded randomness.

class Random {
public:
    explicit Random(std::uint64_t seed = 0x67797265u) : engine_(seed) {}

    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
    double normal() { return normal_(engine_); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }

    Eigen::Vector3d vector(double scale)
    {
        return Eigen::Vector3d(uniform(-scale, scale), uniform(-scale, scale), uniform(-scale, scale));
    }

    Eigen::Vector3d unitVector()
    {
        for (;;) {
            const Eigen::Vector3d v(normal(), normal(), normal());
            const double n = v.norm();
            if (n > 1e-3)
                return v / n;
        }
    }

    // Uniform on SO(3): a normalised Gaussian 4-vector, with a random sign.
    Eigen::Quaterniond rotation()
    {
        for (;;) {
            Eigen::Quaterniond q(normal(), normal(), normal(), normal());
            const double n = q.coeffs().norm();
            if (n > 1e-3) {
                q.coeffs() /= n;
                return q;
            }
        }
    }

    // A rotation by an angle drawn uniformly from [minAngle, maxAngle] about a random axis.
    Eigen::Quaterniond rotationWithAngle(double minAngle, double maxAngle)
    {
        return axisAngleQuaternion(unitVector(), uniform(minAngle, maxAngle));
    }

    Pose pose(double positionScale)
    {
        Pose p;
        p.orientation = rotation();
        p.position = vector(positionScale);
        return p;
    }

private:
    std::mt19937_64 engine_;
    std::normal_distribution<double> normal_;
};

// An interpolation method and the Euler convention it uses (ignored but for Euler).
struct CurveCase {
    InterpolationMethod method;
    EulerConvention convention;
    QString label;
};

// Every orientation curve through keys, once per Euler convention worth telling apart. Screw moves
// poses, not orientations: its tracks are subdivided (tst_subdivision, tst_polyscrew).
inline std::vector<CurveCase> allCurveCases()
{
    return {
        {InterpolationMethod::Slerp, {}, QStringLiteral("slerp")},
        {InterpolationMethod::Nlerp, {}, QStringLiteral("nlerp")},
        {InterpolationMethod::Squad, {}, QStringLiteral("squad")},
        {InterpolationMethod::Hermite, {}, QStringLiteral("hermite")},
        {InterpolationMethod::Euler, *EulerConvention::parse("xyz", AngleFrame::Extrinsic), QStringLiteral("euler extrinsic xyz")},
        {InterpolationMethod::Euler, *EulerConvention::parse("zxz", AngleFrame::Intrinsic), QStringLiteral("euler intrinsic zxz")},
        {InterpolationMethod::Euler, *EulerConvention::parse("yxz", AngleFrame::Intrinsic), QStringLiteral("euler intrinsic yxz")},
    };
}

} // namespace gyre::test
