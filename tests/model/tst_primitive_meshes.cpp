// The primitives Object ▸ Add makes: each a closed surface (every edge shared by exactly two
// triangles that run it in opposite directions), facing outward, with the volume its solid has.
#include "model/object_mass.h"
#include "model/primitive_meshes.h"

#include <QtTest>

#include <map>
#include <numbers>
#include <tuple>

using namespace gyre;
using namespace gyre::model;

namespace {

using Point = std::tuple<float, float, float>;

Point pointOf(const Eigen::Vector3f& p) { return {p.x(), p.y(), p.z()}; }

// How many times each directed edge is run by the triangles, the faces' own vertices welded by
// position (faces are flat-shaded, so corners they share are equal copies).
std::map<std::pair<Point, Point>, int> directedEdges(const Mesh& mesh)
{
    std::map<std::pair<Point, Point>, int> edges;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        for (std::size_t k = 0; k < 3; ++k) {
            const Point from = pointOf(mesh.positions[mesh.indices[t + k]]);
            const Point to = pointOf(mesh.positions[mesh.indices[t + (k + 1) % 3]]);
            ++edges[{from, to}];
        }
    return edges;
}

// The volume the surface encloses, by the divergence theorem: the sum over triangles of
// p0 · (p1 × p2) / 6; positive when the triangles face outward.
double enclosedVolume(const Mesh& mesh)
{
    double volume = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const Eigen::Vector3d p0 = mesh.positions[mesh.indices[t]].cast<double>();
        const Eigen::Vector3d p1 = mesh.positions[mesh.indices[t + 1]].cast<double>();
        const Eigen::Vector3d p2 = mesh.positions[mesh.indices[t + 2]].cast<double>();
        volume += p0.dot(p1.cross(p2)) / 6.0;
    }
    return volume;
}

// The area of a regular polygon of 32 sides inscribed in a circle of radius r: 16 r² sin(2π/32).
double roundArea(double r) { return 16.0 * r * r * std::sin(2.0 * std::numbers::pi / 32.0); }

} // namespace

class TstPrimitiveMeshes : public QObject {
    Q_OBJECT

private slots:
    void everyPrimitiveIsClosedAndFacesOutward_data()
    {
        QTest::addColumn<Primitive>("primitive");
        for (const auto& [primitive, name] : kPrimitiveNames)
            QTest::newRow(name.data()) << primitive;
    }

    void everyPrimitiveIsClosedAndFacesOutward()
    {
        QFETCH(Primitive, primitive);
        const Mesh mesh = primitiveMesh(primitive);
        QVERIFY(!mesh.indices.empty());
        QCOMPARE(mesh.indices.size() % 3, std::size_t(0));
        QCOMPARE(mesh.normals.size(), mesh.positions.size());
        for (const std::uint32_t index : mesh.indices)
            QVERIFY(index < mesh.positions.size());

        const auto edges = directedEdges(mesh);
        for (const auto& [edge, count] : edges) {
            QCOMPARE(count, 1);
            const auto reverse = edges.find({edge.second, edge.first});
            QVERIFY2(reverse != edges.end(), "an edge with a triangle on one side only");
        }
        // Each triangle's stored normal is the one its winding gives.
        for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
            const Eigen::Vector3f p0 = mesh.positions[mesh.indices[t]];
            const Eigen::Vector3f winding =
                (mesh.positions[mesh.indices[t + 1]] - p0).cross(mesh.positions[mesh.indices[t + 2]] - p0);
            if (winding.norm() > 1e-6F)
                QVERIFY(winding.normalized().dot(mesh.normals[mesh.indices[t]]) > 0.999F);
        }
        QVERIFY(enclosedVolume(mesh) > 0.0);

        // So each is a solid body to the physics, weighing its volume in water.
        SceneObject object;
        object.mesh = std::make_shared<Mesh>(mesh);
        const ObjectMass mass = objectMassProperties(object);
        QCOMPARE(mass.source, MassSource::Solid);
        QVERIFY(std::abs(mass.properties.mass - kDefaultDensity * enclosedVolume(mesh)) < 1e-9 * mass.properties.mass);
        QCOMPARE(inertiaProblem(mass.properties.inertia), InertiaProblem::None);
    }

    // An object without a mesh is drawn as the block, and weighs as the block does.
    void anObjectWithoutAMeshHasTheBlocksMass()
    {
        const MeshMass block = meshMassProperties(primitiveMesh(Primitive::Block).positions,
                                                  primitiveMesh(Primitive::Block).indices);
        QVERIFY(objectMassProperties(SceneObject{}).properties == block.properties);
        // An empty too: a ballistic empty flies as the block would.
        SceneObject empty;
        empty.empty = true;
        QVERIFY(objectMassProperties(empty).properties == block.properties);
        // The block's centre of mass lies ahead of its body's, towards the nose (+x), and above, towards the fin.
        QVERIFY(block.properties.centre.x() > 0.0 && block.properties.centre.z() > 0.0);
    }

    void theVolumesAreThoseOfTheSolids()
    {
        QCOMPARE(enclosedVolume(primitiveMesh(Primitive::Box)), 1.0);
        // Body 1.2 × 0.6 × 0.4, a pyramid nose 0.6 × 0.4 × 0.4 high, a fin 0.4 × 0.1 × 0.3.
        QVERIFY(std::abs(enclosedVolume(primitiveMesh(Primitive::Block)) - (0.288 + 0.032 + 0.012)) < 1e-6);
        QVERIFY(std::abs(enclosedVolume(primitiveMesh(Primitive::Disc)) - roundArea(0.5) * 0.1) < 1e-6);
        QVERIFY(std::abs(enclosedVolume(primitiveMesh(Primitive::Cone)) - roundArea(0.5) * 1.0 / 3.0) < 1e-6);
        // Shaft 0.7 long, head a cone 0.3 long.
        const double arrow = roundArea(0.05) * 0.7 + roundArea(0.15) * 0.3 / 3.0;
        QVERIFY(std::abs(enclosedVolume(primitiveMesh(Primitive::Arrow)) - arrow) < 1e-6);
    }
};

QTEST_GUILESS_MAIN(TstPrimitiveMeshes)
#include "tst_primitive_meshes.moc"
