// What drawing costs while a motion capture plays: the main window on a 31-joint capture of 4,500
// frames at 120 Hz (the one gyre-bench imports), a bone of it selected, the docks as the window lays
// them out. Prints the time to repaint the timeline and the sphere view for a new current time, and
// the frame rate of playback with every view drawing; tests never assert on time.

#include "app/main_window.h"
#include "app/sketch/sphere_view.h"
#include "app/timeline_widget.h"
#include "app/viewport/viewport.h"
#include "gui_test_support.h"
#include "io/bvh_fixture.h"
#include "io/scene_import.h"
#include "model/commands/import_objects_command.h"
#include "model/commands/set_time_range_command.h"

#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

using namespace gyre;
using namespace gyre::io;

namespace {

constexpr int kJoints = 31;
constexpr int kFrames = 4500;
constexpr double kFrameTime = 1.0 / 120.0;
constexpr std::size_t kSelectedJoint = 15;
constexpr int kMeasuredFrames = 60;
constexpr qint64 kPlayingMilliseconds = 4000;

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

} // namespace

class TestViewDrawing : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }

    void measuresPlayingAMotionCapture()
    {
        QTemporaryDir folder;
        const QString path = folder.filePath(QStringLiteral("capture.bvh"));
        QFile file(path);
        const QByteArray bvh = test::bvhChain(kJoints, kFrames, kFrameTime);
        QVERIFY(file.open(QIODevice::WriteOnly) && file.write(bvh) == bvh.size());
        file.close();
        const SceneImport imported = importScene(path);
        QVERIFY(imported.scene.objects.size() > kSelectedJoint);

        app::MainWindow window;
        window.resize(1500, 950);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.playback().pause();
        model::Document& document = window.document();
        // As the app adds an import to a new document: the objects and the capture's range, one step.
        auto* step = new QUndoCommand(QStringLiteral("Import"));
        auto* objects = new model::ImportObjectsCommand(document, imported.scene.objects, step);
        new model::SetTimeRangeCommand(
            document, {imported.scene.fps, imported.scene.startTime, imported.scene.endTime}, step);
        document.undoStack().push(step);

        auto* sphere = window.findChild<app::SphereView*>();
        auto* timeline = window.findChild<app::TimelineWidget*>();
        auto* viewport = window.findChild<app::Viewport*>();
        QVERIFY(sphere != nullptr && timeline != nullptr && viewport != nullptr);
        QVERIFY(sphere->isVisible() && timeline->isVisible());
        QSignalSpy curves(sphere, &app::SphereView::curvesUpdated);
        const model::ObjectId bone = objects->ids().at(kSelectedJoint);
        window.selection().selectObject(bone);
        QVERIFY(curves.wait(30000));
        const std::size_t keys = document.object(bone)->track.keys.size();
        document.setCurrentTime(document.scene().startTime);
        QCoreApplication::processEvents();

        // A new current time each frame, one frame of the capture apart, and the view drawn: alone (into
        // an image, or the sphere's framebuffer read back), and repainted on screen, which adds the
        // window's composition of its OpenGL views.
        auto medianTime = [&](const std::function<void()>& draw) {
            std::vector<double> milliseconds;
            for (int frame = 1; frame <= kMeasuredFrames; ++frame) {
                document.setCurrentTime(document.scene().startTime + frame * kFrameTime);
                QElapsedTimer clock;
                clock.start();
                draw();
                milliseconds.push_back(static_cast<double>(clock.nsecsElapsed()) / 1e6);
            }
            return median(milliseconds);
        };
        QImage timelineImage(timeline->size(), QImage::Format_ARGB32_Premultiplied);
        const double timelinePaintMs = medianTime([&] { timeline->render(&timelineImage); });
        const double timelineRepaintMs = medianTime([&] { timeline->repaint(); });
        const double spherePaintMs = medianTime([&] { sphere->grabFramebuffer(); });
        const double sphereRepaintMs = medianTime([&] { sphere->repaint(); });

        // Playback with every view following, counted in the current time's changes a second and in
        // the viewport's own readout in the status bar.
        double viewportFps = 0.0;
        connect(viewport, &app::Viewport::frameStatsChanged, this, [&](double fps, double, double) { viewportFps = fps; });
        QSignalSpy frames(&document, &model::Document::currentTimeChanged);
        window.playback().play();
        QElapsedTimer clock;
        clock.start();
        while (clock.elapsed() < kPlayingMilliseconds)
            QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
        const double seconds = static_cast<double>(clock.nsecsElapsed()) / 1e9;
        window.playback().pause();

        std::printf("capture: %d joints x %d frames, %zu objects, the selected one has %zu keys\n", kJoints, kFrames,
                    imported.scene.objects.size(), keys);
        std::printf("a new current time, median of %d: timeline (%dx%d) drawn %.2f ms, repainted %.2f ms; "
                    "sphere view (%dx%d) drawn %.2f ms, repainted %.2f ms\n",
                    kMeasuredFrames, timeline->width(), timeline->height(), timelinePaintMs, timelineRepaintMs,
                    sphere->width(), sphere->height(), spherePaintMs, sphereRepaintMs);
        std::printf("playing: %.1f current times a second over %.1f s; the viewport's readout %.1f frames a second\n",
                    static_cast<double>(frames.count()) / seconds, seconds, viewportFps);
        QVERIFY(frames.count() > 0);
    }
};

QTEST_MAIN(TestViewDrawing)
#include "tst_view_drawing.moc"
