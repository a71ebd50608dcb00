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

#include <ceres/cost_function.h>

#include <Eigen/Core>

#include <array>
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

class SegmentEnergy final : public ceres::CostFunction {
public:
    static constexpr int kResidualsPerNode = 8;

    // `nodes` and `quadratureWeights` on [0, 1]; `targets` the target ω at each node.
    SegmentEnergy(double duration, const std::vector<double>& nodes, const std::vector<double>& quadratureWeights,
                  const std::vector<Eigen::Vector3d>& targets, const EnergyWeights& weights);

    bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

private:
    struct Node {
        NodeBasis basis;
        Eigen::Vector3d target;
        double angularScale;
        double tangentialScale;
        double unitScale;
    };
    std::vector<Node> nodes_;
};

} // namespace gyre::fit
