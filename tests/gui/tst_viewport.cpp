// The viewport driven with the mouse on the bundled sample: handle drags change the selected key in
// one undo step each, clicks select, the stroboscopic trail follows the subdivision settings, the
// ghost shows the motion as opened; a hermite track has a trail too, whose copies follow View ▸ Trail, and every
// selected object has its own, a screw track's its subdivision; the number-pad views follow View ▸ Y Up. Two tests also measure while a handle is dragged with thousands of
// trail instances: the viewport's drawing, and the UI thread's own time per move with every dock
// shown (issue 18); they print the figures (tests never assert on time).

#include "app/main_window.h"
#include "app/viewport/default_shape.h"
#include "app/viewport/pose_handles.h"
#include "app/viewport/viewport.h"
#include "gui_test_support.h"
#include "model/commands/import_objects_command.h"
#include "model/commands/set_interpolation_command.h"
#include "model/commands/set_subdivision_command.h"

#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QImage>
#include <QMouseEvent>
#include <QScopeGuard>
#include <QSettings>
#include <QTest>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

using namespace gyre;
using Handle = app::Viewport::Handle;

namespace {

// The main window on the bundled sample, paused at `time`, its viewport shown and drawn once.
struct Session {
    app::MainWindow window;
    app::Viewport* viewport = nullptr;
    model::ObjectId object = model::kNoObject;

    explicit Session(double time = 0.5)
    {
        window.resize(1200, 850);
        window.show();
        window.openBundledSample();
        window.playback().pause();
        window.document().setCurrentTime(time);
        viewport = window.findChild<app::Viewport*>();
        object = window.document().scene().objects.front().id;
    }

    const model::Keyframe& key(std::size_t index) { return window.document().object(object)->track.keys[index]; }

    // Adds a copy of the sample's object, its track's interpolation and settings included, its keys moved aside
    // along x by more than the sample's reach; returns its id.
    model::ObjectId importAside()
    {
        model::Document& document = window.document();
        model::SceneObject aside = *document.object(object);
        aside.id = 1;
        aside.parent = model::kNoObject;
        aside.name = QStringLiteral("aside");
        double reach = 0.0;
        for (const model::Keyframe& key : aside.track.keys)
            reach = std::max(reach, key.pose.position.norm());
        std::vector<model::Keyframe> keys = aside.track.keys;
        for (model::Keyframe& key : keys)
            key.pose.position.x() += 2.0 * reach + 1.0;
        aside.track.keys = keys;
        auto* import = new model::ImportObjectsCommand(document, {aside});
        document.push(import);
        return import->ids().front();
    }

    // Subdivides the sample's track to `levels` and selects its first key; returns the trail's
    // instance count, once the viewport draws that many.
    std::size_t trailAtLevels(int levels)
    {
        SubdivisionSettings settings = window.document().object(object)->track.subdivision;
        settings.levels = levels;
        window.document().push(new model::SetSubdivisionCommand(window.document(), object, settings));
        const std::size_t instances = *subdividedPoseCount(6, settings.levels, settings.cyclic);
        if (!QTest::qWaitFor([&] { return viewport->trailInstanceCount() == instances; }))
            qFatal("The viewport did not draw the trail of %zu instances", instances);
        window.selection().selectKey(object, 0);
        return instances;
    }
};

// From `from`, an arc of `radians` (counter-clockwise on screen) about `centre`.
std::vector<QPointF> arcPath(const QPointF& centre, const QPointF& from, double radians, int steps)
{
    const QPointF offset = from - centre;
    const double radius = std::hypot(offset.x(), offset.y());
    const double start = std::atan2(-offset.y(), offset.x());
    std::vector<QPointF> path;
    for (int i = 0; i <= steps; ++i) {
        const double angle = start + radians * i / steps;
        path.push_back(centre + QPointF(radius * std::cos(angle), -radius * std::sin(angle)));
    }
    return path;
}

// A point one arrow length along the x handle, beyond its tip.
QPointF pastTheXArrow(const app::Viewport& viewport)
{
    const QPointF base = *viewport.controlPoseScreenPosition(0);
    const QPointF grab = *viewport.handleScreenPosition(Handle::MoveX);
    return grab + (grab - base);
}

// The viewport drawn anew, read back: waits for a frame drawn after the call.
QImage drawnImage(app::Viewport& viewport)
{
    const std::uint64_t before = viewport.framesDrawn();
    viewport.update();
    if (!QTest::qWaitFor([&] { return viewport.framesDrawn() > before; }))
        qFatal("The viewport drew no frame");
    return viewport.grabFramebuffer();
}

// Where the trail's `copies` of the object stand, spread over the scene's range: the middle of its mesh's first
// triangle at each copy's time, a point inside its outline on screen.
std::vector<Eigen::Vector3d> copyPlaces(model::Document& document, model::ObjectId object, int copies)
{
    const model::Scene& scene = document.scene();
    const model::TrackMotion& motion = document.motion(object)->motion();
    const model::Mesh& mesh = app::displayMesh(*document.object(object));
    Eigen::Vector3d onSurface = Eigen::Vector3d::Zero();
    for (int corner = 0; corner < 3; ++corner)
        onSurface += mesh.positions[mesh.indices[std::size_t(corner)]].cast<double>() / 3.0;
    std::vector<Eigen::Vector3d> places;
    for (int i = 0; i < copies; ++i)
        places.push_back(motion.at(scene.startTime + (scene.endTime - scene.startTime) * i / (copies - 1)).apply(onSurface));
    return places;
}

// How many of the copies' places (a point on each one's surface, on screen) show something else in `with` than
// in `without`, looking within a few pixels about each.
int copiesSeen(app::Viewport& viewport, const std::vector<Eigen::Vector3d>& places, const QImage& with,
               const QImage& without)
{
    const double ratio = with.devicePixelRatio();
    constexpr int kAbout = 4;
    int seen = 0;
    for (const Eigen::Vector3d& place : places) {
        const QPointF point = app::toScreen(viewport.camera(), place) * ratio;
        bool differs = false;
        for (int dy = -kAbout; dy <= kAbout && !differs; ++dy)
            for (int dx = -kAbout; dx <= kAbout && !differs; ++dx) {
                const QPoint pixel = point.toPoint() + QPoint(dx, dy);
                differs = with.rect().contains(pixel) && with.pixel(pixel) != without.pixel(pixel);
            }
        seen += differs ? 1 : 0;
    }
    return seen;
}

// The UI thread's CPU time inside one widget's paint events: each paint event is sent on to the
// widget from within the filter, so that the filter sees where it ends.
class PaintClock : public QObject {
public:
    explicit PaintClock(QWidget& widget)
        : widget_(widget)
    {
        widget_.installEventFilter(this);
    }
    ~PaintClock() override { widget_.removeEventFilter(this); }

    double milliseconds() const { return milliseconds_; }
    void reset() { milliseconds_ = 0; }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (watched != &widget_ || event->type() != QEvent::Paint || painting_)
            return false;
        painting_ = true;
        const double start = test::threadMilliseconds();
        QCoreApplication::sendEvent(&widget_, event);
        milliseconds_ += test::threadMilliseconds() - start;
        painting_ = false;
        return true;
    }

private:
    QWidget& widget_;
    double milliseconds_ = 0;
    bool painting_ = false;
};

} // namespace

class TestViewport : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }

    void draggingTheXArrowMovesTheKeyInOneUndoStep()
    {
        Session session;
        QVERIFY(QTest::qWaitForWindowExposed(&session.window));
        session.window.selection().selectKey(session.object, 0);
        QUndoStack& stack = session.window.document().undoStack();
        const int stepsBefore = stack.count();
        const Eigen::Vector3d before = session.key(0).pose.position;
        const Eigen::Quaterniond orientation = session.key(0).pose.orientation;

        const QPointF grab = *session.viewport->handleScreenPosition(Handle::MoveX);
        test::dragAlong(session.viewport, test::straightPath(grab, pastTheXArrow(*session.viewport), 8));

        const Eigen::Vector3d after = session.key(0).pose.position;
        QVERIFY(after.x() > before.x() + 0.1);
        QCOMPARE(after.y(), before.y());
        QCOMPARE(after.z(), before.z());
        QVERIFY(session.key(0).pose.orientation.coeffs() == orientation.coeffs());
        QCOMPARE(stack.count(), stepsBefore + 1);
        stack.undo();
        QVERIFY(session.key(0).pose.position == before);
        stack.redo();
        QVERIFY(session.key(0).pose.position == after);

        // The next drag is an undo step of its own.
        const QPointF again = *session.viewport->handleScreenPosition(Handle::MoveX);
        test::dragAlong(session.viewport, test::straightPath(again, again + QPointF(0, 40), 4));
        QCOMPARE(stack.count(), stepsBefore + 2);
        stack.undo();
        QVERIFY(session.key(0).pose.position == after);
    }

    void turningTheZRingTurnsTheKeyAboutZInOneUndoStep()
    {
        Session session;
        QVERIFY(QTest::qWaitForWindowExposed(&session.window));
        session.window.selection().selectKey(session.object, 1);
        QUndoStack& stack = session.window.document().undoStack();
        const int stepsBefore = stack.count();
        const Pose before = session.key(1).pose;

        const QPointF centre = *session.viewport->controlPoseScreenPosition(1);
        const QPointF grab = *session.viewport->handleScreenPosition(Handle::RotateZ);
        test::dragAlong(session.viewport, arcPath(centre, grab, std::numbers::pi / 4, 6));

        const Pose after = session.key(1).pose;
        QVERIFY(after.position == before.position);
        // A turn about the parent frame's z (the world's here) only: the change fixes z.
        const Eigen::Quaterniond turn = after.orientation * before.orientation.conjugate();
        const Eigen::AngleAxisd axisAngle(turn);
        QVERIFY(axisAngle.angle() > 0.2);
        QVERIFY(std::abs(std::abs(axisAngle.axis().z()) - 1) < 1e-9);
        QCOMPARE(stack.count(), stepsBefore + 1);
        stack.undo();
        QVERIFY(session.key(1).pose.orientation.coeffs() == before.orientation.coeffs());
        stack.redo();
        QVERIFY(session.key(1).pose.orientation.coeffs() == after.orientation.coeffs());
    }

    void theTrailHasOneInstancePerSubdividedPose()
    {
        Session session;
        QVERIFY(QTest::qWaitForWindowExposed(&session.window));
        const SubdivisionSettings settings = session.window.document().object(session.object)->track.subdivision;
        QTRY_COMPARE(session.viewport->trailInstanceCount(), *subdividedPoseCount(6, settings.levels, settings.cyclic));

        SubdivisionSettings finer = settings;
        finer.levels = settings.levels + 2;
        session.window.document().undoStack().push(
            new model::SetSubdivisionCommand(session.window.document(), session.object, finer));
        QTRY_COMPARE(session.viewport->trailInstanceCount(), *subdividedPoseCount(6, finer.levels, finer.cyclic));

        session.viewport->setShowTrail(false);
        QTRY_COMPARE(session.viewport->trailInstanceCount(), std::size_t{0});
    }

    void aHermiteTrackHasATrailThatFollowsTheViewMenusCount()
    {
        Session session(0.0);
        QVERIFY(QTest::qWaitForWindowExposed(&session.window));
        model::Document& document = session.window.document();
        document.push(new model::SetInterpolationCommand(document, session.object, InterpolationMethod::Hermite));
        // The path and the ghost off, so that what differs is the trail.
        for (const char* name : {"actionShowTrajectory", "actionShowGhost"})
            session.window.findChild<QAction*>(QLatin1String(name))->setChecked(false);
        QAction* showTrail = session.window.findChild<QAction*>(QStringLiteral("actionShowTrail"));
        QVERIFY(showTrail->isChecked());
        for (const int copies : {8, 32}) {
            session.window.findChild<QAction*>(QStringLiteral("actionTrailCopies-%1").arg(copies))->trigger();
            QTRY_COMPARE(session.viewport->trailInstanceCount(), std::size_t(copies));
            // Each copy where the motion is at its time, the scene's range spread evenly.
            const std::vector<Eigen::Vector3d> places = copyPlaces(document, session.object, copies);
            const QImage with = drawnImage(*session.viewport);
            showTrail->setChecked(false);
            const QImage without = drawnImage(*session.viewport);
            showTrail->setChecked(true);
            QCOMPARE(session.viewport->trailInstanceCount(), std::size_t{0});
            // The object itself stands on one copy or two, hiding them.
            QVERIFY2(copiesSeen(*session.viewport, places, with, without) >= copies - 2,
                     qPrintable(QStringLiteral("%1 of %2 copies seen").arg(copiesSeen(*session.viewport, places, with, without)).arg(copies)));
        }
        // The choice outlives the window.
        QCOMPARE(QSettings().value(QStringLiteral("view/trailCopies")).toInt(), 32);
    }

    // The selected object's centre path, uploaded when it arrives and drawn from then on: its yellow shows while
    // View ▸ Trajectory is on, goes when it is off, and goes with the selection, the path then emptied.
    void theCentrePathIsDrawnUntilTheSelectionGoes()
    {
        Session session;
        QVERIFY(QTest::qWaitForWindowExposed(&session.window));
        // Hidden for this test alone: the View menu's choices are kept in the settings the later tests read.
        std::vector<QAction*> hiddenHere;
        for (const char* name : {"actionShowTrail", "actionShowGhost", "actionShowControlPoses"})
            hiddenHere.push_back(session.window.findChild<QAction*>(QLatin1String(name)));
        const auto showAgain = qScopeGuard([&] {
            for (QAction* action : hiddenHere)
                action->setChecked(true);
        });
        for (QAction* action : hiddenHere)
            action->setChecked(false);
        QTRY_VERIFY(session.viewport->pathPointCount() > 100);
        const auto yellowPixels = [](const QImage& image) {
            int count = 0;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x) {
                    const QColor colour = image.pixelColor(x, y);
                    count += colour.red() > 230 && colour.green() > 200 && colour.blue() < 130;
                }
            return count;
        };
        QAction* showTrajectory = session.window.findChild<QAction*>(QStringLiteral("actionShowTrajectory"));
        const int shown = yellowPixels(drawnImage(*session.viewport));
        showTrajectory->setChecked(false);
        const int hidden = yellowPixels(drawnImage(*session.viewport));
        QCOMPARE(session.viewport->pathPointCount(), std::size_t{0});
        showTrajectory->setChecked(true);
        QCOMPARE(yellowPixels(drawnImage(*session.viewport)), shown);
        QVERIFY2(shown > hidden + 100, qPrintable(QStringLiteral("%1 yellow pixels shown, %2 hidden").arg(shown).arg(hidden)));
        session.window.selection().clear();
        QTRY_COMPARE(session.viewport->pathPointCount(), std::size_t{0});
        QCOMPARE(yellowPixels(drawnImage(*session.viewport)), hidden);
    }

    void everySelectedObjectHasItsTrail()
    {
        Session session(0.0);
        QVERIFY(QTest::qWaitForWindowExposed(&session.window));
        model::Document& document = session.window.document();
        document.push(new model::SetInterpolationCommand(document, session.object, InterpolationMethod::Hermite));
        // A second object on the sample's keys moved aside along x by more than the sample's reach.
        const model::ObjectId second = session.importAside();
        for (const char* name : {"actionShowTrajectory", "actionShowGhost"})
            session.window.findChild<QAction*>(QLatin1String(name))->setChecked(false);
        constexpr int kCopies = 8;
        session.window.findChild<QAction*>(QStringLiteral("actionTrailCopies-%1").arg(kCopies))->trigger();
        session.window.selection().selectObjects({session.object, second}, session.object);
        QTRY_COMPARE(session.viewport->trailInstanceCount(), std::size_t(2 * kCopies));
        // Framed once the drawn motion has the new object (its trail is sampled from it), so that both show.
        session.viewport->frameScene();

        QAction* showTrail = session.window.findChild<QAction*>(QStringLiteral("actionShowTrail"));
        const QImage with = drawnImage(*session.viewport);
        showTrail->setChecked(false);
        const QImage without = drawnImage(*session.viewport);
        showTrail->setChecked(true);
        for (const model::ObjectId object : {session.object, second}) {
            // The object itself stands on one copy or two, hiding them.
            const int seen = copiesSeen(*session.viewport, copyPlaces(document, object, kCopies), with, without);
            QVERIFY2(seen >= kCopies - 2, qPrintable(QStringLiteral("object %1: %2 of %3 copies seen").arg(object).arg(seen).arg(kCopies)));
        }
        // The second object alone selected: its trail alone.
        session.window.selection().selectObjects({second}, second);
        QTRY_COMPARE(session.viewport->trailInstanceCount(), std::size_t(kCopies));
    }

    void everySelectedScrewTrackHasItsSubdividedTrail()
    {
        Session session(0.0);
        QVERIFY(QTest::qWaitForWindowExposed(&session.window));
        model::Document& document = session.window.document();
        // The sample's screw track at 2 levels: 24 copies of a cycle of 6 keys.
        SubdivisionSettings settings = document.object(session.object)->track.subdivision;
        settings.levels = 2;
        document.push(new model::SetSubdivisionCommand(document, session.object, settings));
        // A second screw track on the sample's keys moved aside along x by more than the sample's reach.
        const model::ObjectId second = session.importAside();
        QCOMPARE(document.object(second)->track.interpolation, InterpolationMethod::Screw);
        for (const char* name : {"actionShowTrajectory", "actionShowGhost"})
            session.window.findChild<QAction*>(QLatin1String(name))->setChecked(false);
        session.window.selection().selectObjects({session.object, second}, session.object);
        const std::size_t copies = *subdividedPoseCount(6, settings.levels, settings.cyclic);
        QTRY_COMPARE(session.viewport->trailInstanceCount(), 2 * copies);
        // Each copy at its subdivided pose (neither object has a parent): a point on its surface there.
        std::vector<std::vector<Eigen::Vector3d>> places;
        for (const model::ObjectId object : {session.object, second}) {
            const model::Mesh& mesh = app::displayMesh(*document.object(object));
            Eigen::Vector3d onSurface = Eigen::Vector3d::Zero();
            for (int corner = 0; corner < 3; ++corner)
                onSurface += mesh.positions[mesh.indices[std::size_t(corner)]].cast<double>() / 3.0;
            std::vector<Pose> controlPoses;
            for (const model::Keyframe& key : document.object(object)->track.keys)
                controlPoses.push_back(key.pose);
            std::vector<Eigen::Vector3d>& objectPlaces = places.emplace_back();
            for (const Pose& pose : subdividePolyscrew(controlPoses, document.object(object)->track.subdivision))
                objectPlaces.push_back(pose.apply(onSurface));
            QCOMPARE(objectPlaces.size(), copies);
        }
        // Framed once the selected objects' centre paths, which pass by every copy, are sampled.
        session.viewport->frameSceneWhenDrawn();
        QTRY_VERIFY(std::all_of(places.begin(), places.end(), [&](const std::vector<Eigen::Vector3d>& objectPlaces) {
            return std::all_of(objectPlaces.begin(), objectPlaces.end(), [&](const Eigen::Vector3d& place) {
                return session.viewport->rect().contains(app::toScreen(session.viewport->camera(), place).toPoint());
            });
        }));

        QAction* showTrail = session.window.findChild<QAction*>(QStringLiteral("actionShowTrail"));
        const QImage with = drawnImage(*session.viewport);
        showTrail->setChecked(false);
        const QImage without = drawnImage(*session.viewport);
        showTrail->setChecked(true);
        for (std::size_t object = 0; object < places.size(); ++object) {
            // The object itself stands on one copy or two, hiding them.
            const int seen = copiesSeen(*session.viewport, places[object], with, without);
            QVERIFY2(seen >= int(copies) - 2, qPrintable(QStringLiteral("object %1: %2 of %3 copies seen").arg(object).arg(seen).arg(copies)));
        }
    }

    // The window's own picture (the screen's, and the user guide's screenshots) holds the viewport's frame as
    // drawn, in place and upright: the viewport draws off screen and shows its frame as an image.
    void theWindowsPictureShowsTheViewportsFrame()
    {
        Session session;
        QVERIFY(QTest::qWaitForWindowExposed(&session.window));
        const QImage frame = drawnImage(*session.viewport).convertToFormat(QImage::Format_RGB32);
        const QImage window = session.window.grab().toImage().convertToFormat(QImage::Format_RGB32);
        const QRect area(session.viewport->mapTo(&session.window, QPoint(0, 0)), session.viewport->size());
        QCOMPARE(frame.size(), area.size());
        QVERIFY(window.copy(area) == frame);
        // Not a blank frame: the selected object's colour stands where its origin projects.
        const QPoint origin = session.viewport->objectScreenPosition(session.object)->toPoint();
        QVERIFY(frame.pixelColor(origin) != frame.pixelColor(2, 2));
    }

    void theNumberPadViewsFollowTheUpAxis()
    {
        Session session;
        QVERIFY(QTest::qWaitForWindowExposed(&session.window));
        app::OrbitCamera& camera = session.viewport->camera();
        // (action, its view direction Z-up, Y-up, the world axis up on screen Z-up, Y-up)
        struct View {
            const char* action;
            Eigen::Vector3d zUpDirection, yUpDirection;
        };
        const std::vector<View> views{{"actionViewFront", Eigen::Vector3d::UnitY(), -Eigen::Vector3d::UnitZ()},
                                      {"actionViewBack", -Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()},
                                      {"actionViewRight", -Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitX()},
                                      {"actionViewLeft", Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitX()},
                                      {"actionViewTop", -Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitY()},
                                      {"actionViewBottom", Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY()}};
        QAction* yUp = session.window.findChild<QAction*>(QStringLiteral("actionYUp"));
        QVERIFY(yUp != nullptr && !yUp->isChecked());
        for (const bool y : {false, true}) {
            yUp->setChecked(y);
            const Eigen::Vector3d up = y ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
            for (const View& view : views) {
                session.window.findChild<QAction*>(QLatin1String(view.action))->trigger();
                const Eigen::Vector3d expected = y ? view.yUpDirection : view.zUpDirection;
                QVERIFY2((camera.viewDirection() - expected).norm() < 1e-9, view.action);
                // The side views stand upright: the up axis points up the screen.
                if (std::abs(expected.dot(up)) < 0.5) {
                    const Eigen::Vector3d centre = camera.project(camera.target());
                    const Eigen::Vector3d above = camera.project(camera.target() + up);
                    QVERIFY2(above.y() < centre.y() - 1 && std::abs(above.x() - centre.x()) < 1e-6, view.action);
                }
            }
        }
        // Front, Y-up: x to the right, as in Maya.
        session.window.findChild<QAction*>(QStringLiteral("actionViewFront"))->trigger();
        QVERIFY(camera.project(camera.target() + Eigen::Vector3d::UnitX()).x() > camera.project(camera.target()).x() + 1);
        QCOMPARE(QSettings().value(QStringLiteral("view/yUp")).toBool(), true);
        yUp->setChecked(false);
    }

    void clickingSelectsObjectsAndControlPoses()
    {
        Session session;
        QVERIFY(QTest::qWaitForWindowExposed(&session.window));
        app::Selection& selection = session.window.selection();
        selection.clear();
        QTest::mouseClick(session.viewport, Qt::LeftButton, Qt::NoModifier,
                          session.viewport->objectScreenPosition(session.object)->toPoint());
        QCOMPARE(selection.object(), session.object);
        QVERIFY(!selection.key());

        QTest::mouseClick(session.viewport, Qt::LeftButton, Qt::NoModifier,
                          session.viewport->controlPoseScreenPosition(3)->toPoint());
        QCOMPARE(selection.key(), std::optional<std::size_t>(3));

        // Empty space keeps the object and clears the key.
        QTest::mouseClick(session.viewport, Qt::LeftButton, Qt::NoModifier, QPoint(5, 5));
        QCOMPARE(selection.object(), session.object);
        QVERIFY(!selection.key());
    }

    void theGhostShowsTheMotionAsOpenedWhereItDiffers()
    {
        Session session(0.0);
        QVERIFY(QTest::qWaitForWindowExposed(&session.window));
        QTRY_VERIFY(session.viewport->trailInstanceCount() > 0); // drawn since the sample opened
        QVERIFY(!session.viewport->drewGhost());
        session.window.selection().selectKey(session.object, 0);
        const QPointF grab = *session.viewport->handleScreenPosition(Handle::MoveX);
        test::dragAlong(session.viewport, test::straightPath(grab, pastTheXArrow(*session.viewport), 4));
        QTRY_VERIFY(session.viewport->drewGhost());
        session.window.document().undoStack().undo();
        QTRY_VERIFY(!session.viewport->drewGhost());
    }

    void dragsAndOrbitsTheCameraAndTheWheelZooms()
    {
        Session session;
        QVERIFY(QTest::qWaitForWindowExposed(&session.window));
        const Eigen::Vector3d eye = session.viewport->camera().eye();
        const int steps = session.window.document().undoStack().count();
        test::dragAlong(session.viewport, test::straightPath(QPointF(20, 20), QPointF(120, 60), 5));
        QVERIFY((session.viewport->camera().eye() - eye).norm() > 0.1);
        QCOMPARE(session.window.document().undoStack().count(), steps);

        const double distance = session.viewport->camera().distance();
        const QPointF at(300, 300);
        QWheelEvent wheel(at, session.viewport->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(session.viewport, &wheel);
        QVERIFY(session.viewport->camera().distance() < distance);

        session.viewport->frameScene();
        for (std::size_t key = 0; key < 6; ++key)
            QVERIFY(session.viewport->rect().contains(session.viewport->controlPoseScreenPosition(key)->toPoint()));
    }

    // Levels 8 on the sample: 1536 trail instances, re-subdivided at every move of the drag.
    void measuresDrawingWhileDraggingWithThousandsOfInstances()
    {
        Session session;
        QVERIFY(QTest::qWaitForWindowExposed(&session.window));
        const std::size_t instances = session.trailAtLevels(8);

        double framesPerSecond = 0, subdivisionMs = 0, latencyMs = 0;
        connect(session.viewport, &app::Viewport::frameStatsChanged, this, [&](double fps, double ms, double latency) {
            framesPerSecond = fps;
            subdivisionMs = ms;
            latencyMs = latency;
        });
        // Drawing alone first: orbiting redraws the trail without re-subdividing it.
        const auto waitForFrame = [&](std::uint64_t drawn) {
            // Every move asks for a frame: wait for it without spinning.
            while (session.viewport->framesDrawn() == drawn)
                QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
        };
        constexpr int kMoves = 60;
        const QPointF corner(30, 30);
        QTest::mousePress(session.viewport, Qt::LeftButton, Qt::NoModifier, corner.toPoint());
        QElapsedTimer clock;
        clock.start();
        for (int move = 1; move <= kMoves; ++move) {
            const std::uint64_t drawn = session.viewport->framesDrawn();
            test::sendMove(session.viewport, corner + QPointF(move % 2 == 0 ? 0 : 4, 0), Qt::LeftButton);
            waitForFrame(drawn);
        }
        const double orbitSeconds = double(clock.nsecsElapsed()) / 1e9;
        QTest::mouseRelease(session.viewport, Qt::LeftButton, Qt::NoModifier, corner.toPoint());

        const int stepsBefore = session.window.document().undoStack().count();
        const QPointF grab = *session.viewport->handleScreenPosition(Handle::MoveX);
        const QPointF end = pastTheXArrow(*session.viewport);
        QTest::mousePress(session.viewport, Qt::LeftButton, Qt::NoModifier, grab.toPoint());
        clock.restart();
        for (int move = 1; move <= kMoves; ++move) {
            // Back and forth along the arrow, a frame drawn after each move, as fast as it goes.
            const double phase = 0.5 - 0.5 * std::cos(2 * std::numbers::pi * move / 30.0);
            const std::uint64_t drawn = session.viewport->framesDrawn();
            test::sendMove(session.viewport, grab + (end - grab) * phase, Qt::LeftButton);
            waitForFrame(drawn);
        }
        const double dragSeconds = double(clock.nsecsElapsed()) / 1e9;
        QTest::mouseRelease(session.viewport, Qt::LeftButton, Qt::NoModifier, grab.toPoint());
        QTRY_COMPARE(session.viewport->trailInstanceCount(), instances);
        QCOMPARE(session.window.document().undoStack().count(), stepsBefore + 1);
        qInfo("%zu trail instances, a frame after each of %d moves: orbiting %.1f frames/s (%.1f ms a frame), dragging "
              "the x arrow %.1f frames/s (%.1f ms a move and frame); the viewport's last figures: %.1f fps, "
              "subdivision %.1f ms on the worker, %.1f ms from request to arrival",
              instances, kMoves, kMoves / orbitSeconds, 1000 * orbitSeconds / kMoves, kMoves / dragSeconds,
              1000 * dragSeconds / kMoves, framesPerSecond, subdivisionMs, latencyMs);
    }

    // Issue 18: what a drag move costs the UI thread itself, with every dock open (the smoothness
    // plots tabbed behind the inspector, the speed plot and the sphere on screen) and 1,536 trail
    // instances. Prints per move the UI thread's CPU time, the part of it in the viewport's paint
    // events (Gyre's draw calls, the GL driver's work on this thread and reading the frame back), and
    // the wall time from one move to its frame.
    void measuresTheUiThreadPerDragMoveWithEveryDockShown()
    {
        Session session;
        for (QDockWidget* dock : session.window.findChildren<QDockWidget*>())
            dock->show();
        QVERIFY(QTest::qWaitForWindowExposed(&session.window));
        const std::size_t instances = session.trailAtLevels(8);

        PaintClock viewportPaint(*session.viewport);

        constexpr int kWarmUpMoves = 10;
        constexpr int kMoves = 60;
        const QPointF grab = *session.viewport->handleScreenPosition(Handle::MoveX);
        const QPointF end = pastTheXArrow(*session.viewport);
        double uiStart = 0;
        QElapsedTimer clock;
        QTest::mousePress(session.viewport, Qt::LeftButton, Qt::NoModifier, grab.toPoint());
        for (int move = 1; move <= kWarmUpMoves + kMoves; ++move) {
            if (move == kWarmUpMoves + 1) {
                viewportPaint.reset();
                uiStart = test::threadMilliseconds();
                clock.start();
            }
            // Back and forth along the arrow, each move waiting for its frame, as fast as it goes.
            const double phase = 0.5 - 0.5 * std::cos(2 * std::numbers::pi * move / 30.0);
            const std::uint64_t drawn = session.viewport->framesDrawn();
            test::sendMove(session.viewport, grab + (end - grab) * phase, Qt::LeftButton);
            while (session.viewport->framesDrawn() == drawn)
                QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
        }
        const double uiMilliseconds = test::threadMilliseconds() - uiStart;
        const double wallMilliseconds = double(clock.nsecsElapsed()) / 1e6;
        QTest::mouseRelease(session.viewport, Qt::LeftButton, Qt::NoModifier, grab.toPoint());
        QTRY_COMPARE(session.viewport->trailInstanceCount(), instances);
        qInfo("%zu trail instances, every dock shown, per drag move over %d moves: UI thread %.1f ms of CPU, of it "
              "%.1f ms in the viewport's paint; %.1f ms wall from move to frame",
              instances, kMoves, uiMilliseconds / kMoves, viewportPaint.milliseconds() / kMoves, wallMilliseconds / kMoves);
    }
};

QTEST_MAIN(TestViewport)
#include "tst_viewport.moc"
