#include "fit/segment_energy.h"

#include <Eigen/Geometry>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>

namespace gyre::fit {

namespace {

using Matrix34 = Eigen::Matrix<double, 3, 4>;
using JacobianMap = Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor>>;

// [v]×, the matrix with [v]× x = v × x.
Eigen::Matrix3d crossMatrix(const Eigen::Vector3d& v)
{
    Eigen::Matrix3d m;
    m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
    return m;
}

// The weights of a one-second segment's basis at u, for a segment of h seconds with 1/h and 1/h²
// given. The slope weights h₁₀, h₁₁ multiply h·d, since d is a derivative in time, not in u; each
// derivative in time divides by h once more.
NodeBasis scaledBasis(const HermiteBasis& basis, double h, double inverse, double inverseSquare)
{
    return {{basis.value[0], basis.value[1] * h, basis.value[2], basis.value[3] * h},
            {basis.first[0] * inverse, basis.first[1], basis.first[2] * inverse, basis.first[3]},
            {basis.second[0] * inverseSquare, basis.second[1] * inverse, basis.second[2] * inverseSquare,
             basis.second[3] * inverse}};
}

} // namespace

NodeBasis nodeBasis(double u, double duration)
{
    const double inverse = 1.0 / duration;
    return scaledBasis(hermiteBasis(u), duration, inverse, inverse * inverse);
}

SegmentQuadrature::SegmentQuadrature(const QuadratureRule& rule)
{
    nodes_.reserve(rule.nodes.size());
    for (std::size_t j = 0; j < rule.nodes.size(); ++j)
        nodes_.push_back({rule.nodes[j], std::sqrt(rule.weights[j]), hermiteBasis(rule.nodes[j])});
}

SegmentEnergy::SegmentEnergy(double duration, std::shared_ptr<const SegmentQuadrature> quadrature,
                             std::vector<Eigen::Vector3d> targets, const EnergyWeights& weights)
    : duration_(duration)
    , quadrature_(std::move(quadrature))
    , targets_(std::move(targets))
    , angularScale_(std::sqrt(weights.beta * duration))
    , tangentialScale_(std::sqrt(weights.alpha * duration))
    , unitScale_(std::sqrt(weights.unitNorm * duration))
{
    if (targets_.size() != quadrature_->nodes().size())
        throw std::invalid_argument("a segment's energy needs one target a quadrature node");
    set_num_residuals(static_cast<int>(targets_.size()) * kResidualsPerNode);
    *mutable_parameter_block_sizes() = {4, 4, 4, 4};
}

bool SegmentEnergy::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const
{
    const std::array<Eigen::Map<const Eigen::Vector4d>, 4> control{
        Eigen::Map<const Eigen::Vector4d>(parameters[0]), Eigen::Map<const Eigen::Vector4d>(parameters[1]),
        Eigen::Map<const Eigen::Vector4d>(parameters[2]), Eigen::Map<const Eigen::Vector4d>(parameters[3])};
    const Eigen::Matrix4d identity = Eigen::Matrix4d::Identity();
    const double inverse = 1.0 / duration_;
    const double inverseSquare = inverse * inverse;
    const std::vector<SegmentQuadrature::Node>& nodes = quadrature_->nodes();
    for (std::size_t j = 0; j < nodes.size(); ++j) {
        const NodeBasis b = scaledBasis(nodes[j].basis, duration_, inverse, inverseSquare);
        const double angularScale = angularScale_ * nodes[j].rootWeight;
        const double tangentialScale = tangentialScale_ * nodes[j].rootWeight;
        const double unitScale = unitScale_ * nodes[j].rootWeight;
        Eigen::Vector4d q = Eigen::Vector4d::Zero();
        Eigen::Vector4d dq = Eigen::Vector4d::Zero();
        Eigen::Vector4d ddq = Eigen::Vector4d::Zero();
        for (std::size_t k = 0; k < 4; ++k) {
            q += b.value[k] * control[k];
            dq += b.first[k] * control[k];
            ddq += b.second[k] * control[k];
        }
        const double norm2 = q.squaredNorm();
        if (!(norm2 > 1e-12))
            return false;  // the spline passed through zero: no rotation there, reject the step
        const double w = q[0];
        const double dw = dq[0];
        const Eigen::Vector3d v = q.tail<3>();
        const Eigen::Vector3d dv = dq.tail<3>();
        // vec(q′ q̄) = w v′ − w′ v + v × v′
        const Eigen::Vector3d g = w * dv - dw * v + v.cross(dv);
        const Eigen::Vector3d omega = (2.0 / norm2) * g;
        const double qDotAcceleration = q.dot(ddq);

        const int row = static_cast<int>(j) * kResidualsPerNode;
        Eigen::Map<Eigen::Vector3d>(residuals + row) = angularScale * (omega - targets_[j]);
        Eigen::Map<Eigen::Vector4d>(residuals + row + 3) =
            tangentialScale * (ddq - (qDotAcceleration / norm2) * q);
        residuals[row + 7] = unitScale * (1.0 - norm2);
        if (jacobians == nullptr)
            continue;

        // ∂ω/∂q = (2/|q|²)(∂g/∂q − ω qᵀ), ∂ω/∂q′ = (2/|q|²) ∂g/∂q′ with
        // ∂g/∂q = [v′ | −w′I − [v′]×] and ∂g/∂q′ = [−v | wI + [v]×].
        Matrix34 gByQ;
        gByQ << dv, -dw * Eigen::Matrix3d::Identity() - crossMatrix(dv);
        Matrix34 gByDq;
        gByDq << -v, w * Eigen::Matrix3d::Identity() + crossMatrix(v);
        const Matrix34 omegaByQ = angularScale * (2.0 / norm2) * (gByQ - omega * q.transpose());
        const Matrix34 omegaByDq = angularScale * (2.0 / norm2) * gByDq;
        // r_T = a − (q·a/|q|²) q with a = q″:
        // ∂r_T/∂q = −((q·a/|q|²) I + q aᵀ/|q|² − 2 (q·a) q qᵀ/|q|⁴),  ∂r_T/∂a = I − q qᵀ/|q|².
        const Eigen::Matrix4d tangentialByQ =
            -tangentialScale * ((qDotAcceleration / norm2) * identity + q * ddq.transpose() / norm2 -
                                     (2.0 * qDotAcceleration / (norm2 * norm2)) * q * q.transpose());
        const Eigen::Matrix4d tangentialByDdq = tangentialScale * (identity - q * q.transpose() / norm2);
        const Eigen::RowVector4d unitByQ = -2.0 * unitScale * q.transpose();
        for (std::size_t k = 0; k < 4; ++k) {
            if (jacobians[k] == nullptr)
                continue;
            JacobianMap jacobian(jacobians[k], num_residuals(), 4);
            jacobian.block<3, 4>(row, 0) = b.value[k] * omegaByQ + b.first[k] * omegaByDq;
            jacobian.block<4, 4>(row + 3, 0) = b.value[k] * tangentialByQ + b.second[k] * tangentialByDdq;
            jacobian.block<1, 4>(row + 7, 0) = b.value[k] * unitByQ;
        }
    }
    return true;
}

} // namespace gyre::fit
