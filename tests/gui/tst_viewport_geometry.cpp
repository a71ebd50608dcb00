// The viewport's geometry without OpenGL: the orbit camera's projections and moves, picking, and the
// trail of any track (onion skinning), for every selected object within the trails' total budget.

#include "app/viewport/body_overlay.h"
#include "app/viewport/default_shape.h"
#include "app/viewport/mesh_winding.h"
#include "app/viewport/orbit_camera.h"
#include "app/viewport/picking.h"
#include "app/viewport/sampled_trail.h"
#include "app/viewport/skeleton.h"
#include "core/subdivision.h"
#include "model/object_mass.h"
#include "model/scene_joints.h"
#include "model/scene_motion.h"
#include "model/track_evaluation.h"

#include <QTest>

#include <Eigen/Geometry>

#include <array>
#include <algorithm>
#include <numbers>
#include <random>

using namespace gyre;

namespace {

// Each object moving by its own track, as the document's motion() would give it.
std::shared_ptr<const model::SharedTrackMotion> ownMotion(const model::SceneObject& object)
{
    return std::make_shared<const model::SharedTrackMotion>(object.track);
}

app::OrbitCamera cameraAt(const Eigen::Vector3d& target)
{
    app::OrbitCamera camera;
    camera.setViewportSize(800, 600);
    camera.frame(target - Eigen::Vector3d::Constant(2), target + Eigen::Vector3d::Constant(2));
    return camera;
}

// A tetrahedron with its own three vertices per face, each face counter-clockwise seen from
// outside; one face's copy of the corner at the origin is written (−0, 0, −0).
model::Mesh tetrahedron()
{
    const Eigen::Vector3f o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1), negativeZeroO(-0.0F, 0.0F, -0.0F);
    model::Mesh mesh;
    for (const auto& face : {std::array{o, y, x}, std::array{negativeZeroO, x, z}, std::array{o, z, y}, std::array{x, y, z}}) {
        for (const Eigen::Vector3f& corner : face) {
            mesh.indices.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
            mesh.positions.push_back(corner);
        }
    }
    return mesh;
}

model::Mesh reversed(model::Mesh mesh)
{
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3)
        std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
    return mesh;
}

// An object at a fixed pose relative to its parent: one key.
model::SceneObject placed(model::ObjectId id, model::ObjectId parent, const Pose& pose, std::shared_ptr<const model::Mesh> mesh = nullptr)
{
    model::SceneObject object;
    object.id = id;
    object.parent = parent;
    object.mesh = std::move(mesh);
    object.track.keys.push_back({0.0, pose, true});
    return object;
}

Pose turned(double angle, const Eigen::Vector3d& axis, const Eigen::Vector3d& position)
{
    return {Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized())), position};
}

// Root (1) ─ Upper (2) ─ Lower (3), meshless and turned, the chain several tests start from.
std::vector<model::SceneObject> rootUpperLower()
{
    return {placed(1, model::kNoObject, turned(0.3, {1, 2, 3}, {1, 0, 0})), placed(2, 1, turned(0.8, {0, 1, 0}, {0, 0, 2})),
            placed(3, 2, turned(-0.5, {1, 0, 1}, {1.5, 0, 0}))};
}

} // namespace

class TestViewportGeometry : public QObject {
    Q_OBJECT

private slots:
    // The arrow of a box body, against its momentum summed over a grid of small cells, each moving at
    // v = ω × r: L = Σ m·r × v about the centre of mass. Its principal axes are the box's edges, the
    // longest edge's the one of least moment.
    void theMomentumArrowAndPrincipalAxesAreTheBoxs()
    {
        const Eigen::Vector3d size(0.8, 0.3, 0.5);
        model::SceneObject box;
        auto mesh = std::make_shared<model::Mesh>();
        for (int corner = 0; corner < 8; ++corner)
            mesh->positions.push_back(Eigen::Vector3f(corner & 1 ? 0.4F : -0.4F, corner & 2 ? 0.15F : -0.15F,
                                                      corner & 4 ? 0.25F : -0.25F) + Eigen::Vector3f(0.1F, 0.2F, 0.3F));
        mesh->indices = {0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};
        box.mesh = mesh;
        const MassProperties mass = model::objectMassProperties(box).properties;
        const Pose pose{Eigen::Quaterniond(Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, 2, -1).normalized())), {1, -2, 0.5}};
        const Eigen::Vector3d omega(1.5, -0.4, 2.0);

        const int cells = 24;
        const double cellMass = mass.mass / (cells * cells * cells);
        Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
        for (int i = 0; i < cells; ++i)
            for (int j = 0; j < cells; ++j)
                for (int k = 0; k < cells; ++k) {
                    const Eigen::Vector3d local = (Eigen::Vector3d(i, j, k).array() + 0.5).matrix().cwiseProduct(size) / cells - size / 2;
                    const Eigen::Vector3d r = pose.orientation * local; // from the centre of mass
                    momentum += cellMass * r.cross(omega.cross(r));
                }
        // The midpoint rule leaves out each cell's own spin, a relative 1/cells² of the moments.
        const Eigen::Vector3d computed = app::worldAngularMomentum(pose, mass, omega);
        QVERIFY2((computed - momentum).norm() < 3.0 / (cells * cells) * momentum.norm(),
                 qPrintable(QStringLiteral("%1 against %2").arg(computed.norm()).arg(momentum.norm())));

        std::vector<app::LineVertex> lines;
        app::appendMomentumArrow(lines, pose, mass, omega, 1.0);
        QCOMPARE(lines.size(), std::size_t(10)); // the shaft and four barbs
        const auto point = [&](std::size_t index) {
            return Eigen::Vector3d(lines[index].position[0], lines[index].position[1], lines[index].position[2]);
        };
        const Eigen::Vector3d centre = pose.apply(Eigen::Vector3d(0.1, 0.2, 0.3));
        QVERIFY((point(0) - centre).norm() < 1e-6);
        QVERIFY((point(1) - point(0)).normalized().dot(momentum.normalized()) > 1.0 - 1e-4);
        // Two body radii for one turn a second about the largest principal axis, the box's about its
        // shortest side: I₃ = m/12·(0.8² + 0.5²), capped at six.
        const double largestMoment = mass.mass / 12.0 * (size.x() * size.x() + size.z() * size.z());
        const double expectedLength = std::min(2.0 * momentum.norm() / (2.0 * std::numbers::pi * largestMoment), 6.0);
        QVERIFY(std::abs((point(1) - point(0)).norm() - expectedLength) < 3.0 / (cells * cells) * expectedLength);

        lines.clear();
        app::appendPrincipalAxes(lines, pose, mass, 1.0);
        QCOMPARE(lines.size(), std::size_t(6));
        for (int axis = 0; axis < 3; ++axis) {
            const Eigen::Vector3d drawn = (point(2 * axis + 1) - point(2 * axis)).normalized();
            // Least moment about the longest edge (x, 0.8), most about the shortest (y, 0.3).
            const Eigen::Vector3d edge = pose.orientation * Eigen::Vector3d::Unit(axis == 0 ? 0 : axis == 1 ? 2 : 1);
            QVERIFY2(std::abs(drawn.dot(edge)) > 1.0 - 1e-5, qPrintable(QStringLiteral("axis %1").arg(axis)));
            QVERIFY(((point(2 * axis + 1) + point(2 * axis)) / 2 - centre).norm() < 1e-5);
        }
        // At rest there is no arrow.
        lines.clear();
        app::appendMomentumArrow(lines, pose, mass, Eigen::Vector3d::Zero(), 1.0);
        QVERIFY(lines.empty());
    }

    void projectThenUnprojectComesBack()
    {
        app::OrbitCamera camera = cameraAt(Eigen::Vector3d(1, 2, 3));
        camera.orbit(37, -12);
        for (const Eigen::Vector3d& point : {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(-2, 0.5, 4), Eigen::Vector3d(3, 3, 1)}) {
            const Eigen::Vector3d screen = camera.project(point);
            QVERIFY(screen.z() > 0 && screen.z() < 1);
            QVERIFY((camera.unproject(screen) - point).norm() < 1e-6);
        }
    }

    void theTargetIsInTheMiddleOfTheView()
    {
        const app::OrbitCamera camera = cameraAt(Eigen::Vector3d(4, -1, 2));
        const Eigen::Vector3d screen = camera.project(camera.target());
        QVERIFY(std::abs(screen.x() - 400) < 1e-9);
        QVERIFY(std::abs(screen.y() - 300) < 1e-9);
    }

    void orbitingKeepsTheDistanceToTheTarget()
    {
        app::OrbitCamera camera = cameraAt(Eigen::Vector3d(1, 0, 0));
        const double distance = (camera.eye() - camera.target()).norm();
        const Eigen::Vector3d eyeBefore = camera.eye();
        camera.orbit(120, 45);
        QVERIFY(std::abs((camera.eye() - camera.target()).norm() - distance) < 1e-9);
        QVERIFY((camera.eye() - eyeBefore).norm() > 0.1);
        // Over the pole the pitch stops short of straight down, so the view never flips.
        camera.orbit(0, 1e5);
        QVERIFY(std::abs((camera.eye() - camera.target()).norm() - distance) < 1e-9);
        QVERIFY(camera.eye().z() - camera.target().z() < distance);
    }

    void panningMovesThePointUnderTheCursorWithIt()
    {
        app::OrbitCamera camera = cameraAt(Eigen::Vector3d::Zero());
        const Eigen::Vector3d before = camera.project(Eigen::Vector3d::Zero());
        camera.pan(30, -20);
        const Eigen::Vector3d after = camera.project(Eigen::Vector3d::Zero());
        QVERIFY(std::abs(after.x() - (before.x() + 30)) < 1e-6);
        QVERIFY(std::abs(after.y() - (before.y() - 20)) < 1e-6);
    }

    void zoomingInComesCloser()
    {
        app::OrbitCamera camera = cameraAt(Eigen::Vector3d::Zero());
        const double distance = camera.distance();
        camera.zoom(2);
        QCOMPARE(camera.distance(), distance * app::OrbitCamera::kZoomFactor * app::OrbitCamera::kZoomFactor);
        camera.zoom(-2);
        QVERIFY(std::abs(camera.distance() - distance) < 1e-12);
    }

    void framingShowsTheWholeBox()
    {
        app::OrbitCamera camera;
        camera.setViewportSize(400, 900); // narrow: the horizontal field of view decides
        camera.orbit(-80, 30);
        const Eigen::AlignedBox3d box(Eigen::Vector3d(-1, 0, 2), Eigen::Vector3d(5, 7, 3));
        camera.frame(box.min(), box.max());
        for (int corner = 0; corner < 8; ++corner) {
            const Eigen::Vector3d screen = camera.project(box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)));
            QVERIFY(screen.x() >= 0 && screen.x() <= 400);
            QVERIFY(screen.y() >= 0 && screen.y() <= 900);
            QVERIFY(screen.z() > 0 && screen.z() < 1);
        }
    }

    void aRayThroughAPointOnScreenPassesThroughIt()
    {
        const app::OrbitCamera camera = cameraAt(Eigen::Vector3d(0, 0, 1));
        const Eigen::Vector3d point(1.5, -0.5, 0.25);
        const Eigen::Vector3d screen = camera.project(point);
        const app::Ray ray = camera.ray(screen.x(), screen.y());
        const double t = (point - ray.origin).dot(ray.direction);
        QVERIFY((ray.at(t) - point).norm() < 1e-6);
    }

    void aRayHitsTheNearestPlacedMesh()
    {
        const model::Mesh& shape = app::defaultShapeMesh();
        const Pose near{Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ())), Eigen::Vector3d(0, 0, 2)};
        const Pose far{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0, 0, -3)};
        const std::vector<app::MeshPlacement> placements{{&shape, far, 1.0}, {&shape, near, 0.5}};
        const app::Ray down{Eigen::Vector3d(0, 0, 10), -Eigen::Vector3d::UnitZ()};
        QCOMPARE(app::nearestHit(down, placements), std::optional<std::size_t>(1));
        // The top of the half-size body at z = 2 + 0.5·0.2.
        QVERIFY(std::abs(*app::intersectMesh(down, placements[1]) - (10 - 2.1)) < 1e-6);
        const app::Ray beside{Eigen::Vector3d(5, 5, 10), -Eigen::Vector3d::UnitZ()};
        QVERIFY(!app::nearestHit(beside, placements));
        // The nose reaches x = 1 on an unturned shape, and no further.
        const app::Ray throughNose{Eigen::Vector3d(0.95, 0, 10), -Eigen::Vector3d::UnitZ()};
        const app::Ray pastNose{Eigen::Vector3d(1.05, 0, 10), -Eigen::Vector3d::UnitZ()};
        QCOMPARE(app::nearestHit(throughNose, placements), std::optional<std::size_t>(0));
        QVERIFY(!app::nearestHit(pastNose, placements));
    }

    void theDefaultShapeShowsOnlyItsFrontFacesFromOutside()
    {
        // What culling its back faces relies on, checked by casting rays at it: from any eye outside,
        // the first triangle a ray meets faces the eye, its corners counter-clockwise.
        const model::Mesh& shape = app::defaultShapeMesh();
        QCOMPARE(app::meshWinding(shape), app::MeshWinding::CounterClockwise);
        std::mt19937_64 random(7);
        std::uniform_real_distribution<double> inside(-0.5, 0.5);
        std::normal_distribution<double> normal;
        int hits = 0;
        for (int i = 0; i < 2000; ++i) {
            const Eigen::Vector3d eye = 5.0 * Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized();
            const Eigen::Vector3d aim(inside(random), inside(random), 0.5 * inside(random));
            const app::Ray ray{eye, (aim - eye).normalized()};
            std::optional<double> nearest;
            Eigen::Vector3d nearestNormal = Eigen::Vector3d::Zero();
            for (std::size_t k = 0; k < shape.indices.size(); k += 3) {
                const Eigen::Vector3d a = shape.positions[shape.indices[k]].cast<double>();
                const Eigen::Vector3d b = shape.positions[shape.indices[k + 1]].cast<double>();
                const Eigen::Vector3d c = shape.positions[shape.indices[k + 2]].cast<double>();
                const std::optional<double> t = app::intersectTriangle(ray, a, b, c);
                if (t && (!nearest || *t < *nearest)) {
                    nearest = t;
                    nearestNormal = (b - a).cross(c - a);
                }
            }
            if (!nearest)
                continue;
            ++hits;
            QVERIFY2(nearestNormal.dot(ray.direction) < 0.0, qPrintable(QStringLiteral("ray %1 meets a back face first").arg(i)));
        }
        QVERIFY(hits > 1000);
    }

    void meshWindingTellsClosedMeshesFromOpenOnes()
    {
        const model::Mesh tetra = tetrahedron();
        QCOMPARE(app::meshWinding(tetra), app::MeshWinding::CounterClockwise);
        QCOMPARE(app::meshWinding(reversed(tetra)), app::MeshWinding::Clockwise);
        QCOMPARE(app::meshWinding(reversed(app::defaultShapeMesh())), app::MeshWinding::Clockwise);

        model::Mesh missingFace = tetra;
        missingFace.indices.resize(9);
        QCOMPARE(app::meshWinding(missingFace), app::MeshWinding::Open);
        // One face turned over: its edges are walked twice the same way.
        model::Mesh oneFaceTurned = tetra;
        std::swap(oneFaceTurned.indices[10], oneFaceTurned.indices[11]);
        QCOMPARE(app::meshWinding(oneFaceTurned), app::MeshWinding::Open);
        QCOMPARE(app::meshWinding(model::Mesh{}), app::MeshWinding::Open);

        // A sheet seen from both sides: each side's triangles face their own eye, so it is closed.
        model::Mesh sheet;
        sheet.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
        sheet.indices = {0, 1, 2, 0, 2, 3};
        QCOMPARE(app::meshWinding(sheet), app::MeshWinding::Open);
        sheet.indices.insert(sheet.indices.end(), {0, 2, 1, 0, 3, 2});
        QVERIFY(app::meshWinding(sheet) != app::MeshWinding::Open);
    }

    void jointsAreMeshlessObjectsJoinedToMeshlessObjects()
    {
        // Root (1) ─ Upper (2) ─ Lower (3, a leaf); Root ─ Prop (4, a mesh) ─ Tag (5, meshless);
        // Lone (6, meshless, alone).
        auto mesh = std::make_shared<const model::Mesh>(tetrahedron());
        model::Scene scene;
        scene.objects = rootUpperLower();
        scene.objects.insert(scene.objects.end(), {placed(4, 1, turned(0.1, {0, 0, 1}, {0, 3, 0}), mesh),
                                                   placed(5, 4, turned(0.2, {0, 0, 1}, {0, 1, 0})),
                                                   placed(6, model::kNoObject, turned(0.4, {1, 0, 0}, {5, 5, 0}))});
        const model::SceneMotion motion(scene, ownMotion);
        app::Skeleton skeleton;
        skeleton.update(scene, motion, 0.0);
        for (std::size_t i = 0; i < scene.objects.size(); ++i)
            QCOMPARE(skeleton.isJoint(i), i < 3);
        const auto world = [&](model::ObjectId id) { return motion.worldPose(id, 0.0); };
        const std::vector<app::Bone>& bones = skeleton.bones();
        QCOMPARE(bones.size(), std::size_t{3});
        // From each joint to its child joint, and the leaf's own on along its offset, half as long.
        const Eigen::Vector3d leafTail = world(3).apply(app::Skeleton::kLeafBoneFraction * Eigen::Vector3d(1.5, 0, 0));
        const std::array<std::array<Eigen::Vector3d, 2>, 3> expected{{{world(1).position, world(2).position},
                                                                      {world(2).position, world(3).position},
                                                                      {world(3).position, leafTail}}};
        for (std::size_t i = 0; i < 3; ++i) {
            QCOMPARE(bones[i].joint, model::ObjectId(i + 1));
            QVERIFY((bones[i].head() - expected[i][0]).norm() < 1e-12);
            QVERIFY((bones[i].tail() - expected[i][1]).norm() < 1e-12);
        }
        // A bone turns with its joint: its x axis is fixed in the joint's frame.
        const Eigen::Vector3d alongInJoint = world(1).orientation.conjugate() * (bones[0].pose.orientation * Eigen::Vector3d::UnitX());
        QVERIFY((alongInJoint - Eigen::Vector3d::UnitZ()).norm() < 1e-12);
    }

    void anEmptyIsNeverAJoint()
    {
        // Root (1, meshless) ─ Pivot (2, an empty) ─ Tip (3, meshless): with the empty, no two meshless
        // objects are joined, so none is a joint; without it, all three are.
        model::Scene scene;
        scene.objects = rootUpperLower();
        scene.objects[1].empty = true;
        QCOMPARE(model::findJoints(scene), std::vector<bool>(3, false));
        scene.objects[1].empty = false;
        QCOMPARE(model::findJoints(scene), std::vector<bool>(3, true));
    }

    void anEmptysHullIsClosedAndSpansItsAxes()
    {
        model::SceneObject empty;
        empty.empty = true;
        const model::Mesh& hull = app::displayMesh(empty);
        QCOMPARE(app::meshWinding(hull), app::MeshWinding::CounterClockwise);
        Eigen::AlignedBox3f box;
        for (const Eigen::Vector3f& position : hull.positions)
            box.extend(position);
        QVERIFY((box.max() - Eigen::Vector3f::Constant(float(app::kEmptyAxisLength))).norm() < 1e-6F);
        QVERIFY((box.min() + Eigen::Vector3f::Constant(float(app::kEmptyAxisLength))).norm() < 1e-6F);
        // A click on an axis hits it: a ray straight down through a point of its x axis.
        const std::vector<app::MeshPlacement> placements{{&hull, Pose{}, 1.0}};
        QVERIFY(app::nearestHit({Eigen::Vector3d(0.5, 0.0, 5.0), -Eigen::Vector3d::UnitZ()}, placements));
        QVERIFY(!app::nearestHit({Eigen::Vector3d(0.8, 0.8, 5.0), -Eigen::Vector3d::UnitZ()}, placements));
    }

    void theTrailsTimesAreEvenlySpacedWithinItsBudget()
    {
        model::Scene scene;
        scene.fps = 24.0;
        scene.startTime = 1.0;
        scene.endTime = 4.0;
        scene.currentTime = 2.0;
        // Spread: from the start to the end, evenly.
        const std::vector<double> spread = app::trailTimes(scene, {7, 0});
        QCOMPARE(spread.size(), std::size_t{7});
        for (std::size_t i = 0; i < spread.size(); ++i)
            QVERIFY(std::abs(spread[i] - (1.0 + 0.5 * double(i))) < 1e-12);
        // Every 6 frames about the current time: 4 before and 4 after, a quarter second apart; the
        // current time left out, and nothing before the start (1.0 is the fourth before, 0.75 would be out).
        const std::vector<double> about = app::trailTimes(scene, {8, 6});
        const std::vector<double> expected{1.0, 1.25, 1.5, 1.75, 2.25, 2.5, 2.75, 3.0};
        QCOMPARE(about.size(), expected.size());
        for (std::size_t i = 0; i < about.size(); ++i)
            QVERIFY(std::abs(about[i] - expected[i]) < 1e-12);
        scene.currentTime = 1.25;
        QCOMPARE(app::trailTimes(scene, {8, 6}).front(), 1.0); // 0.25 and 0.5 … are out of range
        QCOMPARE(app::trailTimes(scene, {8, 6}).size(), std::size_t{5});
        // The budget, up front: a setting past it is clamped.
        QCOMPARE(app::trailTimes(scene, {1'000'000, 0}).size(), std::size_t(app::TrailSpacing::kMaxCopies));
        QCOMPARE(app::trailTimes(scene, {0, 0}).size(), std::size_t{2});
        QCOMPARE((app::TrailSpacing{5, -3}.clamped().everyFrames), 0);
        scene.endTime = scene.startTime;
        QVERIFY(app::trailTimes(scene, {16, 0}).empty());
    }

    void theTrailsCopiesStandWhereTheMotionIsAtTheirTimes()
    {
        // A hermite child of a slerp parent: each copy is the child's world pose, composed here from the
        // two tracks evaluated on their own.
        model::Scene scene;
        scene.objects = {placed(1, model::kNoObject, turned(0.0, {0, 0, 1}, {0, 0, 0})),
                         placed(2, 1, turned(0.0, {1, 0, 0}, {2, 0, 0}))};
        model::MotionTrack& parent = scene.objects[0].track;
        parent.interpolation = InterpolationMethod::Slerp;
        parent.keys.push_back({2.0, turned(1.5, {0, 0, 1}, {0, 3, 0}), true});
        model::MotionTrack& child = scene.objects[1].track;
        child.interpolation = InterpolationMethod::Hermite;
        child.keys.push_back({1.0, turned(2.0, {1, 1, 0}, {2, 0, 1}), true});
        child.keys.push_back({2.0, turned(-1.0, {0, 1, 1}, {1, 1, 1}), true});
        scene.startTime = 0.0;
        scene.endTime = 2.0;
        const model::SceneMotion motion(scene, ownMotion);
        const std::vector<double> times = app::trailTimes(scene, {9, 0});
        const std::vector<Pose> copies = app::trailPoses(motion, 2, times);
        QCOMPARE(copies.size(), times.size());
        const model::TrackMotion parentMotion(parent);
        const model::TrackMotion childMotion(child);
        for (std::size_t i = 0; i < times.size(); ++i) {
            const Pose expected = parentMotion.at(times[i]) * childMotion.at(times[i]);
            QVERIFY(copies[i].orientation.angularDistance(expected.orientation) < 1e-12);
            QVERIFY((copies[i].position - expected.position).norm() < 1e-12);
        }
        // The copies differ: the trail shows the motion, not one pose many times.
        QVERIFY((copies.front().position - copies.back().position).norm() > 1.0);
    }

    void everySelectedObjectGetsItsCopiesWithinTheTotalBudget()
    {
        // Five objects each turning and moving its own way, and an empty (drawn as axes, no trail).
        model::Scene scene;
        scene.startTime = 0.0;
        scene.endTime = 2.0;
        for (model::ObjectId id = 1; id <= 6; ++id) {
            scene.objects.push_back(placed(id, model::kNoObject, turned(0.0, {0, 0, 1}, {double(id), 0, 0})));
            scene.objects.back().track.keys.push_back({2.0, turned(0.5 * double(id), {1, 0, double(id)}, {0, double(id), 1}), true});
        }
        scene.objects.back().empty = true;
        const std::vector<model::ObjectId> selected{1, 2, 3, 4, 5, 6};
        // The active object first, then the others in their order; the empty left out.
        QCOMPARE(app::planTrails(scene, selected, 3, {16, 0}).sampled, (std::vector<model::ObjectId>{3, 1, 2, 4, 5}));
        QVERIFY(app::planTrails(scene, selected, 3, {16, 0}).subdivided.empty());
        // The active screw track's trail is its subdivision, not one of these.
        model::Scene screw = scene;
        screw.objects[2].track.interpolation = InterpolationMethod::Screw;
        QCOMPARE(app::planTrails(screw, selected, 3, {16, 0}).sampled, (std::vector<model::ObjectId>{1, 2, 4, 5}));
        QCOMPARE(app::planTrails(screw, selected, 3, {16, 0}).subdivided,
                 (std::vector<app::TrailPlan::Subdivided>{{3, screw.objects[2].track.subdivision.levels}}));
        // The total budget, up front: 1024 copies are four objects' at 256 each, 64 objects' at 16.
        QCOMPARE(app::TrailSpacing::kMaxTotalCopies, 1024);
        QCOMPARE(app::planTrails(scene, selected, 3, {256, 0}).sampled, (std::vector<model::ObjectId>{3, 1, 2, 4}));
        QCOMPARE(app::planTrails(scene, selected, 3, {100'000, 0}).sampled, (std::vector<model::ObjectId>{3, 1, 2, 4}));
        std::vector<model::ObjectId> many;
        for (model::ObjectId id = 1; id <= 70; ++id) {
            if (id > 6)
                scene.objects.push_back(placed(id, model::kNoObject, turned(0.0, {0, 0, 1}, {double(id), 0, 0})));
            many.push_back(id);
        }
        QCOMPARE(app::planTrails(scene, many, 1, {16, 0}).sampled.size(), std::size_t{64});
        scene.objects.resize(6);

        // Two selected objects each get their copies, each where its own motion is at the times.
        const model::SceneMotion motion(scene, ownMotion);
        const std::vector<double> times = app::trailTimes(scene, {9, 0});
        const std::vector<app::ObjectTrail> trails = app::trailPoses(motion, {2, 5}, times);
        QCOMPARE(trails.size(), std::size_t{2});
        for (const app::ObjectTrail& trail : trails) {
            QCOMPARE(trail.poses.size(), times.size());
            const model::TrackMotion own(scene.objects[trail.object - 1].track);
            for (std::size_t i = 0; i < times.size(); ++i) {
                QVERIFY(trail.poses[i].orientation.angularDistance(own.at(times[i]).orientation) < 1e-12);
                QVERIFY((trail.poses[i].position - own.at(times[i]).position).norm() < 1e-12);
            }
        }
        QCOMPARE(trails[0].object, model::ObjectId{2});
        QCOMPARE(trails[1].object, model::ObjectId{5});
        QVERIFY((trails[0].poses.back().position - trails[1].poses.back().position).norm() > 1.0);
    }

    void screwTracksShareTheBudgetAtTheirLevelsOrFewer()
    {
        // Five screw tracks of 6 keys (a cycle at 4 levels: 96 poses), then a hermite one.
        model::Scene scene;
        scene.startTime = 0.0;
        scene.endTime = 5.0;
        for (model::ObjectId id = 1; id <= 6; ++id) {
            scene.objects.push_back(placed(id, model::kNoObject, turned(0.0, {0, 0, 1}, {double(id), 0, 0})));
            for (int key = 1; key < 6; ++key)
                scene.objects.back().track.keys.push_back({double(key), turned(0.3 * key, {1, 0, double(id)}, {0, double(key), 0}), true});
            scene.objects.back().track.interpolation = id <= 5 ? InterpolationMethod::Screw : InterpolationMethod::Hermite;
        }
        scene.objects[0].track.subdivision.levels = 9; // 3072 poses: the active one's, outside the budget
        scene.objects[1].track.subdivision.levels = 7; // 768 poses
        scene.objects[2].track.subdivision.levels = 6; // 384 do not fit the 256 left: 5 levels, 192
        scene.objects[3].track.subdivision.levels = 4; // 96 do not fit the 64 left: 3 levels, 48
        scene.objects[4].track.subdivision.levels = 4; // 16 left: 1 level, 12
        const std::vector<model::ObjectId> selected{1, 2, 3, 4, 5, 6};
        const app::TrailPlan plan = app::planTrails(scene, selected, 1, {16, 0});
        QCOMPARE(plan.subdivided, (std::vector<app::TrailPlan::Subdivided>{{1, 9}, {2, 7}, {3, 5}, {4, 3}, {5, 1}}));
        // 4 copies left: not enough for the hermite track's 16.
        QVERIFY(plan.sampled.empty());
        std::size_t shared = 0;
        for (std::size_t i = 1; i < plan.subdivided.size(); ++i)
            shared += *subdividedPoseCount(6, plan.subdivided[i].levels, true);
        QCOMPARE(shared, std::size_t{768 + 192 + 48 + 12});
        QVERIFY(shared <= std::size_t(app::TrailSpacing::kMaxTotalCopies));
        // Another object active: it leads and takes the budget first (16 copies); object 1 (3072 poses at 9 levels)
        // then fits in the 1008 left at 7 levels, 768 poses.
        QCOMPARE(app::planTrails(scene, selected, 6, {16, 0}).sampled, (std::vector<model::ObjectId>{6}));
        QCOMPARE(app::planTrails(scene, selected, 6, {16, 0}).subdivided.front(), (app::TrailPlan::Subdivided{1, 7}));
    }

    // A joint or an empty whose screw track is active shows its control poses, which the artist drags: its trail
    // is its subdivision, as any active screw track's. Not active, it has no trail (its bones or axes and its
    // centre's path say where it goes), nor has an active one whose track is another.
    void anActiveScrewJointOrEmptyHasItsSubdividedTrail()
    {
        // Root (1) ─ Upper (2) ─ Lower (3): joints; Axes (4): an empty; Prop (5): a mesh.
        auto mesh = std::make_shared<const model::Mesh>(tetrahedron());
        model::Scene scene;
        scene.objects = rootUpperLower();
        scene.objects.insert(scene.objects.end(), {placed(4, model::kNoObject, turned(0.4, {1, 0, 0}, {5, 5, 0})),
                                                   placed(5, model::kNoObject, turned(0.1, {0, 0, 1}, {0, 3, 0}), mesh)});
        scene.objects[3].empty = true;
        for (model::SceneObject& object : scene.objects)
            object.track.keys.push_back({2.0, turned(1.2, {0, 1, 1}, {1, 2, 0}), true});
        scene.objects[1].track.interpolation = InterpolationMethod::Screw;
        scene.objects[3].track.interpolation = InterpolationMethod::Screw;
        QCOMPARE(model::findJoints(scene), (std::vector<bool>{true, true, true, false, false}));
        const std::vector<model::ObjectId> selected{1, 2, 3, 4, 5};
        const int levels = scene.objects[1].track.subdivision.levels;
        for (const model::ObjectId active : {model::ObjectId{2}, model::ObjectId{4}}) {
            const app::TrailPlan plan = app::planTrails(scene, selected, active, {16, 0});
            QCOMPARE(plan.subdivided, (std::vector<app::TrailPlan::Subdivided>{{active, levels}}));
            QCOMPARE(plan.sampled, (std::vector<model::ObjectId>{5}));
        }
        for (const model::ObjectId active : {model::ObjectId{3}, model::ObjectId{5}}) {
            const app::TrailPlan plan = app::planTrails(scene, selected, active, {16, 0});
            QVERIFY(plan.subdivided.empty());
            QCOMPARE(plan.sampled, (std::vector<model::ObjectId>{5}));
        }
    }

    void aYUpViewOrbitsAboutY()
    {
        app::OrbitCamera camera = cameraAt(Eigen::Vector3d(1, 2, 3));
        camera.setUpAxis(app::UpAxis::Y);
        const double height = camera.eye().y();
        camera.orbit(80.0, 0.0); // sideways: about the view's up, y
        QVERIFY(std::abs(camera.eye().y() - height) < 1e-9);
        QVERIFY(std::abs((camera.eye() - camera.target()).norm() - camera.distance()) < 1e-9);
        // World +y is up on screen, whichever way the camera turned about it.
        const Eigen::Vector3d centre = camera.project(camera.target());
        QVERIFY(camera.project(camera.target() + Eigen::Vector3d::UnitY()).y() < centre.y() - 1);
        camera.setUpAxis(app::UpAxis::Z);
        QVERIFY(camera.project(camera.target() + Eigen::Vector3d::UnitZ()).y() < centre.y() - 1);
    }

    void aJointWithoutABoneOfItsOwnGetsOne()
    {
        // Hips (1) with Pelvis (2) at its very place, Pelvis with Leg (3) below: the Hips' bone to the
        // Pelvis has no length, so the Hips get a stub along their x axis; the Pelvis's goes to the Leg.
        model::Scene scene;
        scene.objects = {placed(1, model::kNoObject, turned(0.4, {0, 1, 1}, {2, 0, 5})),
                         placed(2, 1, turned(0.3, {1, 0, 0}, {0, 0, 0})),
                         placed(3, 2, turned(0.2, {0, 1, 0}, {0, 0, -4}))};
        const model::SceneMotion motion(scene, ownMotion);
        app::Skeleton skeleton;
        skeleton.update(scene, motion, 0.0);
        const std::vector<app::Bone>& bones = skeleton.bones();
        QCOMPARE(bones.size(), std::size_t{3});
        QCOMPARE(bones[0].joint, model::ObjectId(2));
        QCOMPARE(bones[0].length, 4.0);
        QCOMPARE(bones[1].joint, model::ObjectId(3)); // the leaf's, 2 long
        QCOMPARE(bones[2].joint, model::ObjectId(1));
        QVERIFY(std::abs(bones[2].length - app::Skeleton::kStubFraction * (4.0 + 2.0) / 2) < 1e-12);
        const Pose hips = motion.worldPose(1, 0.0);
        QVERIFY((bones[2].tail() - hips.apply(Eigen::Vector3d(bones[2].length, 0, 0))).norm() < 1e-12);
    }

    void aRayThroughABoneHitsIt()
    {
        QCOMPARE(app::meshWinding(app::boneMesh()), app::MeshWinding::CounterClockwise);
        const app::Bone bone{7, turned(0.7, {1, 1, 0}, {1, 2, 3}), 4.0};
        const std::vector<app::MeshPlacement> placements{{&app::defaultShapeMesh(), Pose{{}, {20, 0, 0}}, 1.0},
                                                         {&app::boneMesh(), bone.pose, bone.length}};
        const app::OrbitCamera camera = cameraAt(0.5 * (bone.head() + bone.tail()));
        for (const double along : {0.1, 0.5, 0.9}) {
            const Eigen::Vector3d screen = camera.project(bone.head() + along * (bone.tail() - bone.head()));
            QCOMPARE(app::nearestHit(camera.ray(screen.x(), screen.y()), placements), std::optional<std::size_t>(1));
        }
        // Across the bone on screen, a quarter of its length from its middle, beyond its widest
        // (a tenth of its length, √2 times at the waist's corners), a ray misses it.
        const Eigen::Vector2d head = camera.project(bone.head()).head<2>();
        const Eigen::Vector2d tail = camera.project(bone.tail()).head<2>();
        const Eigen::Vector2d across = Eigen::Vector2d(head.y() - tail.y(), tail.x() - head.x()).normalized();
        const Eigen::Vector2d beside = 0.5 * (head + tail) + 0.25 * bone.length / camera.worldPerPixel() * across;
        QVERIFY(!app::nearestHit(camera.ray(beside.x(), beside.y()), placements));
    }

    void lookingFromAViewPointTurnsOnlyTheView()
    {
        app::OrbitCamera camera = cameraAt(Eigen::Vector3d(1, 2, 3));
        const double distance = camera.distance();
        constexpr double kQuarter = std::numbers::pi / 2;
        camera.lookFrom(-kQuarter, kQuarter); // straight down: right is +x, up +y
        QVERIFY((camera.viewDirection() + Eigen::Vector3d::UnitZ()).norm() < 1e-12);
        QVERIFY((camera.target() - Eigen::Vector3d(1, 2, 3)).norm() < 1e-12);
        QCOMPARE(camera.distance(), distance);
        const Eigen::Vector3d centre = camera.project(camera.target());
        const Eigen::Vector3d right = camera.project(camera.target() + Eigen::Vector3d::UnitX()) - centre;
        const Eigen::Vector3d up = camera.project(camera.target() + Eigen::Vector3d::UnitY()) - centre;
        QVERIFY(right.x() > 1 && std::abs(right.y()) < 1e-9);
        QVERIFY(up.y() < -1 && std::abs(up.x()) < 1e-9);
    }

    void orthographicKeepsTheSizeAtTheTargetAndCastsParallelRays()
    {
        app::OrbitCamera camera = cameraAt(Eigen::Vector3d(1, 2, 3));
        camera.orbit(40, 20);
        const Eigen::Vector3d aside = camera.target() + Eigen::Vector3d(0.5, -0.3, 0.4);
        const Eigen::Vector3d inPerspective = camera.project(aside);
        camera.setOrthographic(true);
        const double perPixel = camera.worldPerPixel();
        // A point at the target's depth is where the perspective drew it, to first order about the centre.
        const Eigen::Vector3d offset = 0.01 * camera.viewMatrix().block<1, 3>(0, 0).transpose();
        const double pixels = (camera.project(camera.target() + offset) - camera.project(camera.target())).norm();
        QVERIFY(std::abs(pixels * perPixel - 0.01) < 1e-9);
        QVERIFY((camera.project(aside) - inPerspective).head<2>().norm() < 0.1 * camera.height());
        for (const Eigen::Vector3d& point : {aside, Eigen::Vector3d(-4, 0, 1)}) {
            const Eigen::Vector3d screen = camera.project(point);
            QVERIFY((camera.unproject(screen) - point).norm() < 1e-6);
            const app::Ray ray = camera.ray(screen.x(), screen.y());
            QVERIFY((ray.direction - camera.viewDirection()).norm() < 1e-12);
            // The ray passes through the point: its distance from the ray's line is nought.
            QVERIFY(((point - ray.origin).cross(ray.direction)).norm() < 1e-6);
        }
    }

    void theNearestPointOnAnAxisToARay()
    {
        const app::Ray ray{Eigen::Vector3d(3, 0, 5), -Eigen::Vector3d::UnitZ()};
        const std::optional<double> along = app::nearestOnAxis(ray, Eigen::Vector3d(1, 0, 0), Eigen::Vector3d::UnitX());
        QVERIFY(along && std::abs(*along - 2) < 1e-12);
        QVERIFY(!app::nearestOnAxis(ray, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()));
        QCOMPARE(app::distanceToSegment(Eigen::Vector2d(5, 3), Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 0)), 3.0);
        QCOMPARE(app::distanceToSegment(Eigen::Vector2d(13, 4), Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 0)), 5.0);
    }
};

QTEST_MAIN(TestViewportGeometry)
#include "tst_viewport_geometry.moc"
