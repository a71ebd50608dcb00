// The main window driven as the artist drives it: files through the File menu and by dropping them,
// the title and its unsaved-changes mark, asking before unsaved work is lost, the keyframe actions,
// scene import and export off the UI thread, and the layout kept between sessions.

#include "app/main_window.h"
#include "app/sketch/magnitude_plot.h"
#include "app/sketch/sphere_view.h"
#include "built_scene_worker.h"
#include "gui_test_support.h"
#include "io/bvh_fixture.h"
#include "io/scene_export.h"
#include "model/commands/set_keyframe_position_command.h"
#include "model/project_file.h"
#include "model/track_evaluation.h"

#include <QAbstractButton>
#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QUndoStack>
#include <QTemporaryDir>
#include <QTest>
#include <QUrl>

using namespace gyre;
using namespace gyre::io;

namespace {

QAction* action(const app::MainWindow& window, const char* name)
{
    auto* found = window.findChild<QAction*>(QLatin1String(name));
    if (found == nullptr)
        qFatal("No action %s", name);
    return found;
}

model::ObjectId firstObject(const app::MainWindow& window)
{
    return window.document().scene().objects.front().id;
}

Eigen::Vector3d keyPosition(const app::MainWindow& window, std::size_t key)
{
    return window.document().scene().objects.front().track.keys.at(key).pose.position;
}

void moveFirstKey(app::MainWindow& window, const Eigen::Vector3d& position)
{
    window.document().undoStack().push(
        new model::SetKeyframePositionCommand(window.document(), firstObject(window), 0, position));
}

// A file named `name` in `folder` holding `bytes`; its path.
QString writeFile(const QTemporaryDir& folder, const QString& name, const QByteArray& bytes)
{
    const QString path = folder.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size())
        qFatal("Cannot write the fixture %s", qPrintable(path));
    return path;
}

// The window after it opened the bundled sample, shown.
struct SampleWindow {
    SampleWindow()
    {
        window.show();
        window.openBundledSample();
        window.playback().pause();
    }
    app::MainWindow window;
};

} // namespace

class TestMainWindow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        test::useTestSettings();
        test::useBuiltSceneWorker();
    }

    void startsOnTheBundledSampleUntitledAndUnmodified()
    {
        SampleWindow sample;
        const app::MainWindow& window = sample.window;
        QCOMPARE(window.document().scene().objects.size(), std::size_t{1});
        QCOMPARE(window.document().scene().objects.front().track.keys.size(), std::size_t{6});
        QVERIFY(window.document().filePath().isEmpty());
        QVERIFY(!window.document().isModified());
        QVERIFY(window.windowTitle().startsWith(QStringLiteral("Untitled")));
        QVERIFY(!window.isWindowModified());
        QCOMPARE(window.selection().object(), firstObject(window));
    }

    void opensTheOtherSampleFromTheFileMenuAfterAsking()
    {
        SampleWindow sample;
        moveFirstKey(sample.window, Eigen::Vector3d(1, 2, 3));
        QString question;
        test::answerMessageBox(QMessageBox::Discard, &question);
        action(sample.window, "spinning-top")->trigger();
        QVERIFY(!question.isEmpty());
        const model::Document& document = sample.window.document();
        QCOMPARE(document.scene().objects.size(), std::size_t{1});
        QCOMPARE(document.scene().objects.front().name, QStringLiteral("Spinning top"));
        QCOMPARE(document.scene().objects.front().track.keys.size(), std::size_t{85});
        QVERIFY(document.filePath().isEmpty());
        QVERIFY(!document.isModified());
        QCOMPARE(sample.window.selection().key(), std::optional<std::size_t>(0));
    }

    // Every project bundled in :/samples has its entry in File ▸ Open Sample, named after the file,
    // and the entry opens that project untitled.
    void everyBundledSampleHasAMenuEntryThatOpensIt()
    {
        SampleWindow sample;
        const QStringList files = QDir(QStringLiteral(":/samples")).entryList({QStringLiteral("*.gyre")});
        QCOMPARE(files.size(), 12);
        for (const QString& file : files) {
            const QString resourcePath = QStringLiteral(":/samples/") + file;
            action(sample.window, qPrintable(QFileInfo(file).baseName()))->trigger();
            const model::Document& document = sample.window.document();
            const model::Scene bundled = model::readProject(resourcePath);
            QCOMPARE(document.scene().objects.size(), bundled.objects.size());
            QCOMPARE(document.scene().objects.front().name, bundled.objects.front().name);
            QCOMPARE(document.scene().objects.front().track.keys.size(), bundled.objects.front().track.keys.size());
            QVERIFY(document.filePath().isEmpty());
            QVERIFY(!document.isModified());
        }
    }

    // The sketch panels live in the window: the spinning top opens on its fitted motion, and its sketch
    // fits again from the Fit dock's button, with progress in the status bar, as one undo step.
    void fitsTheSpinningTopSampleFromTheFitDock()
    {
        app::MainWindow window;
        window.show();
        // The sphere and the speed plot sample the new scene's curves on their threads; the click
        // comes once they have shown them.
        QSignalSpy sphereCurves(window.findChild<app::SphereView*>(), &app::SphereView::curvesUpdated);
        QSignalSpy speedCurves(window.findChild<app::MagnitudePlot*>(), &app::MagnitudePlot::curvesUpdated);
        window.openSample(QStringLiteral(":/samples/spinning-top.gyre"));
        window.playback().pause();
        for (const char* dock : {"sphereDock", "magnitudeDock", "fitDock"})
            QVERIFY(window.findChild<QDockWidget*>(QLatin1String(dock)) != nullptr);
        auto* fit = window.findChild<QAbstractButton*>(QStringLiteral("fitButton"));
        QVERIFY(fit != nullptr && fit->isEnabled());
        const model::ObjectId top = firstObject(window);
        const model::MotionTrack before = window.document().object(top)->track;
        QVERIFY(!before.sketch.fittedCurve.empty());

        for (QSignalSpy* curves : {&sphereCurves, &speedCurves})
            QVERIFY(curves->count() > 0 || curves->wait(10'000));
        QSignalSpy applied(&window.document().undoStack(), &QUndoStack::indexChanged);
        QElapsedTimer clock;
        clock.start();
        fit->click();
        QVERIFY(applied.wait(60000));
        qInfo("Fit of the spinning-top sample, from the click to the applied step: %lld ms (%s)",
              static_cast<long long>(clock.elapsed()), qPrintable(window.statusBar()->currentMessage()));
        QCOMPARE(window.document().undoStack().count(), 1);
        QCOMPARE(window.document().undoStack().text(0), QStringLiteral("Apply angular velocity fit"));
        const model::MotionTrack& after = window.document().object(top)->track;
        QVERIFY(!after.sketch.fittedCurve.empty());
        for (std::size_t i = 0; i < before.keys.size(); ++i)
            if (before.keys[i].constrained)
                QVERIFY(after.keys[i].pose.orientation.coeffs() == before.keys[i].pose.orientation.coeffs());
        window.document().undoStack().undo();
        const model::MotionTrack& undone = window.document().object(top)->track;
        QCOMPARE(undone.sketch.fittedCurve.size(), before.sketch.fittedCurve.size());
        for (std::size_t i = 0; i < before.sketch.fittedCurve.size(); ++i)
            QVERIFY(undone.sketch.fittedCurve[i].value.coeffs() == before.sketch.fittedCurve[i].value.coeffs());
    }

    void anEditMarksTheTitleAndUndoClearsTheMark()
    {
        SampleWindow sample;
        moveFirstKey(sample.window, Eigen::Vector3d(1, 2, 3));
        QVERIFY(sample.window.isWindowModified());
        action(sample.window, "actionUndo")->trigger();
        QVERIFY(!sample.window.isWindowModified());
        QCOMPARE(keyPosition(sample.window, 0), Eigen::Vector3d::Zero().eval());
        action(sample.window, "actionRedo")->trigger();
        QCOMPARE(keyPosition(sample.window, 0), Eigen::Vector3d(1, 2, 3));
    }

    void savesThroughSaveAsAndReopensThroughTheFileMenu()
    {
        QTemporaryDir folder;
        const QString path = folder.filePath(QStringLiteral("moved.gyre"));
        {
            SampleWindow sample;
            moveFirstKey(sample.window, Eigen::Vector3d(0.25, -1, 2));
            test::answerFileDialog(path);
            action(sample.window, "actionSaveAs")->trigger();
            QCOMPARE(sample.window.document().filePath(), path);
            QVERIFY(!sample.window.isWindowModified());
            QVERIFY(sample.window.windowTitle().startsWith(QStringLiteral("moved.gyre")));
        }
        app::MainWindow window;
        window.show();
        test::answerFileDialog(path);
        action(window, "actionOpen")->trigger();
        QCOMPARE(window.document().filePath(), path);
        QCOMPARE(keyPosition(window, 0), Eigen::Vector3d(0.25, -1, 2));
        QVERIFY(window.windowTitle().startsWith(QStringLiteral("moved.gyre")));
        // It is now the first of the recent files.
        auto* recent = window.findChild<QMenu*>(QStringLiteral("menuOpenRecent"));
        QVERIFY(recent->isEnabled());
        QCOMPARE(recent->actions().front()->statusTip(), QFileInfo(path).absoluteFilePath());
    }

    void closingWithUnsavedWorkAsksAndCancelKeepsTheWindow()
    {
        SampleWindow sample;
        moveFirstKey(sample.window, Eigen::Vector3d(4, 0, 0));
        QString question;
        test::answerMessageBox(QMessageBox::Cancel, &question);
        QVERIFY(!sample.window.close());
        QVERIFY(question.contains(QStringLiteral("unsaved")));
        QVERIFY(sample.window.isVisible());
        QCOMPARE(keyPosition(sample.window, 0), Eigen::Vector3d(4, 0, 0));
        test::answerMessageBox(QMessageBox::Discard);
        QVERIFY(sample.window.close());
    }

    void aBrokenProjectIsReportedByNameAndTheOpenOneStays()
    {
        QTemporaryDir folder;
        const QString path = writeFile(folder, QStringLiteral("broken.gyre"),
                                       "{\"format\": \"gyre-project\", \"version\": 2, \"fps\": \"fast\"}");
        SampleWindow sample;
        QString message;
        test::answerMessageBox(QMessageBox::Ok, &message);
        QVERIFY(!sample.window.openProject(path));
        QVERIFY2(message.contains(QStringLiteral("broken.gyre")), qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("fps")), qPrintable(message));
        QCOMPARE(sample.window.document().scene().objects.size(), std::size_t{1});
        QVERIFY(sample.window.document().filePath().isEmpty());
    }

    void droppingAProjectOpensIt()
    {
        QTemporaryDir folder;
        const QString path = folder.filePath(QStringLiteral("dropped.gyre"));
        {
            SampleWindow sample;
            moveFirstKey(sample.window, Eigen::Vector3d(0, 0, 9));
            sample.window.document().save(path);
        }
        app::MainWindow window;
        window.show();
        QMimeData data;
        data.setUrls({QUrl::fromLocalFile(path)});
        QDragEnterEvent enter(QPoint(200, 200), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&window, &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(QPointF(200, 200), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&window, &drop);
        QCOMPARE(window.document().filePath(), path);
        QCOMPARE(keyPosition(window, 0), Eigen::Vector3d(0, 0, 9));
    }

    void importsASceneOffTheUiThreadAsOneUndoStep()
    {
        QTemporaryDir folder;
        const QString path = folder.filePath(QStringLiteral("exported.gltf"));
        SampleWindow sample;
        app::MainWindow& window = sample.window;
        QSignalSpy exported(&window.sceneFiles().jobs(), &jobs::SceneFileJobs::exported);
        window.sceneFiles().exportScene(path);
        QVERIFY(window.sceneFiles().jobs().isBusy());
        QTRY_COMPARE(exported.count(), 1);
        QVERIFY(QFile::exists(path));

        const int steps = window.document().undoStack().count();
        QSignalSpy imported(&window.sceneFiles().jobs(), &jobs::SceneFileJobs::imported);
        window.sceneFiles().importScene(path);
        QTRY_COMPARE(imported.count(), 1);
        QCOMPARE(window.document().undoStack().count(), steps + 1);
        const auto& objects = window.document().scene().objects;
        QCOMPARE(objects.size(), std::size_t{2});
        // The baked motion plays the sample's: at a key time the imported object has the pose the
        // sample's subdivided motion has then (Jarek's scheme approximates its control poses).
        const double keyTime = objects.front().track.keys.at(2).time;
        const Pose original = model::TrackMotion(objects.front().track).at(keyTime);
        const auto& copiedKeys = objects.back().track.keys;
        const auto copied = std::find_if(copiedKeys.begin(), copiedKeys.end(),
                                         [&](const model::Keyframe& key) { return key.time == keyTime; });
        QVERIFY(copied != copiedKeys.end());
        QVERIFY((copied->pose.position - original.position).norm() < 1e-5);
        QVERIFY(copied->pose.orientation.angularDistance(original.orientation) < 1e-5);
        QCOMPARE(window.selection().object(), objects.back().id);
        window.document().undoStack().undo();
        QCOMPARE(window.document().scene().objects.size(), std::size_t{1});
    }

    void aCancelledImportChangesNothing()
    {
        // A motion capture large enough that its import is still running when the click arrives,
        // however the machine is loaded: seconds under the sanitizers, a third of one in Release.
        QTemporaryDir folder;
        const QString path = folder.filePath(QStringLiteral("long.bvh"));
        QFile file(path);
        const QByteArray bvh = test::bvhChain(31, 4500, 1.0 / 120.0);
        QVERIFY(file.open(QIODevice::WriteOnly) && file.write(bvh) == bvh.size());
        file.close();
        SampleWindow sample;
        app::MainWindow& window = sample.window;
        QSignalSpy cancelled(&window.sceneFiles().jobs(), &jobs::SceneFileJobs::cancelled);
        window.sceneFiles().importScene(path);
        auto* cancel = window.findChild<QAbstractButton*>(QStringLiteral("cancelSceneJob"));
        QVERIFY(cancel->isVisible());
        // The click goes to whatever is at the button's place in the window: let the status bar lay
        // the button out first.
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
        QSignalSpy clicked(cancel, &QAbstractButton::clicked);
        QSignalSpy imported(&window.sceneFiles().jobs(), &jobs::SceneFileJobs::imported);
        QTest::mouseClick(cancel, Qt::LeftButton);
        QCOMPARE(clicked.count(), 1);
        // Cancelling stops the worker process; a loaded machine may still take a while to answer.
        QTRY_COMPARE_WITH_TIMEOUT(cancelled.count() + imported.count(), 1, 30000);
        QCOMPARE(cancelled.count(), 1);
        QVERIFY(!cancel->isVisible());
        QCOMPARE(window.document().scene().objects.size(), std::size_t{1});
        QCOMPARE(window.document().undoStack().count(), 0);
    }

    void anUnreadableSceneIsReportedByName()
    {
        QTemporaryDir folder;
        const QString path = writeFile(folder, QStringLiteral("garbage.fbx"), "this is not an FBX file\n");
        SampleWindow sample;
        QSignalSpy failed(&sample.window.sceneFiles().jobs(), &jobs::SceneFileJobs::failed);
        QString message;
        test::answerMessageBox(QMessageBox::Ok, &message);
        sample.window.sceneFiles().importScene(path);
        QTRY_COMPARE(failed.count(), 1);
        QTRY_VERIFY2(message.contains(QStringLiteral("garbage.fbx")), qPrintable(message));
        QCOMPARE(sample.window.document().scene().objects.size(), std::size_t{1});
    }

    void keyframeActionsAddDeleteAndConstrainTheSelectedKey()
    {
        SampleWindow sample;
        app::MainWindow& window = sample.window;
        window.document().setCurrentTime(2.5);
        action(window, "actionAddKeyframe")->trigger();
        const auto& keys = window.document().scene().objects.front().track.keys;
        QCOMPARE(keys.size(), std::size_t{7});
        QCOMPARE(window.selection().key(), std::optional<std::size_t>(3));
        QCOMPARE(keys[3].time, 2.5);
        QCOMPARE(window.document().undoStack().count(), 1);
        QCOMPARE(window.document().undoStack().undoText(), QStringLiteral("Insert Keyframes"));
        // Keyed again at a time it has a key at, the object keeps that key: no step.
        const model::Keyframe keyed = keys[3];
        action(window, "actionAddKeyframe")->trigger();
        QCOMPARE(keys.size(), std::size_t{7});
        QCOMPARE(keys[3].pose.orientation.coeffs(), keyed.pose.orientation.coeffs());
        QCOMPARE(window.document().undoStack().count(), 1);

        QAction* constrain = action(window, "actionToggleConstraint");
        QVERIFY(constrain->isChecked());
        constrain->trigger();
        QVERIFY(!keys[3].constrained);
        QVERIFY(!constrain->isChecked());

        action(window, "actionDeleteKeyframe")->trigger();
        QCOMPARE(window.document().scene().objects.front().track.keys.size(), std::size_t{6});
        QVERIFY(!action(window, "actionDeleteKeyframe")->isEnabled());
        QCOMPARE(window.document().undoStack().count(), 3);
    }

    void theDockLayoutIsKeptBetweenSessions()
    {
        {
            app::MainWindow window;
            window.show();
            window.findChild<QDockWidget*>(QStringLiteral("screwBenderDock"))->hide();
            QVERIFY(window.close());
        }
        app::MainWindow window;
        window.show();
        QVERIFY(!window.findChild<QDockWidget*>(QStringLiteral("screwBenderDock"))->isVisible());
        QVERIFY(window.findChild<QDockWidget*>(QStringLiteral("inspectorDock"))->isVisible());
        window.findChild<QDockWidget*>(QStringLiteral("screwBenderDock"))->show();
        QVERIFY(window.close());
    }

    // Whoever listens to the document while the window closes reads a whole document: under the
    // sanitizer build a read of freed memory fails the test.
    void closingTheWindowWithListenersAttachedReadsNothingFreed()
    {
        QTemporaryDir folder;
        auto sample = std::make_unique<SampleWindow>();
        app::MainWindow& window = sample->window;
        window.document().save(folder.filePath(QStringLiteral("listened.gyre")));
        moveFirstKey(window, Eigen::Vector3d(1.0, 2.0, 3.0));
        const model::Document* document = &window.document();
        qsizetype pathLengths = 0;
        // No context object: the connection lives as long as the undo stack.
        QObject::connect(&window.document().undoStack(), &QUndoStack::indexChanged,
                         [document, &pathLengths] { pathLengths += document->filePath().size(); });
        QObject::connect(&window.document().undoStack(), &QUndoStack::cleanChanged,
                         [document, &pathLengths] { pathLengths += document->filePath().size(); });
        window.document().undoStack().undo();
        QVERIFY(pathLengths > 0);
        test::answerMessageBox(QMessageBox::Discard);
        QVERIFY(window.close());
        sample.reset();
    }

    void aFailedAutosaveShowsInTheStatusBar()
    {
        const QString directory =
            QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) + QStringLiteral("/autosave");
        QVERIFY(QDir(directory).removeRecursively());
        SampleWindow sample;
        app::MainWindow& window = sample.window;
        QVERIFY(!window.recoverAndStartAutosave(std::chrono::milliseconds(20)));
        // The folder of the copies turns into a file: no copy can be written there.
        QVERIFY(QDir(directory).removeRecursively());
        QFile blocker(directory);
        QVERIFY(blocker.open(QIODevice::WriteOnly));
        blocker.close();
        moveFirstKey(window, Eigen::Vector3d(0.5, 0.0, 0.0));
        QTRY_VERIFY(window.statusBar()->currentMessage().startsWith(QStringLiteral("Autosave failed")));
        QVERIFY(window.statusBar()->currentMessage().contains(QStringLiteral("autosave")));
        QVERIFY(QFile::remove(directory));
        test::answerMessageBox(QMessageBox::Discard);
        QVERIFY(window.close());
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_main_window.moc"
