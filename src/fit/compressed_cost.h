#pragma once
// A Ceres cost function with the Gauss–Newton model of another in far fewer residuals.
//
// A cost function of m residuals r(x) over n parameters, J = ∂r/∂x, enters Ceres' trust-region step
// only through ½|r|², JᵀJ and Jᵀr. With [J r] = Q·R (R upper triangular, (n+1)×(n+1)), the n + 1
// residuals r̃ = R's last column with the Jacobian J̃ = R's first n columns give the same three:
// |r̃|² = |r|², J̃ᵀJ̃ = JᵀJ, J̃ᵀr̃ = Jᵀr (square-root information form). R comes from the Gram matrix
// G = [J r]ᵀ[J r] = RᵀR, by a pivoted LDLᵀ, so that a rank-deficient block (a residual with no
// component off J's columns, as at an exact fit) still factors: R = √D·Lᵀ·P.
//
// For the fit's segments (m = 8 residuals a node, 4 to 64 nodes; n = 16) this shrinks the Jacobian
// Ceres stores and walks several times an iteration from 80×16 to 17×16 at 10 nodes, and keeps the
// full one in one scratch buffer per thread, reused by every segment: m×(2n+1) doubles, 21 KB at 10 nodes
// and 135 KB at 64.
//
// A block Ceres holds constant (a constrained key's value) never has its Jacobian asked for, so R needs
// no columns for it: with `heldBlocks` named, the compressed cost has (free parameters + 1) residuals,
// 9×8 a segment between two constrained keys instead of 17×8 rows of which 8 stay zero, and Ceres'
// Jacobian and every pass over it shrink by half.
//
// r̃ is r turned by Qᵀ, so r̃ is only defined together with its Jacobian: evaluated without Jacobians,
// the residuals are (|r|, 0, …, 0), of the same squared norm. That is all Ceres' trust-region
// minimiser reads of such an evaluation (the cost of a candidate step); nothing in the fit uses
// Problem::Evaluate, covariance estimation or gradient checking, which would need one r̃ throughout.

#include <ceres/cost_function.h>

#include <memory>
#include <vector>

namespace gyre::fit {

class CompressedCost final : public ceres::CostFunction {
public:
    // R stays on the stack up to this many parameters (the fit's segments have 16).
    static constexpr int kMaxParameters = 16;

    // Throws std::invalid_argument if `full` has more than kMaxParameters parameters, or if `heldBlocks`
    // is neither empty (nothing held) nor one flag a parameter block. The Jacobian of a held block is
    // then never asked for: the evaluation fails if it is.
    explicit CompressedCost(std::unique_ptr<ceres::CostFunction> full, const std::vector<bool>& heldBlocks = {});

    bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

private:
    std::unique_ptr<ceres::CostFunction> full_;
    std::vector<bool> heldBlocks_; // empty when nothing is held
};

} // namespace gyre::fit
