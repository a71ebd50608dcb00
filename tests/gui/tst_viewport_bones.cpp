// The viewport on an imported motion capture: its joints drawn as bones from each joint to each child
// joint, a click on a bone selecting its joint and the selected bone drawn highlighted; the camera
// framing the capture on import, on Frame Scene and on Frame Selected, at a human's size and at a
// hundredth of it; Blender's number-pad views and orthographic toggle; wireframe and X-ray shading; an
// empty (Object ▸ Add ▸ Empty) drawn as its axes, pickable, highlighted, and never a joint.

#include "app/main_window.h"
#include "app/scene_file_actions.h"
#include "app/viewport/default_shape.h"
#include "app/viewport/viewport.h"
#include "built_scene_worker.h"
#include "gui_test_support.h"
#include "jobs/scene_file_jobs.h"
#include "model/commands/reparent_object_command.h"
#include "model/commands/replace_keyframes_command.h"
#include "model/key_edits.h"
#include "model/project_file.h"
#include "model/scene_motion.h"

#include <QAction>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <Eigen/Geometry>

#include <algorithm>
#include <map>

using namespace gyre;

namespace {

// A BVH skeleton (Y-up, as BVH files are) whose offsets are `scale` times a human's in units: hips,
// a spine to the head (with an end site), two arms from the chest and two legs from the hips.
QByteArray skeletonBvh(double scale)
{
    static const test::BvhJoint joints[] = {
        {"Hips", 0, 0, 0, 0},        {"Spine", 1, 0, 2, 0},     {"Chest", 2, 0, 2, 0},     {"Head", 3, 0, 2, 0},
        {"LeftArm", 3, 2, 1.5, 0},   {"LeftHand", 4, 3, 0, 0},  {"RightArm", 3, -2, 1.5, 0}, {"RightHand", 4, -3, 0, 0},
        {"LeftLeg", 1, 1, -1, 0},    {"LeftFoot", 2, 0, -4, 0}, {"RightLeg", 1, -1, -1, 0},  {"RightFoot", 2, 0, -4, 0},
    };
    return test::bvhFile(
        joints, scale, 30, [scale](int) { return Eigen::Vector3d(0.0, 5.0 * scale, 0.0); },
        [](int frame, std::size_t joint, int axis) { return 10.0 * std::sin(0.1 * frame + double(joint) + axis); }, "Head");
}

constexpr std::size_t kJoints = 12;
constexpr std::size_t kBones = kJoints + 5; // and one on from each leaf: the hands, the feet, the end site

// The main window with a skeleton imported into a new project, paused at 0.
struct Session {
    app::MainWindow window;
    app::Viewport* viewport = nullptr;
    QTemporaryDir folder;
    std::size_t firstJoint = 0; // the index of the skeleton's root in the scene; the project's own objects come first

    explicit Session(double scale = 1.0)
    {
        window.resize(1200, 850);
        window.show();
        window.activateWindow(); // the shortcuts go to the active window
        if (!QTest::qWaitForWindowActive(&window))
            qFatal("The main window was not shown");
        viewport = window.findChild<app::Viewport*>();
        const QString path = folder.filePath(QStringLiteral("skeleton.bvh"));
        QFile file(path);
        const QByteArray bvh = skeletonBvh(scale);
        if (!file.open(QIODevice::WriteOnly) || file.write(bvh) != bvh.size())
            qFatal("Cannot write the BVH file");
        file.close();
        QSignalSpy imported(&window.sceneFiles(), &app::SceneFileActions::objectsImported);
        window.openFile(path);
        if (!imported.wait(30'000))
            qFatal("The skeleton was not imported");
        window.playback().pause();
        window.document().setCurrentTime(0.0);
        // The skeleton's motion is built off the UI thread: until it arrives, its joints have no place.
        const auto bonesDrawn = [&] {
            viewport->update();
            return viewport->skeleton().bones().size() == kBones;
        };
        if (!QTest::qWaitFor(bonesDrawn, 30'000))
            qFatal("The viewport did not draw the bones");
        const model::ObjectId hips = objectNamed("Hips");
        while (scene().objects[firstJoint].id != hips)
            ++firstJoint;
    }

    const model::Scene& scene() { return window.document().scene(); }
    model::ObjectId objectNamed(const char* name)
    {
        for (const model::SceneObject& object : scene().objects)
            if (object.name == QLatin1String(name))
                return object.id;
        qFatal("No object is named %s", name);
    }
    const app::Bone& boneOf(model::ObjectId joint)
    {
        const std::vector<app::Bone>& bones = viewport->skeleton().bones();
        const auto bone = std::find_if(bones.begin(), bones.end(), [&](const app::Bone& each) { return each.joint == joint; });
        if (bone == bones.end())
            qFatal("The joint has no bone");
        return *bone;
    }
    void trigger(const char* action) { window.findChild<QAction*>(QLatin1String(action))->trigger(); }

    // Draws until the viewport has drawn the newest motion: a frame after the motion holds the skeleton.
    void settle()
    {
        const std::uint64_t drawn = viewport->framesDrawn();
        viewport->update();
        if (!QTest::qWaitFor([&] { return viewport->framesDrawn() > drawn; }))
            qFatal("The viewport did not draw");
    }

    model::SceneMotion motion()
    {
        model::Document& document = window.document();
        return model::SceneMotion(scene(), [&document](const model::SceneObject& object) { return document.motion(object.id); });
    }

    // Every joint's origin on screen.
    std::vector<Eigen::Vector3d> jointsOnScreen()
    {
        std::vector<Eigen::Vector3d> points;
        const model::SceneMotion built = motion();
        for (std::size_t i = firstJoint; i < scene().objects.size(); ++i)
            points.push_back(viewport->camera().project(built.worldPose(scene().objects[i].id, 0.0).position));
        return points;
    }

    // Whether every joint is inside the view and the skeleton fills at least a third of its height.
    bool skeletonFillsTheView()
    {
        double top = viewport->height();
        double bottom = 0;
        for (const Eigen::Vector3d& point : jointsOnScreen()) {
            if (point.x() < 0 || point.x() > viewport->width() || point.y() < 0 || point.y() > viewport->height()
                || point.z() < 0 || point.z() > 1)
                return false;
            top = std::min(top, point.y());
            bottom = std::max(bottom, point.y());
        }
        return bottom - top > viewport->height() / 3.0;
    }

    QPointF screenMiddle(const app::Bone& bone)
    {
        const Eigen::Vector3d middle = viewport->camera().project(0.5 * (bone.head() + bone.tail()));
        return {middle.x(), middle.y()};
    }
};

bool isSelectedOrange(const QColor& color)
{
    return color.red() > color.green() + 40 && color.green() > color.blue() + 40;
}

bool isGrey(const QColor& color)
{
    return std::abs(color.red() - color.blue()) < 40 && color.blue() > 40;
}

} // namespace

class TestViewportBones : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        test::useTestSettings();
        test::useBuiltSceneWorker();
    }

    void eachJointHasABoneToEachChildJoint()
    {
        Session session;
        const model::Scene& scene = session.scene();
        QCOMPARE(scene.objects.size() - session.firstJoint, kJoints + 1); // and the head's end site
        const app::Skeleton& skeleton = session.viewport->skeleton();
        const model::SceneMotion motion = session.motion();
        std::map<model::ObjectId, int> childJoints;
        // The project's own block, without a mesh but alone, is no joint.
        for (std::size_t i = 0; i < session.firstJoint; ++i)
            QVERIFY(!skeleton.isJoint(i));
        for (std::size_t i = session.firstJoint; i < scene.objects.size(); ++i) {
            QVERIFY(skeleton.isJoint(i));
            const model::SceneObject& child = scene.objects[i];
            if (i == session.firstJoint)
                continue;
            ++childJoints[child.parent];
            const Eigen::Vector3d head = motion.worldPose(child.parent, 0.0).position;
            const Eigen::Vector3d tail = motion.worldPose(child.id, 0.0).position;
            const auto bone = std::find_if(skeleton.bones().begin(), skeleton.bones().end(), [&](const app::Bone& each) {
                return each.joint == child.parent && (each.tail() - tail).norm() < 1e-6;
            });
            QVERIFY2(bone != skeleton.bones().end(), qPrintable(child.name));
            QVERIFY((bone->head() - head).norm() < 1e-6);
            QVERIFY(std::abs(bone->length - (tail - head).norm()) < 1e-6);
        }
        // A bone for each link, and one on from each leaf.
        const std::size_t leaves = kJoints + 1 - childJoints.size();
        QCOMPARE(skeleton.bones().size(), kJoints + leaves);
        QCOMPARE(skeleton.bones().size(), kBones);
    }

    void aClickOnABoneSelectsItsJointDrawnHighlighted()
    {
        Session session;
        session.trigger("actionViewFront");
        session.trigger("actionFrameAll");
        session.settle();
        const auto boneOf = [&](const char* name) { return session.boneOf(session.objectNamed(name)); };
        for (const char* name : {"Spine", "LeftArm", "RightLeg", "LeftFoot"}) {
            const app::Bone bone = boneOf(name);
            QTest::mouseClick(session.viewport, Qt::LeftButton, Qt::NoModifier, session.screenMiddle(bone).toPoint());
            QCOMPARE(session.window.selection().object(), bone.joint);
        }
        session.settle();
        const QImage image = session.viewport->grabFramebuffer();
        const qreal ratio = image.devicePixelRatio();
        const auto colourAt = [&](const app::Bone& bone) { return image.pixelColor((session.screenMiddle(bone) * ratio).toPoint()); };
        QVERIFY2(isSelectedOrange(colourAt(boneOf("LeftFoot"))), qPrintable(colourAt(boneOf("LeftFoot")).name()));
        QVERIFY2(isGrey(colourAt(boneOf("Spine"))), qPrintable(colourAt(boneOf("Spine")).name()));
    }

    void anEmptyIsItsAxesPickableHighlightedAndNeverAJoint()
    {
        Session session;
        model::Document& document = session.window.document();
        const int steps = document.undoStack().count();
        session.trigger("actionAdd-empty");
        QCOMPARE(document.undoStack().count(), steps + 1);
        QCOMPARE(document.undoStack().text(steps), QStringLiteral("Add Empty"));
        const model::SceneObject& added = session.scene().objects.back();
        const model::ObjectId empty = added.id;
        QVERIFY(added.empty && added.mesh == nullptr);
        QCOMPARE(added.name, QStringLiteral("Empty"));
        QCOMPARE(session.window.selection().object(), empty);
        // Away from the skeleton, seen from the front.
        const model::Keyframe away{0.0, Pose{Eigen::Quaterniond::Identity(), {30, 0, 0}}};
        document.push(new model::ReplaceKeyframesCommand(document, {{empty, model::withKeys(added.track.keys, {away})}},
                                                         model::ReplaceKeyframesCommand::Edit::Insert));
        session.trigger("actionViewFront");
        const auto onScreen = [&](const Eigen::Vector3d& world) {
            const Eigen::Vector3d point = session.viewport->camera().project(world);
            return QPointF(point.x(), point.y());
        };
        // The motion with the key is built off the UI thread: Frame Selected frames the empty once it has it.
        const QPointF middle(session.viewport->width() / 2.0, session.viewport->height() / 2.0);
        QVERIFY(QTest::qWaitFor([&] {
            session.trigger("actionFrameSelected");
            return (onScreen({30, 0, 0}) - middle).manhattanLength() < 2.0;
        }));
        session.settle();
        // On its x axis, and beside the axes where the block would be drawn: the empty is lines, not a block.
        const QPointF onAxis = onScreen({30.0 + 0.5 * app::kEmptyAxisLength, 0, 0});
        const QPointF offAxes = onScreen({30.0 + 0.3 * app::kEmptyAxisLength, 0, 0.3 * app::kEmptyAxisLength});
        QImage image = session.viewport->grabFramebuffer();
        const qreal ratio = image.devicePixelRatio();
        // A line a pixel wide: within two pixels of where it is meant to be.
        const auto anyAbout = [&](const QPointF& point, bool (*test)(const QColor&)) {
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx)
                    if (test(image.pixelColor((point * ratio).toPoint() + QPoint(dx, dy))))
                        return true;
            return false;
        };
        QVERIFY(anyAbout(onAxis, isSelectedOrange));
        // The dark background there, not a lit block.
        const QColor background = image.pixelColor((offAxes * ratio).toPoint());
        QVERIFY2(background.lightness() < 80, qPrintable(background.name()));

        // Another object selected: the axes turn grey; a click on one selects the empty again.
        session.window.selection().selectObject(session.objectNamed("Hips"));
        session.settle();
        image = session.viewport->grabFramebuffer();
        QVERIFY(anyAbout(onAxis, [](const QColor& color) { return isGrey(color) && color.lightness() > 150; }));
        QVERIFY(!anyAbout(onAxis, isSelectedOrange));
        QTest::mouseClick(session.viewport, Qt::LeftButton, Qt::NoModifier, onAxis.toPoint());
        QCOMPARE(session.window.selection().object(), empty);

        // Under a leaf joint, it does not become a joint, nor make a bone of the hand's point at it.
        document.push(new model::ReparentObjectCommand(document, empty, session.objectNamed("LeftHand")));
        session.settle();
        const model::SceneObject* reparented = document.object(empty);
        const auto emptyIndex = static_cast<std::size_t>(reparented - session.scene().objects.data());
        QCOMPARE(session.viewport->skeleton().bones().size(), kBones);
        QVERIFY(!session.viewport->skeleton().isJoint(emptyIndex));

        // Saved and opened again, it is still an empty.
        const QString path = session.folder.filePath(QStringLiteral("empty.gyre"));
        model::writeProject(path, document.scene());
        const model::Scene opened = model::readProject(path);
        for (const model::SceneObject& object : opened.objects)
            QCOMPARE(object.empty, object.id == empty);
        QVERIFY(opened.objects[emptyIndex].mesh == nullptr);
    }

    void theCameraFramesTheSkeletonAtAnySize_data()
    {
        QTest::addColumn<double>("scale");
        QTest::newRow("human size") << 1.0;
        QTest::newRow("a hundredth") << 0.01;
        QTest::newRow("a hundred times") << 100.0;
    }

    void theCameraFramesTheSkeletonAtAnySize()
    {
        QFETCH(double, scale);
        Session session(scale);
        // Framed as soon as imported.
        QVERIFY(session.skeletonFillsTheView());
        // Zoomed far off, Frame Scene brings it back.
        session.viewport->camera().zoom(-25);
        QVERIFY(!session.skeletonFillsTheView());
        session.trigger("actionFrameAll");
        QVERIFY(session.skeletonFillsTheView());
    }

    void frameSelectedLooksAtTheSelectedJointsBones()
    {
        Session session;
        const model::ObjectId leftLeg = session.objectNamed("LeftLeg");
        session.window.selection().selectObject(leftLeg);
        session.trigger("actionFrameSelected");
        // The leg's one bone, to the foot, fills the view about the camera's target.
        const app::Bone& bone = session.boneOf(leftLeg);
        QVERIFY((session.viewport->camera().target() - 0.5 * (bone.head() + bone.tail())).norm() < 1e-6);
        const Eigen::Vector3d head = session.viewport->camera().project(bone.head());
        const Eigen::Vector3d tail = session.viewport->camera().project(bone.tail());
        QVERIFY((head - tail).head<2>().norm() > session.viewport->height() / 3.0);
        // With NumLock off, the pad's period sends Delete: it frames the joint too and deletes nothing.
        const Eigen::Vector3d middle = 0.5 * (bone.head() + bone.tail()); // framing rebuilds the bones
        session.trigger("actionFrameAll");
        const std::size_t objects = session.window.document().scene().objects.size();
        QTest::keyClick(session.viewport, Qt::Key_Delete, Qt::KeypadModifier);
        QVERIFY((session.viewport->camera().target() - middle).norm() < 1e-6);
        QCOMPARE(session.window.document().scene().objects.size(), objects);
    }

    void numberPadViewsLookAlongTheWorldAxes()
    {
        Session session;
        app::OrbitCamera& camera = session.viewport->camera();
        const struct {
            Qt::Key key;
            Qt::KeyboardModifiers modifiers;
            Eigen::Vector3d direction; // the view's, in Gyre's Z-up world
            Eigen::Vector3d screenRight;
        } views[] = {
            {Qt::Key_1, Qt::KeypadModifier, {0, 1, 0}, {1, 0, 0}},
            {Qt::Key_1, Qt::KeypadModifier | Qt::ControlModifier, {0, -1, 0}, {-1, 0, 0}},
            {Qt::Key_3, Qt::KeypadModifier, {-1, 0, 0}, {0, 1, 0}},
            {Qt::Key_3, Qt::KeypadModifier | Qt::ControlModifier, {1, 0, 0}, {0, -1, 0}},
            {Qt::Key_7, Qt::KeypadModifier, {0, 0, -1}, {1, 0, 0}},
            {Qt::Key_7, Qt::KeypadModifier | Qt::ControlModifier, {0, 0, 1}, {1, 0, 0}},
        };
        // With NumLock off the pad sends End for 1, PageDown for 3, Home for 7: the same views.
        const std::map<Qt::Key, Qt::Key> numLockOff{{Qt::Key_1, Qt::Key_End}, {Qt::Key_3, Qt::Key_PageDown},
                                                    {Qt::Key_7, Qt::Key_Home}};
        for (const auto& view : views)
            for (const Qt::Key key : {view.key, numLockOff.at(view.key)}) {
                camera.lookFrom(0.3, 0.2); // away from every view
                QTest::keyClick(session.viewport, key, view.modifiers);
                QVERIFY((camera.viewDirection() - view.direction).norm() < 1e-9);
            }
        for (const auto& view : views) {
            QTest::keyClick(session.viewport, view.key, view.modifiers);
            QVERIFY((camera.viewDirection() - view.direction).norm() < 1e-9);
            const Eigen::Vector3d right = camera.project(camera.target() + view.screenRight) - camera.project(camera.target());
            QVERIFY(right.x() > 10 && std::abs(right.y()) < 1e-6);
        }
        // Front: z up on screen, the skeleton standing.
        QTest::keyClick(session.viewport, Qt::Key_1, Qt::KeypadModifier);
        const Eigen::Vector3d up = camera.project(camera.target() + Eigen::Vector3d::UnitZ()) - camera.project(camera.target());
        QVERIFY(up.y() < -10 && std::abs(up.x()) < 1e-6);

        // 5: orthographic, where a point and another behind it along the view meet on screen.
        QVERIFY(!camera.isOrthographic());
        QTest::keyClick(session.viewport, Qt::Key_5, Qt::KeypadModifier);
        QVERIFY(camera.isOrthographic());
        const Eigen::Vector3d near = camera.target() + Eigen::Vector3d(1, 0, 1);
        const Eigen::Vector3d far = near + 3 * camera.viewDirection();
        QVERIFY((camera.project(near) - camera.project(far)).head<2>().norm() < 1e-6);
        QVERIFY(camera.project(near).z() < camera.project(far).z());
        // Picking works in orthographic too.
        const model::ObjectId spine = session.objectNamed("Spine");
        const app::Bone& bone = session.boneOf(spine);
        QTest::mouseClick(session.viewport, Qt::LeftButton, Qt::NoModifier, session.screenMiddle(bone).toPoint());
        QCOMPARE(session.window.selection().object(), spine);
        QTest::keyClick(session.viewport, Qt::Key_5, Qt::KeypadModifier);
        QVERIFY(!camera.isOrthographic());
        QVERIFY((camera.project(near) - camera.project(far)).head<2>().norm() > 1);
    }

    void wireframeAndXrayChangeHowTheObjectsAreDrawn()
    {
        Session session;
        session.trigger("actionViewFront");
        session.window.selection().selectObject(session.objectNamed("LeftLeg"));
        session.trigger("actionFrameSelected"); // the left leg's bone, filling the view
        session.settle();
        const auto objectPixels = [&] {
            const QImage image = session.viewport->grabFramebuffer();
            int count = 0;
            for (int y = 0; y < image.height(); y += 4)
                for (int x = 0; x < image.width(); x += 4)
                    count += isSelectedOrange(image.pixelColor(x, y)) ? 1 : 0;
            return count;
        };
        const int solid = objectPixels();
        QVERIFY2(solid > 100, qPrintable(QString::number(solid)));

        QTest::keyClick(session.viewport, Qt::Key_Z, Qt::ShiftModifier);
        QVERIFY(session.viewport->shading().wireframe);
        session.settle();
        // Only the triangles' edges: most of the bone's pixels are background now.
        QVERIFY2(objectPixels() < solid / 3, qPrintable(QString::number(objectPixels())));
        QTest::keyClick(session.viewport, Qt::Key_Z, Qt::ShiftModifier);
        QVERIFY(!session.viewport->shading().wireframe);

        QTest::keyClick(session.viewport, Qt::Key_Z, Qt::AltModifier);
        QVERIFY(session.viewport->shading().xray);
        session.settle();
        // See-through: the bone's colour mixed with the background's, no longer the selected orange.
        QVERIFY2(objectPixels() < solid / 3, qPrintable(QString::number(objectPixels())));
        QTest::keyClick(session.viewport, Qt::Key_Z, Qt::AltModifier);
        QVERIFY(!session.viewport->shading().xray);
        session.settle();
        QCOMPARE(objectPixels(), solid);
    }
};

QTEST_MAIN(TestViewportBones)
#include "tst_viewport_bones.moc"
