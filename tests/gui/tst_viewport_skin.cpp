// The viewport on a skinned mesh: a bar skinned to two joints follows them when a joint turns (linear
// blend skinning in the vertex shader, checked by the pixels where the bar was and where its far end
// goes, worked out here with poses), while a rigid box stays where it was; a click hits the bar where
// it is drawn, not where it was modelled; undo puts the bar back in its bind pose.

#include "app/main_window.h"
#include "app/viewport/viewport.h"
#include "gui_test_support.h"
#include "skinned_tube.h"
#include "model/commands/set_keyframe_orientation_command.h"
#include "model/primitive_meshes.h"
#include "model/project_file.h"

#include <QAction>
#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTest>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

using namespace gyre;

namespace {

constexpr float kHalfWidth = 0.1F;
constexpr model::ObjectId kRoot = 1;
constexpr model::ObjectId kTip = 2;
constexpr model::ObjectId kBar = 3;
constexpr model::ObjectId kBox = 4;
const Eigen::Vector3d kBoxPosition(-2.0, 0.0, 0.0);

// A bar along x from 0 to 2, its cross-section 0.2 wide, skinned to Root at the origin and Tip at
// (1, 0, 0): a vertex at x weighs x/2 on Tip and the rest on Root.
std::shared_ptr<model::Mesh> skinnedBar()
{
    auto bar = std::make_shared<model::Mesh>();
    const float w = kHalfWidth;
    for (const float x0 : {0.0F, 1.0F}) {
        const float x1 = x0 + 1.0F;
        model::addFace(*bar, {{x0, -w, -w}, {x1, -w, -w}, {x1, -w, w}, {x0, -w, w}});
        model::addFace(*bar, {{x0, w, -w}, {x0, w, w}, {x1, w, w}, {x1, w, -w}});
        model::addFace(*bar, {{x0, -w, -w}, {x0, w, -w}, {x1, w, -w}, {x1, -w, -w}});
        model::addFace(*bar, {{x0, -w, w}, {x1, -w, w}, {x1, w, w}, {x0, w, w}});
    }
    model::addFace(*bar, {{0, -w, -w}, {0, -w, w}, {0, w, w}, {0, w, -w}});
    model::addFace(*bar, {{2, -w, -w}, {2, w, -w}, {2, w, w}, {2, -w, w}});
    model::Skin& skin = bar->skin;
    skin.joints = {kRoot, kTip};
    Eigen::Matrix4f tipInverseBind = Eigen::Matrix4f::Identity();
    tipInverseBind(0, 3) = -1.0F;
    skin.inverseBinds = {Eigen::Matrix4f::Identity(), tipInverseBind};
    for (const Eigen::Vector3f& position : bar->positions) {
        const float onTip = position.x() / 2.0F;
        skin.vertexJoints.push_back({0, 1, 0, 0});
        skin.vertexWeights.emplace_back(1.0F - onTip, onTip, 0.0F, 0.0F);
    }
    return bar;
}

model::Scene skinnedScene()
{
    model::Scene scene;
    scene.objects = {test::sceneObject(kRoot, "Root", model::kNoObject, Eigen::Vector3d::Zero(), nullptr),
                     test::sceneObject(kTip, "Tip", kRoot, Eigen::Vector3d(1, 0, 0), nullptr),
                     test::sceneObject(kBar, "Bar", model::kNoObject, Eigen::Vector3d::Zero(), skinnedBar()),
                     test::sceneObject(kBox, "Box", model::kNoObject, kBoxPosition,
                            std::make_shared<model::Mesh>(model::primitiveMesh(model::Primitive::Box)))};
    scene.nextObjectId = kBox + 1;
    return scene;
}

// Lit mesh: the grid's lines (0.32 grey) and the background (0.19 at most) are darker.
bool isMesh(const QColor& color) { return color.value() > 120; }

struct Session {
    app::MainWindow window;
    app::Viewport* viewport = nullptr;
    QTemporaryDir folder;

    explicit Session(const model::Scene& scene = skinnedScene(), std::size_t bones = 2)
    {
        window.resize(1200, 850);
        window.show();
        window.activateWindow();
        if (!QTest::qWaitForWindowActive(&window))
            qFatal("The main window was not shown");
        viewport = window.findChild<app::Viewport*>();
        const QString path = folder.filePath(QStringLiteral("skinned.gyre"));
        model::writeProject(path, scene);
        if (!window.openProject(path))
            qFatal("The project did not open");
        window.playback().pause();
        if (!QTest::qWaitFor([&] { viewport->update(); return viewport->skeleton().bones().size() == bones; }, 30'000))
            qFatal("The viewport did not draw the joints");
        window.findChild<QAction*>(QStringLiteral("actionViewFront"))->trigger();
        window.findChild<QAction*>(QStringLiteral("actionFrameAll"))->trigger();
        settle();
    }

    void settle()
    {
        const std::uint64_t drawn = viewport->framesDrawn();
        viewport->update();
        if (!QTest::qWaitFor([&] { return viewport->framesDrawn() > drawn; }))
            qFatal("The viewport did not draw");
    }

    QPointF onScreen(const Eigen::Vector3d& world) const
    {
        const Eigen::Vector3d point = viewport->camera().project(world);
        return {point.x(), point.y()};
    }

    QColor colourAt(const QImage& image, const Eigen::Vector3d& world) const
    {
        return image.pixelColor((onScreen(world) * image.devicePixelRatio()).toPoint());
    }

    // Whether a new frame shows a mesh at `world`.
    bool drawsMeshAt(const Eigen::Vector3d& world)
    {
        settle();
        return isMesh(colourAt(viewport->grabFramebuffer(), world));
    }
};

} // namespace

class TestViewportSkin : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }

    void theBarFollowsItsJointAndTheBoxStays()
    {
        Session session;
        model::Document& document = session.window.document();
        // Near the bar's far end, x = 1.9, which Tip alone moves; and where Tip turned a quarter
        // turn about −y takes that point: Tip's origin + R·(point − Tip's origin) = (1, 0, 0.9).
        const Eigen::Vector3d farEnd(1.9, 0.0, 0.0);
        const Eigen::Quaterniond turn(Eigen::AngleAxisd(-std::numbers::pi / 2, Eigen::Vector3d::UnitY()));
        const Eigen::Vector3d tipOrigin(1.0, 0.0, 0.0);
        const Eigen::Vector3d farEndTurned = tipOrigin + turn * (farEnd - tipOrigin);
        QVERIFY((farEndTurned - Eigen::Vector3d(1.0, 0.0, 0.9)).norm() < 1e-12);
        const Eigen::Vector3d nearEnd(0.05, 0.0, 0.0); // Root's alone: it stays

        QImage image = session.viewport->grabFramebuffer();
        QVERIFY2(isMesh(session.colourAt(image, farEnd)), qPrintable(session.colourAt(image, farEnd).name()));
        QVERIFY2(!isMesh(session.colourAt(image, farEndTurned)), qPrintable(session.colourAt(image, farEndTurned).name()));
        QVERIFY(isMesh(session.colourAt(image, nearEnd)));
        QVERIFY(isMesh(session.colourAt(image, kBoxPosition)));
        const QColor boxBefore = session.colourAt(image, kBoxPosition);

        document.push(new model::SetKeyframeOrientationCommand(document, kTip, 0, turn));
        // The changed track's motion is built off the UI thread: frames until the drawn one has it.
        QTRY_VERIFY_WITH_TIMEOUT(session.drawsMeshAt(farEndTurned), 30'000);
        image = session.viewport->grabFramebuffer();
        QVERIFY2(!isMesh(session.colourAt(image, farEnd)), qPrintable(session.colourAt(image, farEnd).name()));
        QVERIFY2(isMesh(session.colourAt(image, farEndTurned)), qPrintable(session.colourAt(image, farEndTurned).name()));
        QVERIFY(isMesh(session.colourAt(image, nearEnd)));
        QCOMPARE(session.colourAt(image, kBoxPosition), boxBefore);
        QCOMPARE(document.object(kBox)->track.keys[0].pose.position, kBoxPosition);

        // A click hits the bar where it is drawn: on its turned end, not where the end was.
        QTest::mouseClick(session.viewport, Qt::LeftButton, Qt::NoModifier, session.onScreen(kBoxPosition).toPoint());
        QCOMPARE(session.window.selection().object(), kBox);
        QTest::mouseClick(session.viewport, Qt::LeftButton, Qt::NoModifier, session.onScreen(farEnd).toPoint());
        QCOMPARE(session.window.selection().object(), kBox); // empty space keeps the selection
        QTest::mouseClick(session.viewport, Qt::LeftButton, Qt::NoModifier, session.onScreen(farEndTurned).toPoint());
        QCOMPARE(session.window.selection().object(), kBar);

        // Undone, the bar is back in its bind pose.
        document.undoStack().undo();
        QTRY_VERIFY_WITH_TIMEOUT(session.drawsMeshAt(farEnd), 30'000);
        image = session.viewport->grabFramebuffer();
        QVERIFY(isMesh(session.colourAt(image, farEnd)));
        QVERIFY(!isMesh(session.colourAt(image, farEndTurned)));
    }

    // The cost of skinning, read by hand (never asserted): the wall time per frame of a 31-joint
    // chain's tube of 19,840 vertices drawn skinned and drawn rigid (the same mesh without its skin),
    // in alternating rounds. Skinned frames upload 31 joint matrices and blend four in the shader.
    void measuresTheFrameOfA31JointSkin()
    {
        constexpr int kRings = 310;
        constexpr int kFrames = 30;
        constexpr int kRounds = 2;
        const model::Scene skinned = test::skinnedTube(31, kRings, 0.1, 0.05);
        model::Scene rigid = skinned;
        auto rigidTube = std::make_shared<model::Mesh>(*rigid.objects.back().mesh);
        rigidTube->skin = {};
        rigid.objects.back().mesh = rigidTube;
        double milliseconds[2] = {0, 0};
        for (int round = 0; round < kRounds; ++round)
            for (const int skinning : {1, 0}) {
                Session session(skinning ? skinned : rigid, 31);
                QElapsedTimer clock;
                for (int frame = -10; frame < kFrames; ++frame) {
                    if (frame == 0)
                        clock.start();
                    session.settle();
                }
                milliseconds[skinning] += double(clock.nsecsElapsed()) / 1e6 / (kFrames * kRounds);
            }
        qInfo("31 joints, %d vertices, per frame: skinned %.2f ms, rigid %.2f ms", kRings * 64, milliseconds[1],
              milliseconds[0]);
        QVERIFY(milliseconds[1] > 0 && milliseconds[0] > 0);
    }
};

QTEST_MAIN(TestViewportSkin)
#include "tst_viewport_skin.moc"
