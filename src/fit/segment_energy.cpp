#include "fit/segment_energy.h"

#include "core/position_curve.h"

#include <Eigen/Geometry>

#include <cmath>
#include <cstddef>

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

} // namespace

NodeBasis nodeBasis(double u, double duration)
{
    const HermiteBasis basis = hermiteBasis(u);
    // The slope weights h₁₀, h₁₁ multiply h·d, since d is a derivative in time, not in u.
    const std::array<double, 4> slopeScale{1.0, duration, 1.0, duration};
    NodeBasis node{};
    for (std::size_t k = 0; k < 4; ++k) {
        node.value[k] = basis.value[k] * slopeScale[k];
        node.first[k] = basis.first[k] * slopeScale[k] / duration;
        node.second[k] = basis.second[k] * slopeScale[k] / (duration * duration);
    }
    return node;
}

SegmentEnergy::SegmentEnergy(double duration, const std::vector<double>& nodes,
                             const std::vector<double>& quadratureWeights, const std::vector<Eigen::Vector3d>& targets,
                             const EnergyWeights& weights)
{
    for (std::size_t j = 0; j < nodes.size(); ++j) {
        const double measure = quadratureWeights[j] * duration;
        nodes_.push_back({nodeBasis(nodes[j], duration), targets[j], std::sqrt(weights.beta * measure),
                          std::sqrt(weights.alpha * measure), std::sqrt(weights.unitNorm * measure)});
    }
    set_num_residuals(static_cast<int>(nodes_.size()) * kResidualsPerNode);
    *mutable_parameter_block_sizes() = {4, 4, 4, 4};
}

bool SegmentEnergy::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const
{
    const std::array<Eigen::Map<const Eigen::Vector4d>, 4> control{
        Eigen::Map<const Eigen::Vector4d>(parameters[0]), Eigen::Map<const Eigen::Vector4d>(parameters[1]),
        Eigen::Map<const Eigen::Vector4d>(parameters[2]), Eigen::Map<const Eigen::Vector4d>(parameters[3])};
    const Eigen::Matrix4d identity = Eigen::Matrix4d::Identity();
    for (std::size_t j = 0; j < nodes_.size(); ++j) {
        const Node& node = nodes_[j];
        const NodeBasis& b = node.basis;
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
        Eigen::Map<Eigen::Vector3d>(residuals + row) = node.angularScale * (omega - node.target);
        Eigen::Map<Eigen::Vector4d>(residuals + row + 3) =
            node.tangentialScale * (ddq - (qDotAcceleration / norm2) * q);
        residuals[row + 7] = node.unitScale * (1.0 - norm2);
        if (jacobians == nullptr)
            continue;

        // ∂ω/∂q = (2/|q|²)(∂g/∂q − ω qᵀ), ∂ω/∂q′ = (2/|q|²) ∂g/∂q′ with
        // ∂g/∂q = [v′ | −w′I − [v′]×] and ∂g/∂q′ = [−v | wI + [v]×].
        Matrix34 gByQ;
        gByQ << dv, -dw * Eigen::Matrix3d::Identity() - crossMatrix(dv);
        Matrix34 gByDq;
        gByDq << -v, w * Eigen::Matrix3d::Identity() + crossMatrix(v);
        const Matrix34 omegaByQ = node.angularScale * (2.0 / norm2) * (gByQ - omega * q.transpose());
        const Matrix34 omegaByDq = node.angularScale * (2.0 / norm2) * gByDq;
        // r_T = a − (q·a/|q|²) q with a = q″:
        // ∂r_T/∂q = −((q·a/|q|²) I + q aᵀ/|q|² − 2 (q·a) q qᵀ/|q|⁴),  ∂r_T/∂a = I − q qᵀ/|q|².
        const Eigen::Matrix4d tangentialByQ =
            -node.tangentialScale * ((qDotAcceleration / norm2) * identity + q * ddq.transpose() / norm2 -
                                     (2.0 * qDotAcceleration / (norm2 * norm2)) * q * q.transpose());
        const Eigen::Matrix4d tangentialByDdq = node.tangentialScale * (identity - q * q.transpose() / norm2);
        const Eigen::RowVector4d unitByQ = -2.0 * node.unitScale * q.transpose();
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
