#pragma once
// Gauss–Legendre quadrature on [0, 1]: ∫₀¹ f(u) du ≈ Σⱼ wⱼ f(uⱼ), exact for polynomials of degree
// up to 2n − 1 with n nodes.

#include <vector>

namespace gyre::fit {

struct QuadratureRule {
    std::vector<double> nodes;    // in (0, 1), increasing
    std::vector<double> weights;  // positive, summing to 1
};

// The n-node rule, n ≥ 1, by the Golub–Welsch method: the nodes on [−1, 1] are the eigenvalues of
// the symmetric tridiagonal Jacobi matrix with off-diagonal k/√(4k² − 1), and each weight is twice
// the squared first component of its unit eigenvector; both are then mapped to [0, 1].
QuadratureRule gaussLegendre(int n);

} // namespace gyre::fit
