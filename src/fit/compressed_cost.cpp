#include "fit/compressed_cost.h"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <numeric>
#include <string>
#include <stdexcept>
#include <vector>

namespace gyre::fit {

namespace {

// The parameters and the residual: R is at most this square, kept off the heap.
constexpr int kMaxColumns = CompressedCost::kMaxParameters + 1;
using Square = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxColumns, kMaxColumns>;
using RowMajorMap = Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>;

} // namespace

CompressedCost::CompressedCost(std::unique_ptr<ceres::CostFunction> full, const std::vector<bool>& heldBlocks)
    : full_(std::move(full))
    , heldBlocks_(heldBlocks)
{
    const std::vector<int>& sizes = full_->parameter_block_sizes();
    const int parameters = std::accumulate(sizes.begin(), sizes.end(), 0);
    if (parameters > kMaxParameters)
        throw std::invalid_argument("a compressed cost takes at most " + std::to_string(kMaxParameters) +
                                    " parameters, not " + std::to_string(parameters));
    if (!heldBlocks.empty() && heldBlocks.size() != sizes.size())
        throw std::invalid_argument("a compressed cost needs one held flag a parameter block");
    int free = parameters;
    for (std::size_t k = 0; k < heldBlocks.size(); ++k)
        if (heldBlocks[k])
            free -= sizes[k];
    set_num_residuals(free + 1);
    *mutable_parameter_block_sizes() = sizes;
}

bool CompressedCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const
{
    const Eigen::Index rows = full_->num_residuals();
    const Eigen::Index compressed = num_residuals();
    Eigen::Map<Eigen::VectorXd> output(residuals, compressed);
    // The full residuals and Jacobian live here between calls, so that an evaluation allocates nothing
    // once the largest block has been seen.
    thread_local std::vector<double> scratch;
    if (jacobians == nullptr) {
        scratch.resize(std::max<std::size_t>(scratch.size(), static_cast<std::size_t>(rows)));
        if (!full_->Evaluate(parameters, scratch.data(), nullptr))
            return false;
        output.setZero();
        output[0] = Eigen::Map<const Eigen::VectorXd>(scratch.data(), rows).norm();
        return true;
    }

    // [J r] of the requested blocks only: any columns of R have the Gram of the same columns of [J r].
    const std::vector<int>& sizes = parameter_block_sizes();
    std::vector<Eigen::Index> offsets(sizes.size(), -1);
    Eigen::Index columns = 0;
    for (std::size_t k = 0; k < sizes.size(); ++k) {
        if (jacobians[k] != nullptr) {
            if (!heldBlocks_.empty() && heldBlocks_[k])
                return false; // R has no rows for a held block's columns
            offsets[k] = columns;
            columns += sizes[k];
        }
    }
    // [J r] column-major, then each requested block as Ceres lays it out (row-major) for the full cost.
    scratch.resize(std::max<std::size_t>(scratch.size(), static_cast<std::size_t>(rows * (2 * columns + 1))));
    Eigen::Map<Eigen::MatrixXd> augmented(scratch.data(), rows, columns + 1);
    std::vector<double*> blockData(sizes.size(), nullptr);
    for (std::size_t k = 0; k < sizes.size(); ++k)
        if (jacobians[k] != nullptr)
            blockData[k] = scratch.data() + rows * (columns + 1 + offsets[k]);
    if (!full_->Evaluate(parameters, augmented.col(columns).data(), blockData.data()))
        return false;
    for (std::size_t k = 0; k < sizes.size(); ++k)
        if (jacobians[k] != nullptr)
            augmented.middleCols(offsets[k], sizes[k]) = RowMajorMap(blockData[k], rows, sizes[k]);

    // Coefficient by coefficient, each a dot product of two contiguous columns: for these sizes (at
    // most 17 columns of 32 to 512 rows) faster than Eigen's blocked rank update, whose packing dominates.
    const Square gram = augmented.transpose().lazyProduct(augmented);
    const Eigen::LDLT<Square, Eigen::Lower> factors(gram);
    if (factors.info() != Eigen::Success)
        return false;
    // G = Pᵀ L D Lᵀ P, so R = √D Lᵀ P; rounding may leave a zero pivot slightly negative.
    Square root = factors.vectorD().cwiseMax(0.0).cwiseSqrt().asDiagonal() * Square(factors.matrixU());
    root = root * factors.transpositionsP().transpose();

    output.setZero();
    output.head(columns + 1) = root.col(columns);
    for (std::size_t k = 0; k < sizes.size(); ++k) {
        if (jacobians[k] == nullptr)
            continue;
        RowMajorMap jacobian(jacobians[k], compressed, sizes[k]);
        jacobian.setZero();
        jacobian.topRows(columns + 1) = root.middleCols(offsets[k], sizes[k]);
    }
    return true;
}

} // namespace gyre::fit
