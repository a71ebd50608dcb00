#pragma once
// The fit's energy over one segment of the Hermite quaternion spline, as Ceres residuals.
//
// On the segment [t₀, t₁], h = t₁ − t₀, the spline is q(t) = Σₖ bₖ(u)·cₖ with u = (t − t₀)/h, the
// control vectors c = (q₀, d₀, q₁, d₁) (values and time derivatives at both ends, each a quaternion
// stored w, x, y, z) and the Hermite weights b = (h₀₀, h·h₁₀, h₀₁, h·h₁₁); q′ and q″ use the weights'
// derivatives divided by h and h². At each quadrature node tⱼ with weight wⱼ (on [0, 1]) it gives
//
//   angular:    √(β wⱼ h) · (ω(tⱼ) − ωˢ(tⱼ)),   ω = 2·vec(q′ q̄)/|q|²        (3 residuals)
//   tangential: √(α wⱼ h) · (q″ − (q·q″/|q|²) q)                           (4 residuals)
//   unit norm:  √(μ wⱼ h) · (1 − |q|²)                                       (1 residual)
//
// whose squares sum to the quadrature of βW_A, αW_T (|q″|² − (q·q″)²/|q|², the paper's tangential
// acceleration) and μU. The Jacobians are analytic: every residual is a function of q, q′, q″ at the
// node, each linear in c.

#include "core/position_curve.h"
#include "fit/gauss_legendre.h"

#include <ceres/cost_function.h>

#include <Eigen/Core>

#include <array>
#include <memory>
#include <vector>

namespace gyre::fit {

struct EnergyWeights {
    double alpha = 0.002;  // tangential acceleration, W_T
    double beta = 1.0;     // angular-velocity deviation, W_A
    double unitNorm = 1.0; // penalty μ on U = ∫(1 − |q|²)² dt
};

// The Hermite weights of one quadrature node, already scaled by the segment's duration.
struct NodeBasis {
    std::array<double, 4> value;
    std::array<double, 4> first;
    std::array<double, 4> second;
};

// The weights of the four control vectors (q₀, d₀, q₁, d₁) at u for a segment of `duration` seconds.
NodeBasis nodeBasis(double u, double duration);

// A quadrature rule's nodes on [0, 1] with their Hermite weights and √wⱼ: what every segment of that
// many nodes shares, so that a segment keeps only its duration and its targets (24 bytes a node, not
// the 144 of a node's scaled weights). At 3,000 keys the segments' data then stays within a few
// hundred KB, where the scaled weights alone took 4 MB, twice the core's L2 cache, read twice an iteration.
class SegmentQuadrature {
public:
    explicit SegmentQuadrature(const QuadratureRule& rule);

    struct Node {
        double u;
        double rootWeight; // √wⱼ
        HermiteBasis basis; // at u, for a segment of one second
    };
    const std::vector<Node>& nodes() const { return nodes_; }

private:
    std::vector<Node> nodes_;
};

class SegmentEnergy final : public ceres::CostFunction {
public:
    static constexpr int kResidualsPerNode = 8;

    // `targets` the target ω at each of the quadrature's nodes, taken from start + u·duration.
    SegmentEnergy(double duration, std::shared_ptr<const SegmentQuadrature> quadrature,
                  std::vector<Eigen::Vector3d> targets, const EnergyWeights& weights);

    bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

private:
    double duration_;
    std::shared_ptr<const SegmentQuadrature> quadrature_;
    std::vector<Eigen::Vector3d> targets_;
    // √(β·h), √(α·h), √(μ·h): each node's residual scale is one of them times √wⱼ.
    double angularScale_;
    double tangentialScale_;
    double unitScale_;
};

} // namespace gyre::fit
