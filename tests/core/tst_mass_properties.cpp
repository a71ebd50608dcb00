// Mass properties of meshes (mass_properties.h) against closed forms written here: a box's inertia
// m/12·(b² + c², …), a square plate's, and a tetrahedron's moments by Monte Carlo integration.

#include "core/mass_properties.h"

#include "core_test_support.h"

#include <QObject>
#include <QTest>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

using namespace gyre;
using namespace gyre::test;

namespace {

struct TestMesh {
    std::vector<Eigen::Vector3f> positions;
    std::vector<std::uint32_t> indices;
};

// The box [−size/2, size/2] turned by `rotation` and moved by `offset`: eight shared corners, twelve
// triangles counter-clockwise seen from outside. With `ownVertices`, every triangle has its own three.
TestMesh box(const Eigen::Vector3d& size, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& offset,
             bool ownVertices = false)
{
    TestMesh mesh;
    for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d unit((corner & 1) ? 0.5 : -0.5, (corner & 2) ? 0.5 : -0.5, (corner & 4) ? 0.5 : -0.5);
        mesh.positions.push_back((rotation * unit.cwiseProduct(size) + offset).cast<float>());
    }
    // Faces as corner quads, counter-clockwise from outside: −x, +x, −y, +y, −z, +z.
    const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& quad : quads)
        for (const int corner : {quad[0], quad[1], quad[2], quad[0], quad[2], quad[3]})
            mesh.indices.push_back(static_cast<std::uint32_t>(corner));
    if (ownVertices) {
        TestMesh split;
        for (const std::uint32_t index : mesh.indices) {
            split.indices.push_back(static_cast<std::uint32_t>(split.positions.size()));
            split.positions.push_back(mesh.positions[index]);
        }
        return split;
    }
    return mesh;
}

Eigen::Matrix3d boxInertia(double mass, const Eigen::Vector3d& size, const Eigen::Matrix3d& rotation)
{
    const Eigen::Vector3d s2 = size.cwiseProduct(size);
    const Eigen::Vector3d moments = mass / 12.0 * Eigen::Vector3d(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y());
    return rotation * moments.asDiagonal() * rotation.transpose();
}

// float positions carry ~1e-7 relative error into every moment.
constexpr double kFloatTolerance = 2e-6;

bool close(const Eigen::MatrixXd& actual, const Eigen::MatrixXd& expected, double tolerance)
{
    return (actual - expected).cwiseAbs().maxCoeff() <= tolerance * std::max(1.0, expected.cwiseAbs().maxCoeff());
}

} // namespace

class TestMassProperties : public QObject {
    Q_OBJECT

private slots:
    void turnedMovedBoxMatchesClosedForm_data();
    void turnedMovedBoxMatchesClosedForm();
    void insideOutBoxIsTheSameSolid();
    void seamCopiesApartByRoundingStillClose();
    void tetrahedronMatchesMonteCarloIntegration();
    void openMeshIsAThinShell();
    void meshWithoutAreaIsItsBoundingBox();
    void badMeshesAreRefused();
    void principalAxesAreARightHandedFrameOfTheTensor();
    void inertiaProblemsAreNamed();
};

void TestMassProperties::turnedMovedBoxMatchesClosedForm_data()
{
    QTest::addColumn<bool>("ownVertices");
    QTest::newRow("shared corners") << false;
    QTest::newRow("a vertex per triangle corner") << true;
}

void TestMassProperties::turnedMovedBoxMatchesClosedForm()
{
    QFETCH(bool, ownVertices);
    Random random;
    for (int trial = 0; trial < 20; ++trial) {
        const Eigen::Vector3d size(random.uniform(0.1, 2.0), random.uniform(0.1, 2.0), random.uniform(0.1, 2.0));
        const Eigen::Matrix3d rotation = random.rotation().toRotationMatrix();
        const Eigen::Vector3d offset = random.vector(3.0);
        const TestMesh mesh = box(size, rotation, offset, ownVertices);
        const MeshMass result = meshMassProperties(mesh.positions, mesh.indices, 700.0);
        QCOMPARE(result.model, MassModel::Solid);
        const double mass = 700.0 * size.prod();
        GYRE_CHECK(std::abs(result.properties.mass - mass) <= kFloatTolerance * mass * 10,
                   QStringLiteral("mass %1, expected %2").arg(result.properties.mass).arg(mass));
        GYRE_CHECK(close(result.properties.centre, offset, 10 * kFloatTolerance), QStringLiteral("centre"));
        GYRE_CHECK(close(result.properties.inertia, boxInertia(mass, size, rotation), 20 * kFloatTolerance),
                   QStringLiteral("inertia, trial %1").arg(trial));
    }
}

void TestMassProperties::insideOutBoxIsTheSameSolid()
{
    TestMesh mesh = box({1.0, 2.0, 3.0}, Eigen::Matrix3d::Identity(), {0.5, 0.0, -1.0});
    const MeshMass outward = meshMassProperties(mesh.positions, mesh.indices);
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
        std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    const MeshMass inward = meshMassProperties(mesh.positions, mesh.indices);
    QCOMPARE(inward.model, MassModel::Solid);
    QVERIFY(outward.properties.mass > 0.0);
    QVERIFY(close(inward.properties.inertia, outward.properties.inertia, 1e-12));
    QVERIFY(std::abs(inward.properties.mass - outward.properties.mass) <= 1e-12 * outward.properties.mass);
}

// A cylinder of radius 1 and height 2 built as modellers do: a ring of quads whose last column copies the
// first at angle 2π (cos and sin in float, off by rounding), and two fan caps.
void TestMassProperties::seamCopiesApartByRoundingStillClose()
{
    const int segments = 64;
    TestMesh mesh;
    for (int k = 0; k <= segments; ++k) {
        const float angle = 2.0f * std::numbers::pi_v<float> * static_cast<float>(k) / segments;
        for (const float z : {-1.0f, 1.0f})
            mesh.positions.emplace_back(std::cos(angle), std::sin(angle), z);
    }
    QVERIFY(mesh.positions[2 * segments] != mesh.positions[0]); // the seam's copy differs
    const auto bottom = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.emplace_back(0.0f, 0.0f, -1.0f);
    mesh.positions.emplace_back(0.0f, 0.0f, 1.0f);
    for (std::uint32_t k = 0; k < segments; ++k) {
        const std::uint32_t a = 2 * k, b = a + 2;
        mesh.indices.insert(mesh.indices.end(), {a, b, b + 1, a, b + 1, a + 1, bottom, b, a, bottom + 1, a + 1, b + 1});
    }
    const MeshMass result = meshMassProperties(mesh.positions, mesh.indices, 1.0);
    QCOMPARE(result.model, MassModel::Solid);
    // The inscribed 64-gon prism: area 32·sin(2π/64), height 2; Izz = m·r²/2 for its disc, near enough.
    const double volume = 2.0 * 32.0 * std::sin(2.0 * std::numbers::pi / segments);
    QVERIFY(std::abs(result.properties.mass - volume) < 1e-5 * volume);
    QVERIFY(std::abs(result.properties.inertia(2, 2) - 0.5 * volume) < 0.01 * volume);
}

void TestMassProperties::tetrahedronMatchesMonteCarloIntegration()
{
    const Eigen::Vector3d corners[4] = {{0.2, -0.1, 0.3}, {1.4, 0.1, 0.2}, {0.3, 1.1, -0.2}, {0.5, 0.4, 1.3}};
    TestMesh mesh;
    for (const Eigen::Vector3d& corner : corners)
        mesh.positions.push_back(corner.cast<float>());
    // Each face wound away from the opposite corner.
    for (const auto& face : {std::array<std::uint32_t, 3>{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}) {
        const Eigen::Vector3d a = mesh.positions[face[0]].cast<double>(), b = mesh.positions[face[1]].cast<double>(),
                              c = mesh.positions[face[2]].cast<double>();
        const int opposite = 6 - static_cast<int>(face[0] + face[1] + face[2]);
        const bool outward = (b - a).cross(c - a).dot(mesh.positions[opposite].cast<double>() - a) < 0.0;
        mesh.indices.insert(mesh.indices.end(), {face[0], outward ? face[1] : face[2], outward ? face[2] : face[1]});
    }
    const MeshMass result = meshMassProperties(mesh.positions, mesh.indices, 1.0);
    QCOMPARE(result.model, MassModel::Solid);

    // Uniform points of the tetrahedron: barycentric weights from sorted uniforms (a Dirichlet sample).
    Random random;
    const int samples = 400000;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < samples; ++i) {
        double cuts[3] = {random.uniform(0, 1), random.uniform(0, 1), random.uniform(0, 1)};
        std::sort(std::begin(cuts), std::end(cuts));
        const double weights[4] = {cuts[0], cuts[1] - cuts[0], cuts[2] - cuts[1], 1.0 - cuts[2]};
        Eigen::Vector3d point = Eigen::Vector3d::Zero();
        for (int k = 0; k < 4; ++k)
            point += weights[k] * mesh.positions[static_cast<std::size_t>(k)].cast<double>();
        points.push_back(point);
        sum += point;
    }
    const Eigen::Vector3d centre = sum / samples;
    for (const Eigen::Vector3d& point : points)
        second += (point - centre) * (point - centre).transpose();
    const Eigen::Vector3d e1 = (mesh.positions[1] - mesh.positions[0]).cast<double>();
    const Eigen::Vector3d e2 = (mesh.positions[2] - mesh.positions[0]).cast<double>();
    const Eigen::Vector3d e3 = (mesh.positions[3] - mesh.positions[0]).cast<double>();
    const double volume = std::abs(e1.dot(e2.cross(e3))) / 6.0;
    second *= volume / samples;
    const Eigen::Matrix3d inertia = second.trace() * Eigen::Matrix3d::Identity() - second;

    QVERIFY(std::abs(result.properties.mass - volume) <= 1e-6 * volume);
    GYRE_CHECK(close(result.properties.centre, centre, 5e-3), QStringLiteral("centre"));
    GYRE_CHECK((result.properties.inertia - inertia).norm() <= 1e-2 * inertia.norm(),
               QStringLiteral("inertia off by %1 of its size").arg((result.properties.inertia - inertia).norm() / inertia.norm()));
}

void TestMassProperties::openMeshIsAThinShell()
{
    // A square plate of side 2 in the xy-plane: of mass m, Ixx = Iyy = m·s²/12, Izz = m·s²/6.
    const TestMesh mesh{{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {0, 1, 2, 0, 2, 3}};
    const MeshMass result = meshMassProperties(mesh.positions, mesh.indices, 1000.0);
    QCOMPARE(result.model, MassModel::Shell);
    // As heavy as the solid sphere of its area would be: 4πr² = 4 gives r = 1/√π, m = ρ·(4/3)πr³.
    const double radius = 1.0 / std::sqrt(std::numbers::pi);
    const double mass = 1000.0 * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
    QVERIFY(std::abs(result.properties.mass - mass) <= 1e-12 * mass);
    QVERIFY(close(result.properties.centre, Eigen::Vector3d::Zero(), 1e-12));
    const Eigen::Matrix3d expected = Eigen::Vector3d(mass * 4 / 12, mass * 4 / 12, mass * 4 / 6).asDiagonal();
    QVERIFY(close(result.properties.inertia, expected, 1e-12));

    // A box with a face missing is open too.
    TestMesh openBox = box({1, 1, 1}, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
    openBox.indices.resize(openBox.indices.size() - 6);
    QCOMPARE(meshMassProperties(openBox.positions, openBox.indices).model, MassModel::Shell);
}

void TestMassProperties::meshWithoutAreaIsItsBoundingBox()
{
    const TestMesh line{{{0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {0, 4, 0}}, {0, 1, 2}};
    const MeshMass result = meshMassProperties(line.positions, line.indices, 1.0);
    QCOMPARE(result.model, MassModel::BoundingBox);
    QVERIFY(close(result.properties.centre, Eigen::Vector3d(1, 2, 0), 1e-12));
    // A 2 × 4 box, 4 mm thick (a thousandth of its size).
    const Eigen::Vector3d size(2, 4, 4e-3);
    QVERIFY(std::abs(result.properties.mass - size.prod()) <= 1e-12);
    QVERIFY(close(result.properties.inertia, boxInertia(size.prod(), size, Eigen::Matrix3d::Identity()), 1e-12));
}

void TestMassProperties::badMeshesAreRefused()
{
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, meshMassProperties({}, {}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, meshMassProperties({{0, 0, 0}}, {0, 0}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, meshMassProperties({{0, 0, 0}}, {0, 0, 1}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             meshMassProperties({{0, 0, 0}, {1, 0, 0}, {0, std::nanf(""), 0}}, {0, 1, 2}));
}

void TestMassProperties::principalAxesAreARightHandedFrameOfTheTensor()
{
    Random random;
    for (int trial = 0; trial < 50; ++trial) {
        const Eigen::Matrix3d rotation = random.rotation().toRotationMatrix();
        const Eigen::Vector3d moments(random.uniform(1, 2), random.uniform(1, 2), random.uniform(1, 2));
        const Eigen::Matrix3d inertia = rotation * moments.asDiagonal() * rotation.transpose();
        const PrincipalAxes principal = principalAxes(inertia);
        QVERIFY(principal.moments[0] <= principal.moments[1] && principal.moments[1] <= principal.moments[2]);
        QVERIFY(std::abs(principal.axes.determinant() - 1.0) < 1e-12);
        QVERIFY(close(principal.axes * principal.moments.asDiagonal() * principal.axes.transpose(), inertia, 1e-12));
    }
}

void TestMassProperties::inertiaProblemsAreNamed()
{
    QCOMPARE(inertiaProblem(boxInertia(2.0, {1, 2, 3}, Eigen::Matrix3d::Identity())), InertiaProblem::None);
    QCOMPARE(inertiaProblem(Eigen::Vector3d(1, 1, 3).asDiagonal().toDenseMatrix()), InertiaProblem::NoSuchBody); // 1 + 1 < 3
    QCOMPARE(inertiaProblem(Eigen::Vector3d(1, -1, 1).asDiagonal().toDenseMatrix()), InertiaProblem::NotPositiveDefinite);
    Eigen::Matrix3d skewed = Eigen::Matrix3d::Identity();
    skewed(0, 1) = 0.1;
    QCOMPARE(inertiaProblem(skewed), InertiaProblem::NotSymmetric);
    Eigen::Matrix3d infinite = Eigen::Matrix3d::Identity();
    infinite(2, 2) = std::numeric_limits<double>::infinity();
    QCOMPARE(inertiaProblem(infinite), InertiaProblem::NotFinite);
    // A thin rod's moments (0, m, m) sit on the boundary but are not positive definite.
    QCOMPARE(inertiaProblem(Eigen::Vector3d(0, 1, 1).asDiagonal().toDenseMatrix()), InertiaProblem::NotPositiveDefinite);
}

QTEST_APPLESS_MAIN(TestMassProperties)
#include "tst_mass_properties.moc"
