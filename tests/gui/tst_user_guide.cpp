// The user guide (docs/user-guide.md) held to the window it describes. Its tables of keyboard
// shortcuts list exactly the shortcuts of the window's actions and buttons, plus keys that a panel
// handles itself; and every state of a sample that the guide pictures is reached the way the guide
// tells (the sample from File ▸ Open Sample, Fit pressed, a control pose dragged, ...) and shows what
// the guide says of it.
//
// With GYRE_GUIDE_IMAGES set to a folder, each of those states is also saved there as the guide's
// picture, named as the guide names it: scripts/user-guide-screenshots.sh regenerates them so.

#include "app/graph_editor/graph_editor_panel.h"
#include "app/main_window.h"
#include "app/outliner/outliner_panel.h"
#include "built_scene_worker.h"
#include "app/sketch/magnitude_plot.h"
#include "app/sketch/pattern_pad.h"
#include "app/sketch/sphere_view.h"
#include "app/smoothness_panel.h"
#include "app/timeline_widget.h"
#include "app/viewport/viewport.h"
#include "gui_test_support.h"
#include "inspected_window.h"
#include "model/project_file.h"
#include "model/skinning.h"
#include "skinned_tube.h"

#include <QAbstractButton>
#include <QAction>
#include <QCheckBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QMenuBar>
#include <QMetaEnum>
#include <QPainter>
#include <QRegularExpression>
#include <QSet>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTreeView>
#include <QStatusBar>
#include <QTest>
#include <QToolBar>
#include <QUndoStack>
#include <qcustomplot.h>

#include <algorithm>
#include <limits>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <utility>
#include <vector>

using namespace gyre;

namespace {

constexpr int kFitTimeoutMilliseconds = 60'000;
// The middle of the pendulum sample's bob, on its local z axis.
constexpr double kPendulumBob = -1.1;

QString readText(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        qFatal("Cannot read %s", qPrintable(path));
    return QString::fromUtf8(file.readAll());
}

QString guideText()
{
    return readText(QStringLiteral(GYRE_USER_GUIDE));
}

QString portable(const QKeySequence& keys)
{
    return keys.toString(QKeySequence::PortableText);
}

// The keys in the first cell of every table row under the guide's "Keyboard shortcuts" heading, each
// `quoted`, in Qt's portable text.
QStringList guideShortcuts()
{
    const QString guide = guideText();
    const qsizetype start = guide.indexOf(QStringLiteral("\n## Keyboard shortcuts\n"));
    if (start < 0)
        qFatal("The guide has no Keyboard shortcuts section");
    const qsizetype end = guide.indexOf(QStringLiteral("\n## "), start + 1);
    const QStringList lines = guide.mid(start, end - start).split(QLatin1Char('\n'));
    static const QRegularExpression quoted(QStringLiteral("`([^`]+)`"));
    QStringList keys;
    for (const QString& line : lines) {
        if (!line.startsWith(QLatin1Char('|')))
            continue;
        const QString firstCell = line.section(QLatin1Char('|'), 1, 1);
        for (const QRegularExpressionMatch& match : quoted.globalMatch(firstCell))
            keys.append(portable(QKeySequence(match.captured(1))));
    }
    return keys;
}

// Whether the sequence is a menu or button mnemonic (Alt and the underlined letter) rather than a
// shortcut: Qt gives every "&Name" button one.
bool isMnemonic(const QKeySequence& keys)
{
    return keys.count() == 1 && keys[0].keyboardModifiers() == Qt::AltModifier;
}

// Every shortcut of the window's actions and buttons, in portable text.
QSet<QString> windowShortcuts(const QMainWindow& window)
{
    QSet<QString> shortcuts;
    for (const QAction* action : window.findChildren<QAction*>())
        for (const QKeySequence& keys : action->shortcuts())
            shortcuts.insert(portable(keys));
    for (const QAbstractButton* button : window.findChildren<QAbstractButton*>())
        if (!button->shortcut().isEmpty() && !isMnemonic(button->shortcut()))
            shortcuts.insert(portable(button->shortcut()));
    return shortcuts;
}

// Whether a widget of the app handles the key itself in a key press handler: `Qt::Key_End` in its source.
bool appSourceHandlesKey(const QKeySequence& keys)
{
    if (keys.count() != 1 || keys[0].keyboardModifiers() != Qt::NoModifier)
        return false;
    const char* name = QMetaEnum::fromType<Qt::Key>().valueToKey(keys[0].key());
    if (name == nullptr)
        return false;
    const QRegularExpression handled(QStringLiteral("case Qt::%1:|key\\(\\) == Qt::%1\\b").arg(QLatin1String(name)));
    const QDir sources(QStringLiteral(GYRE_APP_SOURCES));
    for (const QString& folder : {QStringLiteral("."), QStringLiteral("outliner"), QStringLiteral("sketch"), QStringLiteral("viewport")}) {
        const QDir directory(sources.filePath(folder));
        for (const QString& file : directory.entryList({QStringLiteral("*.cpp")}, QDir::Files))
            if (readText(directory.filePath(file)).contains(handled))
                return true;
    }
    return false;
}

// A numbered badge over `widget`'s top edge at `offset` from its top-left corner, as the guide's
// list of the window's parts numbers them.
void drawBadge(QPainter& painter, const QWidget& window, const QWidget& widget, QPoint offset, int number)
{
    constexpr int kRadius = 11;
    const QPoint centre = widget.mapTo(&window, offset);
    painter.setPen(QPen(Qt::white, 2));
    painter.setBrush(QColor(215, 45, 35));
    painter.drawEllipse(centre, kRadius, kRadius);
    QFont font = painter.font();
    font.setBold(true);
    font.setPixelSize(14);
    painter.setFont(font);
    painter.drawText(QRect(centre - QPoint(kRadius, kRadius), QSize(2 * kRadius, 2 * kRadius)), Qt::AlignCenter,
                     QString::number(number));
}

// A motion capture as a BVH file: a human skeleton of named joints (bones a few units long, so that
// each joint's block stands apart), every joint swinging on its own for four seconds at 30 frames a second.
QByteArray humanBvh()
{
    static const test::BvhJoint joints[] = {
        {"Hips", 0, 0, 0, 0},          {"Spine", 1, 0, 2, 0},        {"Chest", 2, 0, 2, 0},
        {"Neck", 3, 0, 2, 0},          {"Head", 4, 0, 1.5, 0},       {"LeftShoulder", 3, 1.5, 1.5, 0},
        {"LeftArm", 4, 2, 0, 0},       {"LeftForeArm", 5, 2.5, 0, 0}, {"LeftHand", 6, 2, 0, 0},
        {"RightShoulder", 3, -1.5, 1.5, 0}, {"RightArm", 4, -2, 0, 0}, {"RightForeArm", 5, -2.5, 0, 0},
        {"RightHand", 6, -2, 0, 0},    {"LeftUpLeg", 1, 1.2, -1, 0},  {"LeftLeg", 2, 0, -4, 0},
        {"LeftFoot", 3, 0, -4, 0},     {"RightUpLeg", 1, -1.2, -1, 0}, {"RightLeg", 2, 0, -4, 0},
        {"RightFoot", 3, 0, -4, 0},
    };
    return test::bvhFile(
        joints, 1.0, 120, [](int frame) { return Eigen::Vector3d(0.05 * frame, 10.0, 0.0); },
        [](int frame, std::size_t joint, int axis) {
            return 25.0 * std::sin(0.1 * frame * (axis + 1) + 0.9 * double(joint) + axis);
        });
}

// The main window as the guide shows it: its first-start layout (test settings are empty), shown.
class GuideWindow {
public:
    GuideWindow()
    {
        window_.show();
        if (!QTest::qWaitForWindowExposed(&window_))
            qFatal("The main window was not shown");
    }

    app::MainWindow& window() { return window_; }
    model::ObjectId object() const { return window_.selection().object(); }
    const model::MotionTrack& track() const { return window_.document().object(object())->track; }

    template <class Widget>
    Widget* child(const char* name = nullptr) const
    {
        auto* widget = name == nullptr ? window_.findChild<Widget*>() : window_.findChild<Widget*>(QLatin1String(name));
        if (widget == nullptr)
            qFatal("The main window has no %s", name == nullptr ? Widget::staticMetaObject.className() : name);
        return widget;
    }

    // Opens the sample from File ▸ Open Sample, by its menu entry, and pauses it at `time`.
    void openSample(const char* entry, double time)
    {
        child<QAction>(entry)->trigger();
        window_.playback().pause();
        window_.document().setCurrentTime(time);
    }

    void raiseDock(const char* dock) { child<QDockWidget>(dock)->raise(); }

    // Presses Remove fit on the Fit tab: one undo step that takes the track back to its keys.
    void removeFitFromTheFitTab()
    {
        raiseDock("fitDock");
        QUndoStack& stack = window_.document().undoStack();
        const int stepsBefore = stack.count();
        child<QAbstractButton>("removeFitButton")->click();
        QCOMPARE(stack.count(), stepsBefore + 1);
        QVERIFY(track().sketch.fittedCurve.empty());
    }

    // Presses Fit on the Fit tab and waits for the fit's undo step; the status bar's message after it.
    QString fitFromTheFitTab()
    {
        raiseDock("fitDock");
        QUndoStack& stack = window_.document().undoStack();
        const int stepsBefore = stack.count();
        child<QAbstractButton>("fitButton")->click();
        if (!QTest::qWaitFor([&] { return stack.count() == stepsBefore + 1; }, kFitTimeoutMilliseconds))
            qFatal("The fit did not finish");
        if (stack.text(stepsBefore) != QLatin1String("Apply angular velocity fit"))
            qFatal("The fit's undo step is %s", qPrintable(stack.text(stepsBefore)));
        return window_.statusBar()->currentMessage();
    }

    // Waits until the sphere, the speed plot and the smoothness plots, those of them on screen, show the
    // track as it is now (each has a recompute pending after a change of the track or the selection; one
    // off screen, as the smoothness plots are behind the inspector, does nothing until it is shown), and
    // the viewport has drawn it.
    void settle()
    {
        std::vector<const QObject*> onScreen;
        for (const QWidget* view : {static_cast<const QWidget*>(child<app::SphereView>()),
                                    static_cast<const QWidget*>(child<app::MagnitudePlot>()),
                                    static_cast<const QWidget*>(child<app::SmoothnessPanel>())})
            if (view->isVisible() && !view->visibleRegion().isEmpty())
                onScreen.push_back(view);
        waitForCurves(onScreen);
        redraw();
    }

    // Waits until the viewport has drawn the window as it is.
    void redraw()
    {
        auto* viewport = child<app::Viewport>();
        const std::uint64_t framesBefore = viewport->framesDrawn();
        viewport->update();
        if (!QTest::qWaitFor([&] { return viewport->framesDrawn() > framesBefore; }))
            qFatal("The viewport did not draw");
    }

    // Waits until each of `views` has sent curvesUpdated.
    static void waitForCurves(const std::vector<const QObject*>& views)
    {
        std::vector<std::unique_ptr<QSignalSpy>> updates;
        for (const QObject* view : views)
            updates.push_back(std::make_unique<QSignalSpy>(view, SIGNAL(curvesUpdated())));
        for (const auto& updated : updates)
            if (updated->count() == 0 && !updated->wait(10'000))
                qFatal("A view did not update its curves");
    }

    // The window as it is on screen, saved as the guide's picture `name` when GYRE_GUIDE_IMAGES names
    // a folder; `annotate` may draw on it first. Fails the test if the guide does not show `name`.
    template <class Annotate>
    void picture(const QString& name, Annotate annotate)
    {
        QVERIFY2(guideText().contains(QStringLiteral("(images/") + name + QLatin1Char(')')),
                 qPrintable(QStringLiteral("The guide does not show ") + name));
        const QString folder = qEnvironmentVariable("GYRE_GUIDE_IMAGES");
        if (folder.isEmpty())
            return;
        QImage image = window_.grab().toImage();
        annotate(image);
        QVERIFY2(image.save(QDir(folder).filePath(name)), qPrintable(QDir(folder).filePath(name)));
    }
    void picture(const QString& name)
    {
        picture(name, [](QImage&) {});
    }

private:
    app::MainWindow window_;
};

QCPGraph* smoothnessGraph(const GuideWindow& guide, app::SmoothnessPanel::Quantity quantity)
{
    return guide.child<app::SmoothnessPanel>()->graph(quantity, app::SmoothnessPanel::Component::Magnitude);
}

} // namespace

class TestUserGuide : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }

    // Every key the table lists does something in the window, and every shortcut of the window is listed.
    void shortcutTableListsExactlyTheWindowsShortcuts()
    {
        GuideWindow guide;
        const QSet<QString> window = windowShortcuts(guide.window());
        QVERIFY(window.contains(QStringLiteral("Ctrl+F"))); // a button's, on the Fit tab
        QVERIFY(window.contains(QStringLiteral("R")));      // the sphere's, while it has the focus
        const QStringList listed = guideShortcuts();
        for (const QString& keys : listed)
            QVERIFY2(window.contains(keys) || appSourceHandlesKey(QKeySequence(keys)),
                     qPrintable(QStringLiteral("The guide lists %1, which nothing in the window handles").arg(keys)));
        for (const QString& keys : window)
            QVERIFY2(listed.contains(keys), qPrintable(QStringLiteral("The guide does not list %1").arg(keys)));
    }

    // End, listed for the focused timeline, goes to the scene's last frame.
    void endOnTheFocusedTimelineGoesToTheLastFrame()
    {
        GuideWindow guide;
        guide.openSample("l-cycle", 1.0);
        guide.window().activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&guide.window()));
        auto* timeline = guide.child<app::TimelineWidget>();
        timeline->setFocus();
        QTest::keyClick(timeline, Qt::Key_End);
        const model::Scene& scene = guide.window().document().scene();
        QCOMPARE(scene.currentTime, scene.endTime);
    }

    // First launch: the L-shaped cycle, playing, its first key selected; the parts of the window numbered.
    void firstLaunchOpensTheLCycleWithItsFirstKeySelected()
    {
        GuideWindow guide;
        app::MainWindow& window = guide.window();
        window.openBundledSample();
        QVERIFY(window.playback().isPlaying());
        QCOMPARE(window.selection().key(), std::optional<std::size_t>(0));
        QCOMPARE(window.document().object(guide.object())->name, QStringLiteral("L-cycle block"));
        window.playback().pause();
        window.document().setCurrentTime(1.5);
        guide.settle();
        QVERIFY(guide.child<app::Viewport>()->trailInstanceCount() > 0);

        guide.picture(QStringLiteral("guide-window.png"), [&](QImage& image) {
            QPainter painter(&image);
            painter.setRenderHint(QPainter::Antialiasing);
            const QMenuBar& menus = *window.menuBar();
            const QRect lastMenu = menus.actionGeometry(menus.actions().constLast());
            drawBadge(painter, window, menus, {lastMenu.right() + 20, menus.height() / 2}, 1);
            const auto& toolBar = *guide.child<QToolBar>("playbackToolBar");
            const QRect lastTool = toolBar.actionGeometry(toolBar.actions().constLast());
            drawBadge(painter, window, toolBar, {lastTool.right() + 20, toolBar.height() / 2}, 2);
            const std::pair<const char*, int> docks[] = {{"sphereDock", 3}, {"screwBenderDock", 4}, {"outlinerDock", 6},
                                                         {"inspectorDock", 7}, {"magnitudeDock", 8}, {"timelineDock", 9}};
            for (const auto& [name, number] : docks) {
                const auto& dock = *guide.child<QDockWidget>(name);
                drawBadge(painter, window, dock, {dock.width() - 70, 11}, number);
            }
            drawBadge(painter, window, *guide.child<app::Viewport>(), {24, 24}, 5);
            drawBadge(painter, window, *window.statusBar(), {30, window.statusBar()->height() / 2}, 10);
        });
    }

    // The sketch samples: Fit on the Fit tab converges, and the sphere and the speed plot show the
    // fitted motion beside the motion before the fit.
    // The spinning top's picture shows the Pattern tool, its pad holding the sketch's wiggle and its
    // repeat count.
    void fitsTheSpinningTop()
    {
        fitSketchSample("spinning-top", 7.0, QStringLiteral("guide-spinning-top.png"), [](GuideWindow& guide) {
            guide.child<app::SphereView>()->patternAction()->trigger();
            auto* pad = guide.child<app::PatternPad>();
            QVERIFY(pad->isVisible());
            QCOMPARE(pad->canvas()->pattern().size(), guide.track().sketch.pattern.size());
            QCOMPARE(pad->repeatBox()->value(), 30);
        });
    }
    void fitsTheLetterM() { fitSketchSample("letter-m", 4.0, QStringLiteral("guide-letter-m.png")); }
    void fitsTheHat() { fitSketchSample("hat", 4.5, QStringLiteral("guide-hat.png")); }
    void fitsTheFallingLeaf() { fitSketchSample("falling-leaf", 12.0, QStringLiteral("guide-falling-leaf.png")); }
    void fitsThePen() { fitSketchSample("pen", 2.0, QStringLiteral("guide-pen.png")); }

    // The L-cycle: dragging the selected control pose's x arrow moves it in one undo step, the trail
    // follows, and the ghost shows the motion as it was opened.
    void dragsAControlPoseOfTheLCycle()
    {
        GuideWindow guide;
        guide.openSample("l-cycle", 2.3);
        guide.window().selection().selectKey(guide.object(), 2);
        guide.settle();
        auto* viewport = guide.child<app::Viewport>();
        const Eigen::Vector3d before = guide.track().keys[2].pose.position;
        const QPointF grab = *viewport->handleScreenPosition(app::Viewport::Handle::MoveX);
        const QPointF base = *viewport->controlPoseScreenPosition(2);
        test::dragAlong(viewport, test::straightPath(grab, grab + 0.8 * (grab - base), 10));
        QCOMPARE(guide.window().document().undoStack().count(), 1);
        QVERIFY(guide.track().keys[2].pose.position.x() > before.x() + 0.2);
        guide.settle();
        QVERIFY(viewport->drewGhost());
        QVERIFY(viewport->trailInstanceCount() > 0);
        guide.picture(QStringLiteral("guide-l-cycle.png"));
    }

    // The pendulum on the Smoothness tab: position, velocity and acceleration of the middle of its bob.
    void plotsThePendulumsSmoothness()
    {
        GuideWindow guide;
        guide.openSample("pendulum", 1.25);
        guide.raiseDock("smoothnessDock");
        guide.settle();
        guide.child<QDoubleSpinBox>("pointZBox")->setValue(kPendulumBob);
        GuideWindow::waitForCurves({guide.child<app::SmoothnessPanel>()});
        using Quantity = app::SmoothnessPanel::Quantity;
        // The bob swings: its speed and acceleration are far from the rounding noise of a still point.
        for (Quantity quantity : {Quantity::Velocity, Quantity::Acceleration}) {
            bool found = false;
            const QCPRange range = smoothnessGraph(guide, quantity)->getValueRange(found);
            QVERIFY(found && range.upper > 0.5);
        }
        guide.picture(QStringLiteral("guide-pendulum.png"));
    }

    // The spinning top in the Graph Editor: its Euler angles unwrapped, so the spin about z climbs
    // through many turns instead of wrapping at ±180°, with its 85 keys on the curves.
    void showsTheSpinningTopsChannelsInTheGraphEditor()
    {
        GuideWindow guide;
        guide.openSample("spinning-top", 7.0);
        // The other views first: once the Graph Editor has sampled, they may have drawn the top already.
        guide.settle();
        auto* editor = guide.child<app::GraphEditorPanel>();
        QSignalSpy updated(editor, &app::GraphEditorPanel::curvesUpdated);
        guide.child<QDockWidget>("graphEditorDock")->show();
        guide.raiseDock("graphEditorDock");
        QVERIFY(updated.wait(10'000));
        guide.redraw();
        bool found = false;
        const QCPRange spin = editor->graph(model::Channel::EulerThird)->getValueRange(found);
        QVERIFY(found && spin.size() > 3 * 360.0);
        QCOMPARE(editor->keyGraph(model::Channel::EulerThird)->dataCount(), int(guide.track().keys.size()));
        guide.picture(QStringLiteral("guide-graph-editor.png"));
    }

    // Each free-flight sample's angular momentum and energy in the Graph Editor: flat across the flight, however
    // the body tumbles.
    void showsTheFlightSamplesAngularMomentum_data()
    {
        QTest::addColumn<QString>("entry");
        QTest::addColumn<QString>("image");
        QTest::newRow("t-handle") << QStringLiteral("t-handle") << QStringLiteral("guide-t-handle.png");
        QTest::newRow("flipped-coin") << QStringLiteral("flipped-coin") << QStringLiteral("guide-flipped-coin.png");
        QTest::newRow("thrown-book") << QStringLiteral("thrown-book") << QStringLiteral("guide-thrown-book.png");
    }
    void showsTheFlightSamplesAngularMomentum()
    {
        QFETCH(QString, entry);
        QFETCH(QString, image);
        GuideWindow guide;
        guide.openSample(qPrintable(entry), 1.0);
        guide.settle();
        auto* editor = guide.child<app::GraphEditorPanel>();
        for (std::size_t channel = 0; channel < model::kChannelCount; ++channel)
            editor->channels().setShown(static_cast<model::Channel>(channel), false);
        using model::Channel;
        for (const Channel channel : {Channel::AngularMomentumX, Channel::AngularMomentumY, Channel::AngularMomentumZ,
                                      Channel::AngularMomentumMagnitude, Channel::KineticEnergy})
            editor->channels().setShown(channel, true);
        QSignalSpy updated(editor, &app::GraphEditorPanel::curvesUpdated);
        guide.child<QDockWidget>("graphEditorDock")->show();
        guide.raiseDock("graphEditorDock");
        QVERIFY(updated.count() > 0 || updated.wait(10'000));
        guide.redraw();
        // |L| in flight: the same at every sample between the keys.
        const std::vector<model::Keyframe>& keys = guide.track().keys;
        QCOMPARE(keys.size(), std::size_t{2});
        double lowest = std::numeric_limits<double>::infinity();
        double highest = 0.0;
        for (auto point = editor->graph(Channel::AngularMomentumMagnitude)->data()->constBegin();
             point != editor->graph(Channel::AngularMomentumMagnitude)->data()->constEnd(); ++point)
            if (point->key > keys.front().time + 0.01 && point->key < keys.back().time - 0.01) {
                lowest = std::min(lowest, point->value);
                highest = std::max(highest, point->value);
            }
        QVERIFY(highest > 0.0);
        QVERIFY2(highest - lowest <= 1e-6 * highest, qPrintable(QString::number(highest - lowest)));
        guide.picture(image);
    }

    // The falling leaf, a hermite track, with a trail of 32 copies over its whole fall (View ▸ Trail).
    void showsTheFallingLeafsTrail()
    {
        GuideWindow guide;
        guide.openSample("falling-leaf", 13.0);
        guide.child<QAction>("actionTrailCopies-32")->trigger();
        auto* viewport = guide.child<app::Viewport>();
        QTRY_COMPARE(viewport->trailInstanceCount(), std::size_t{32});
        guide.settle();
        guide.picture(QStringLiteral("guide-trail.png"));
        guide.child<QAction>("actionTrailCopies-16")->trigger(); // the setting back as the other pictures have it
    }

    // The spinning block as it opens; then Decoupled, for comparison, ticked: one undo step, the track
    // decoupled, and the ghost showing the screw motion it started from.
    void decouplesTheSpinningBlock()
    {
        GuideWindow guide;
        guide.openSample("spinning-block", 0.6);
        guide.settle();
        QVERIFY(guide.child<app::Viewport>()->trailInstanceCount() > 0);
        guide.picture(QStringLiteral("guide-spinning-block.png"));

        QVERIFY(!guide.track().subdivision.decoupled);
        test::clickIndicator(guide.child<QCheckBox>("decoupledCheck"));
        QVERIFY(guide.track().subdivision.decoupled);
        QCOMPARE(guide.window().document().undoStack().count(), 1);
        guide.settle();
        QVERIFY(guide.child<app::Viewport>()->drewGhost());
    }

    // The critter's cycle as it opens: a screw track of six keys, 4-point subdivided, cyclic.
    void opensTheCrittersCycle()
    {
        GuideWindow guide;
        guide.openSample("critter-cycle", 2.5);
        QCOMPARE(guide.track().keys.size(), std::size_t(6));
        QCOMPARE(guide.track().interpolation, InterpolationMethod::Screw);
        QCOMPARE(guide.track().subdivision.scheme, SubdivisionScheme::FourPoint);
        QVERIFY(guide.track().subdivision.cyclic);
        guide.settle();
        QVERIFY(guide.child<app::Viewport>()->trailInstanceCount() > 0);
        guide.picture(QStringLiteral("guide-critter-cycle.png"));
    }

    // A motion capture opened as the guide tells (a scene file opened is imported) shows its skeleton
    // in the Outliner; typing in the filter box leaves the matching joints with their ancestors.
    void showsAMotionCapturesSkeletonInTheOutliner()
    {
        GuideWindow guide;
        app::MainWindow& window = guide.window();
        openHumanCapture(window);
        if (QTest::currentTestFailed())
            return;
        QCOMPARE(window.document().scene().objects.size(), std::size_t{19});
        guide.child<QAction>("actionFrameAll")->trigger(); // View ▸ Frame Scene
        auto* outliner = guide.child<app::OutlinerPanel>();
        const model::ObjectId foreArm = window.document().scene().objects[7].id;
        QCOMPARE(window.document().object(foreArm)->name, QStringLiteral("LeftForeArm"));
        const QModelIndex row = outliner->filteredModel().mapFromSource(outliner->sceneModel().indexOf(foreArm));
        outliner->tree()->scrollTo(row);
        QTest::mouseClick(outliner->tree()->viewport(), Qt::LeftButton, Qt::NoModifier, outliner->tree()->visualRect(row).center());
        QCOMPARE(window.selection().object(), foreArm);
        guide.settle();
        guide.picture(QStringLiteral("guide-outliner.png"));

        QTest::keyClicks(outliner->filterBox(), QStringLiteral("hand"));
        QCOMPARE(outliner->filteredModel().rowCount(), 1); // Hips, leading to both hands
        QVERIFY(outliner->filteredModel().match(outliner->filteredModel().index(0, 0), Qt::DisplayRole,
                                                QStringLiteral("RightHand"), 1, Qt::MatchRecursive).size() == 1);
        QVERIFY(outliner->filteredModel().match(outliner->filteredModel().index(0, 0), Qt::DisplayRole,
                                                QStringLiteral("LeftLeg"), 1, Qt::MatchRecursive).isEmpty());
    }

    // The same capture in the front view (number pad 1), framed: its joints drawn as bones, standing up
    // (the hips below the head on screen), a click on the left forearm's bone selecting it.
    void showsAMotionCapturesBones()
    {
        GuideWindow guide;
        app::MainWindow& window = guide.window();
        openHumanCapture(window);
        if (QTest::currentTestFailed())
            return;
        auto* viewport = guide.child<app::Viewport>();
        // The capture's motion is built off the UI thread: its 23 bones (18 links and 5 leaves) show once it is in.
        QVERIFY(QTest::qWaitFor([&] { viewport->update(); return viewport->skeleton().bones().size() == 23; }, 30'000));
        guide.child<QAction>("actionViewFront")->trigger();
        guide.child<QAction>("actionFrameAll")->trigger();
        guide.settle();
        const model::Scene& scene = window.document().scene();
        const model::ObjectId foreArm = scene.objects[7].id;
        QCOMPARE(scene.objects[7].name, QStringLiteral("LeftForeArm"));
        QVERIFY(viewport->objectScreenPosition(scene.objects[0].id)->y() > viewport->objectScreenPosition(scene.objects[4].id)->y());
        const std::vector<app::Bone>& bones = viewport->skeleton().bones();
        const auto bone = std::find_if(bones.begin(), bones.end(), [&](const app::Bone& each) { return each.joint == foreArm; });
        QVERIFY(bone != bones.end());
        const Eigen::Vector3d middle = viewport->camera().project(0.5 * (bone->head() + bone->tail()));
        QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, QPoint(int(middle.x()), int(middle.y())));
        QCOMPARE(window.selection().object(), foreArm);
        guide.settle();
        guide.picture(QStringLiteral("guide-bones.png"));
    }

    // A tail of six joints curled a little at each, its skinned tube following them: X-ray shading
    // shows the bones inside, the fourth joint selected.
    void showsASkinnedMeshFollowingItsJoints()
    {
        GuideWindow guide;
        app::MainWindow& window = guide.window();
        QTemporaryDir folder;
        const QString path = folder.filePath(QStringLiteral("tail.gyre"));
        model::writeProject(path, test::skinnedTube(6, 120, 0.5, 0.4));
        QVERIFY(window.openProject(path));
        window.playback().pause();
        auto* viewport = guide.child<app::Viewport>();
        QVERIFY(QTest::qWaitFor([&] { viewport->update(); return viewport->skeleton().bones().size() == 6; }, 30'000));
        guide.child<QAction>("actionViewTop")->trigger();
        guide.child<QAction>("actionXray")->trigger();
        guide.child<QAction>("actionFrameAll")->trigger();
        window.selection().selectObject(4);
        guide.settle();
        // The tube's end ring, modelled about the last joint's place, is about it where the curl takes it.
        const model::Scene& scene = window.document().scene();
        model::Document& document = window.document();
        const model::SceneMotion motion(scene, [&document](const model::SceneObject& object) { return document.motion(object.id); });
        const model::SceneObject& tube = scene.objects.back();
        const std::vector<Eigen::Vector3f> skinned =
            model::skinnedPositions(*tube.mesh, model::jointMatrices(tube.mesh->skin, tube.id, motion, 0.0));
        Eigen::Vector3d endRing = Eigen::Vector3d::Zero();
        for (std::size_t v = skinned.size() - 64; v < skinned.size(); ++v)
            endRing += skinned[v].cast<double>() / 64.0;
        const Eigen::Vector3d lastJoint = motion.worldPose(6, 0.0).position;
        QVERIFY((endRing - lastJoint).norm() < 1e-5);
        QVERIFY(std::abs(lastJoint.y()) > 0.5); // curled well away from the straight line
        guide.picture(QStringLiteral("guide-skinning.png"));
    }

private:
    // Opens humanBvh as the guide tells (a scene file opened is imported), at 1 s, paused.
    static void openHumanCapture(app::MainWindow& window)
    {
        test::useBuiltSceneWorker();
        QTemporaryDir folder;
        const QString path = folder.filePath(QStringLiteral("walk.bvh"));
        QFile file(path);
        const QByteArray bvh = humanBvh();
        QVERIFY(file.open(QIODevice::WriteOnly) && file.write(bvh) == bvh.size());
        file.close();
        QSignalSpy imported(&window.sceneFiles().jobs(), &jobs::SceneFileJobs::imported);
        window.openFile(path);
        QTRY_COMPARE_WITH_TIMEOUT(imported.count(), 1, 30'000);
        window.playback().pause();
        window.document().setCurrentTime(1.0);
    }

    // The sphere and the speed plot show a fitted track's fit and its motion before the fit.
    static void checkShowsTheFit(GuideWindow& guide)
    {
        QVERIFY(guide.child<app::SphereView>()->curves().fitSpan.has_value());
        QVERIFY(guide.child<app::MagnitudePlot>()->graph(app::MagnitudePlot::Curve::Fitted)->dataCount() > 0);
        QVERIFY(guide.child<app::MagnitudePlot>()->graph(app::MagnitudePlot::Curve::BeforeFit)->dataCount() > 0);
    }

    // Opens the sample, which shows its fit; Remove fit takes it back to the keys and Fit fits it again,
    // as the guide says; `prepare` then sets up the picture.
    template <class Prepare>
    void fitSketchSample(const char* entry, double time, const QString& picture, Prepare prepare)
    {
        GuideWindow guide;
        guide.openSample(entry, time);
        guide.settle();
        QVERIFY(!guide.track().sketch.fittedCurve.empty());
        checkShowsTheFit(guide);
        guide.removeFitFromTheFitTab();
        if (QTest::currentTestFailed())
            return;
        guide.settle();
        const QString message = guide.fitFromTheFitTab();
        QVERIFY2(message.startsWith(QStringLiteral("Fit applied: the motion now follows the sketch")), qPrintable(message));
        QVERIFY(!guide.track().sketch.fittedCurve.empty());
        guide.settle();
        checkShowsTheFit(guide);
        if (QTest::currentTestFailed())
            return;
        prepare(guide);
        if (QTest::currentTestFailed())
            return;
        guide.picture(picture);
    }
    void fitSketchSample(const char* entry, double time, const QString& picture)
    {
        fitSketchSample(entry, time, picture, [](GuideWindow&) {});
    }
};

QTEST_MAIN(TestUserGuide)
#include "tst_user_guide.moc"
