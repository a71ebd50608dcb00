// CompressedCost against the cost function it compresses: the same cost, the same JᵀJ and Jᵀr (all
// the trust-region step reads), for every subset of parameter blocks Ceres may ask Jacobians of, and
// for a block whose residual lies in the span of its Jacobian (a rank-deficient [J r]).

#include "fit/compressed_cost.h"
#include "fit/gauss_legendre.h"
#include "fit/segment_energy.h"

#include <ceres/sized_cost_function.h>

#include <Eigen/Core>
#include <QTest>

#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

using namespace gyre::fit;

namespace {

using Jacobian = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct Evaluation {
    Eigen::VectorXd residuals;
    Eigen::MatrixXd jacobian; // the requested blocks side by side
};

// Evaluates `cost` at `parameters`, with the Jacobians of the blocks `wanted` names (none if empty).
Evaluation evaluate(const ceres::CostFunction& cost, const std::vector<Eigen::VectorXd>& parameters,
                    const std::vector<bool>& wanted)
{
    std::vector<const double*> pointers;
    for (const Eigen::VectorXd& block : parameters)
        pointers.push_back(block.data());
    Evaluation result;
    result.residuals.resize(cost.num_residuals());
    std::vector<Jacobian> blocks(parameters.size());
    std::vector<double*> blockData(parameters.size(), nullptr);
    Eigen::Index columns = 0;
    for (std::size_t k = 0; k < wanted.size(); ++k) {
        if (!wanted[k])
            continue;
        blocks[k].resize(cost.num_residuals(), parameters[k].size());
        blockData[k] = blocks[k].data();
        columns += parameters[k].size();
    }
    const bool ok = cost.Evaluate(pointers.data(), result.residuals.data(), wanted.empty() ? nullptr : blockData.data());
    if (!ok)
        throw std::runtime_error("evaluation failed");
    result.jacobian.resize(cost.num_residuals(), columns);
    Eigen::Index offset = 0;
    for (std::size_t k = 0; k < wanted.size(); ++k) {
        if (!wanted[k])
            continue;
        result.jacobian.middleCols(offset, parameters[k].size()) = blocks[k];
        offset += parameters[k].size();
    }
    return result;
}

double relativeDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b)
{
    return (a - b).norm() / std::max(1.0, b.norm());
}

// Residuals linear in two blocks, r = A·x + B·y, so that [J r] has rank 5 < 6 columns.
class LinearCost final : public ceres::SizedCostFunction<7, 2, 3> {
public:
    LinearCost()
    {
        std::mt19937_64 rng(5);
        std::normal_distribution<double> normal;
        a_ = Eigen::Matrix<double, 7, 2>::NullaryExpr([&] { return normal(rng); });
        b_ = Eigen::Matrix<double, 7, 3>::NullaryExpr([&] { return normal(rng); });
    }

    bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override
    {
        const Eigen::Map<const Eigen::Vector2d> x(parameters[0]);
        const Eigen::Map<const Eigen::Vector3d> y(parameters[1]);
        Eigen::Map<Eigen::Matrix<double, 7, 1>> r(residuals);
        r = a_ * x + b_ * y;
        if (jacobians != nullptr && jacobians[0] != nullptr) {
            Eigen::Map<Eigen::Matrix<double, 7, 2, Eigen::RowMajor>> byX(jacobians[0]);
            byX = a_;
        }
        if (jacobians != nullptr && jacobians[1] != nullptr) {
            Eigen::Map<Eigen::Matrix<double, 7, 3, Eigen::RowMajor>> byY(jacobians[1]);
            byY = b_;
        }
        return true;
    }

private:
    Eigen::Matrix<double, 7, 2> a_;
    Eigen::Matrix<double, 7, 3> b_;
};

// The compressed form's cost and normal equations against the full form's, for each subset of blocks.
// Blocks named in `held` are never asked for, as Ceres never asks for a constant block's Jacobian.
void compareNormalEquations(const ceres::CostFunction& full, const CompressedCost& compressed,
                            const std::vector<Eigen::VectorXd>& parameters, double tolerance,
                            const std::vector<bool>& held = {})
{
    const Evaluation plainFull = evaluate(full, parameters, {});
    const Evaluation plainCompressed = evaluate(compressed, parameters, {});
    QCOMPARE(plainCompressed.residuals.size(), compressed.num_residuals());
    const double cost = plainFull.residuals.squaredNorm();
    QVERIFY2(std::abs(plainCompressed.residuals.squaredNorm() - cost) <= tolerance * std::max(1.0, cost),
             qPrintable(QStringLiteral("%1 vs %2").arg(plainCompressed.residuals.squaredNorm()).arg(cost)));
    const std::size_t blockCount = parameters.size();
    for (unsigned subset = 1; subset < (1u << blockCount); ++subset) {
        std::vector<bool> wanted(blockCount);
        bool asksHeld = false;
        for (std::size_t k = 0; k < blockCount; ++k) {
            wanted[k] = ((subset >> k) & 1u) != 0;
            asksHeld = asksHeld || (wanted[k] && !held.empty() && held[k]);
        }
        if (asksHeld)
            continue;
        const Evaluation a = evaluate(full, parameters, wanted);
        const Evaluation b = evaluate(compressed, parameters, wanted);
        const QString which = QStringLiteral("blocks %1").arg(subset);
        QVERIFY2(std::abs(b.residuals.squaredNorm() - cost) <= tolerance * std::max(1.0, cost), qPrintable(which));
        const Eigen::MatrixXd normal = a.jacobian.transpose() * a.jacobian;
        const Eigen::VectorXd gradient = a.jacobian.transpose() * a.residuals;
        QVERIFY2(relativeDifference(b.jacobian.transpose() * b.jacobian, normal) <= tolerance, qPrintable(which));
        QVERIFY2(relativeDifference(b.jacobian.transpose() * b.residuals, gradient) <= tolerance, qPrintable(which));
    }
}

} // namespace

class TestCompressedCost : public QObject {
    Q_OBJECT

private slots:
    void segmentEnergyKeepsCostAndNormalEquations();
    void rankDeficientBlockKeepsCostAndNormalEquations();
    void heldBlocksHaveNoRows();
};

void TestCompressedCost::segmentEnergyKeepsCostAndNormalEquations()
{
    std::mt19937_64 rng(13);
    std::normal_distribution<double> normal;
    for (const int nodes : {4, 10, 64}) {
        const QuadratureRule rule = gaussLegendre(nodes);
        std::vector<Eigen::Vector3d> targets;
        for (const double u : rule.nodes)
            targets.emplace_back(std::sin(3.0 * u), 2.0 * u, -1.0);
        const double duration = 0.2 + 0.01 * nodes;
        const EnergyWeights weights{0.002, 1.0, 1000.0};
        const SegmentEnergy full(duration, std::make_shared<const SegmentQuadrature>(rule), targets, weights);
        const CompressedCost compressed(std::make_unique<SegmentEnergy>(duration, std::make_shared<const SegmentQuadrature>(rule), targets, weights));
        QCOMPARE(compressed.num_residuals(), 17);
        QCOMPARE(compressed.parameter_block_sizes(), full.parameter_block_sizes());
        std::vector<Eigen::VectorXd> parameters(4);
        for (Eigen::VectorXd& block : parameters)
            block = Eigen::Vector4d(normal(rng), normal(rng), normal(rng), normal(rng));
        parameters[0].normalize();
        parameters[2].normalize();
        compareNormalEquations(full, compressed, parameters, 1e-12);
    }
}

void TestCompressedCost::rankDeficientBlockKeepsCostAndNormalEquations()
{
    const CompressedCost compressed(std::make_unique<LinearCost>());
    QCOMPARE(compressed.num_residuals(), 6);
    const std::vector<Eigen::VectorXd> parameters{Eigen::Vector2d(0.3, -1.2), Eigen::Vector3d(2.0, 0.5, -0.7)};
    compareNormalEquations(LinearCost(), compressed, parameters, 1e-12);
}

// A segment between two constrained keys: its values held, its derivatives free. R needs 8 columns
// and the residual, 9 rows; the normal equations of the free blocks are still the full cost's, and a
// held block's Jacobian is refused rather than written past the rows.
void TestCompressedCost::heldBlocksHaveNoRows()
{
    const QuadratureRule rule = gaussLegendre(10);
    std::vector<Eigen::Vector3d> targets;
    for (const double u : rule.nodes)
        targets.emplace_back(1.0 - u, 3.0 * u, 0.5);
    const double duration = 0.21;
    const EnergyWeights weights{0.002, 1.0, 100.0};
    const auto quadrature = std::make_shared<const SegmentQuadrature>(rule);
    const std::vector<bool> held{true, false, true, false};
    const SegmentEnergy full(duration, quadrature, targets, weights);
    const CompressedCost compressed(std::make_unique<SegmentEnergy>(duration, quadrature, targets, weights), held);
    QCOMPARE(compressed.num_residuals(), 9);
    const std::vector<Eigen::VectorXd> parameters{Eigen::Vector4d(0.9, 0.1, -0.3, 0.2).normalized(),
                                                  Eigen::Vector4d(0.2, 1.5, -0.4, 0.7),
                                                  Eigen::Vector4d(0.7, 0.5, 0.1, -0.4).normalized(),
                                                  Eigen::Vector4d(-0.3, 0.9, 1.1, 0.2)};
    compareNormalEquations(full, compressed, parameters, 1e-12, held);
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, evaluate(compressed, parameters, {true, true, false, false}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             CompressedCost(std::make_unique<SegmentEnergy>(duration, quadrature, targets, weights),
                                            std::vector<bool>{true, false}));
}

QTEST_GUILESS_MAIN(TestCompressedCost)
#include "tst_compressed_cost.moc"
