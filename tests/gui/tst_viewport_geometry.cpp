// The viewport's geometry without OpenGL: the orbit camera's projections and moves, and picking.

#include "app/viewport/default_shape.h"
#include "app/viewport/orbit_camera.h"
#include "app/viewport/picking.h"

#include <QTest>

#include <Eigen/Geometry>

using namespace gyre;

namespace {

app::OrbitCamera cameraAt(const Eigen::Vector3d& target)
{
    app::OrbitCamera camera;
    camera.setViewportSize(800, 600);
    camera.frame(target - Eigen::Vector3d::Constant(2), target + Eigen::Vector3d::Constant(2));
    return camera;
}

} // namespace

class TestViewportGeometry : public QObject {
    Q_OBJECT

private slots:
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
