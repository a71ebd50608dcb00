// The fit's building blocks: quadrature exactness, and the segment energy's residuals and analytic
// Jacobians against the energy written out directly and against central differences.

#include "fit/gauss_legendre.h"
#include "fit/segment_energy.h"

#include <Eigen/Geometry>
#include <QTest>

#include <array>
#include <cmath>
#include <random>

using namespace gyre::fit;

namespace {

// A random segment: control vectors (q₀, d₀, q₁, d₁), each w, x, y, z, near unit values.
std::array<Eigen::Vector4d, 4> randomControl(std::mt19937_64& rng)
{
    std::normal_distribution<double> normal;
    std::array<Eigen::Vector4d, 4> control;
    for (Eigen::Vector4d& c : control)
        c = Eigen::Vector4d(normal(rng), normal(rng), normal(rng), normal(rng));
    control[0].normalize();
    control[2].normalize();
    return control;
}

// q, q′, q″ at u of the Hermite segment, from the basis written out here.
struct Derivatives {
    Eigen::Vector4d q, dq, ddq;
};

Derivatives hermiteAt(const std::array<Eigen::Vector4d, 4>& c, double u, double h)
{
    const double u2 = u * u;
    const double u3 = u2 * u;
    const Eigen::Vector4d m0 = h * c[1];
    const Eigen::Vector4d m1 = h * c[3];
    Derivatives d;
    d.q = (2 * u3 - 3 * u2 + 1) * c[0] + (u3 - 2 * u2 + u) * m0 + (-2 * u3 + 3 * u2) * c[2] + (u3 - u2) * m1;
    d.dq = ((6 * u2 - 6 * u) * c[0] + (3 * u2 - 4 * u + 1) * m0 + (-6 * u2 + 6 * u) * c[2] + (3 * u2 - 2 * u) * m1) / h;
    d.ddq = ((12 * u - 6) * c[0] + (6 * u - 4) * m0 + (-12 * u + 6) * c[2] + (6 * u - 2) * m1) / (h * h);
    return d;
}

Eigen::Quaterniond asQuaternion(const Eigen::Vector4d& wxyz) { return {wxyz[0], wxyz[1], wxyz[2], wxyz[3]}; }

std::vector<double> evaluate(const SegmentEnergy& energy, const std::array<Eigen::Vector4d, 4>& control,
                             std::array<Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor>, 4>* jacobians)
{
    const std::array<const double*, 4> parameters{control[0].data(), control[1].data(), control[2].data(),
                                                  control[3].data()};
    std::vector<double> residuals(static_cast<std::size_t>(energy.num_residuals()));
    std::array<double*, 4> jacobianData{};
    if (jacobians != nullptr) {
        for (std::size_t k = 0; k < 4; ++k) {
            (*jacobians)[k].resize(energy.num_residuals(), 4);
            jacobianData[k] = (*jacobians)[k].data();
        }
    }
    energy.Evaluate(parameters.data(), residuals.data(), jacobians != nullptr ? jacobianData.data() : nullptr);
    return residuals;
}

} // namespace

class TestFitEnergy : public QObject {
    Q_OBJECT

private slots:
    void gaussLegendreIsExactToDegreeTwoNMinusOne();
    void residualsSumToTheEnergy();
    void jacobiansMatchCentralDifferences();
};

void TestFitEnergy::gaussLegendreIsExactToDegreeTwoNMinusOne()
{
    for (int n = 1; n <= 12; ++n) {
        const QuadratureRule rule = gaussLegendre(n);
        QCOMPARE(rule.nodes.size(), static_cast<std::size_t>(n));
        for (int degree = 0; degree <= 2 * n; ++degree) {
            double sum = 0.0;
            for (int j = 0; j < n; ++j)
                sum += rule.weights[static_cast<std::size_t>(j)] * std::pow(rule.nodes[static_cast<std::size_t>(j)], degree);
            const double exact = 1.0 / (degree + 1);
            // Degree 2n is the first the rule misses, by the classical remainder
            // ∫₀¹ f − Σ wⱼ f(uⱼ) = (n!)⁴ / ((2n + 1)·((2n)!)³) · f⁽²ⁿ⁾ with f⁽²ⁿ⁾ = (2n)!.
            const double remainder = degree < 2 * n ? 0.0
                                                    : std::pow(std::tgamma(n + 1.0), 4) /
                                                          ((2 * n + 1) * std::pow(std::tgamma(2 * n + 1.0), 2));
            QVERIFY2(std::abs(exact - sum - remainder) < 1e-14,
                     qPrintable(QStringLiteral("n %1, degree %2: %3").arg(n).arg(degree).arg(exact - sum)));
        }
    }
}

void TestFitEnergy::residualsSumToTheEnergy()
{
    // Σ r² against the integrand written with Eigen's quaternion product: ω = 2·vec(q′·q⁻¹).
    std::mt19937_64 rng(7);
    const double duration = 0.37;
    const EnergyWeights weights{0.002, 1.3, 50.0};
    const QuadratureRule rule = gaussLegendre(6);
    std::vector<Eigen::Vector3d> targets;
    for (const double u : rule.nodes)
        targets.emplace_back(std::sin(u), 2.0 * u, -1.0);
    const SegmentEnergy energy(duration, std::make_shared<const SegmentQuadrature>(rule), targets, weights);
    const std::array<Eigen::Vector4d, 4> control = randomControl(rng);
    const std::vector<double> residuals = evaluate(energy, control, nullptr);
    double squares = 0.0;
    for (const double r : residuals)
        squares += r * r;

    double expected = 0.0;
    for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
        const Derivatives d = hermiteAt(control, rule.nodes[j], duration);
        const Eigen::Quaterniond q = asQuaternion(d.q);
        const Eigen::Quaterniond dq = asQuaternion(d.dq);
        const Eigen::Vector3d omega = 2.0 * (dq * q.inverse()).vec();
        const double tangential = d.ddq.squaredNorm() - std::pow(d.q.dot(d.ddq), 2) / d.q.squaredNorm();
        const double unit = std::pow(1.0 - d.q.squaredNorm(), 2);
        expected += rule.weights[j] * duration *
                    (weights.beta * (omega - targets[j]).squaredNorm() + weights.alpha * tangential +
                     weights.unitNorm * unit);
    }
    QVERIFY2(std::abs(squares - expected) < 1e-10 * std::max(1.0, expected),
             qPrintable(QStringLiteral("%1 vs %2").arg(squares).arg(expected)));
}

void TestFitEnergy::jacobiansMatchCentralDifferences()
{
    std::mt19937_64 rng(11);
    const QuadratureRule rule = gaussLegendre(5);
    const std::vector<Eigen::Vector3d> targets(rule.nodes.size(), Eigen::Vector3d(0.5, -1.0, 2.0));
    for (int trial = 0; trial < 20; ++trial) {
        const double duration = 0.05 + 0.5 * trial / 20.0;
        const SegmentEnergy energy(duration, std::make_shared<const SegmentQuadrature>(rule), targets, {0.002, 1.0, 100.0});
        std::array<Eigen::Vector4d, 4> control = randomControl(rng);
        std::array<Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor>, 4> analytic;
        evaluate(energy, control, &analytic);
        for (std::size_t k = 0; k < 4; ++k) {
            for (int i = 0; i < 4; ++i) {
                constexpr double kStep = 1e-6;
                std::array<Eigen::Vector4d, 4> plus = control;
                std::array<Eigen::Vector4d, 4> minus = control;
                plus[k][i] += kStep;
                minus[k][i] -= kStep;
                const std::vector<double> up = evaluate(energy, plus, nullptr);
                const std::vector<double> down = evaluate(energy, minus, nullptr);
                for (std::size_t r = 0; r < up.size(); ++r) {
                    const double numeric = (up[r] - down[r]) / (2.0 * kStep);
                    const double exact = analytic[k](static_cast<Eigen::Index>(r), i);
                    QVERIFY2(std::abs(numeric - exact) < 1e-5 * std::max(1.0, std::abs(exact)),
                             qPrintable(QStringLiteral("trial %1, block %2, coordinate %3, residual %4: %5 vs %6")
                                            .arg(trial).arg(k).arg(i).arg(r).arg(exact).arg(numeric)));
                }
            }
        }
    }
}

QTEST_GUILESS_MAIN(TestFitEnergy)
#include "tst_energy.moc"
