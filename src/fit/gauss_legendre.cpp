#include "fit/gauss_legendre.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <stdexcept>

namespace gyre::fit {

QuadratureRule gaussLegendre(int n)
{
    if (n < 1)
        throw std::invalid_argument("a quadrature rule needs at least one node");
    Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(n, n);
    for (int k = 1; k < n; ++k) {
        const double offDiagonal = k / std::sqrt(4.0 * k * k - 1.0);
        jacobi(k, k - 1) = offDiagonal;
        jacobi(k - 1, k) = offDiagonal;
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(jacobi);
    QuadratureRule rule;
    for (int j = 0; j < n; ++j) {
        const double first = solver.eigenvectors()(0, j);
        rule.nodes.push_back(0.5 * (solver.eigenvalues()(j) + 1.0));
        rule.weights.push_back(first * first);  // 2·first² on [−1, 1], halved on [0, 1]
    }
    return rule;
}

} // namespace gyre::fit
