#include "app/main_window.h"

#include "app/add_object_actions.h"
#include "app/euler_convention_choosers.h"
#include "app/graph_editor/graph_editor_panel.h"
#include "app/inspector_widget.h"
#include "app/key_clipboard_actions.h"
#include "app/outliner/outliner_panel.h"
#include "app/preferences_dialog.h"
#include "app/screwbender_panel.h"
#include "app/sketch/direction_sketch_panel.h"
#include "app/sketch/fit_controller.h"
#include "app/sketch/fit_panel.h"
#include "app/sketch/fit_progress.h"
#include "app/sketch/magnitude_plot.h"
#include "app/smoothness_panel.h"
#include "app/time_bar.h"
#include "app/view_preferences.h"
#include "app/timeline_widget.h"
#include "app/viewport/viewport.h"
#include "app/wheel_guard.h"
#include "io/scene_import.h"
#include "model/input_error.h"
#include "ui_main_window.h"

#include <Eigen/Core>
#include <ceres/version.h>
#include <qcustomplot.h>

#include <QCloseEvent>
#include <QComboBox>
#include <QDragEnterEvent>
#include <QDockWidget>
#include <QDropEvent>
#include <QMimeData>
#include <QStandardPaths>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QStyle>
#include <QTimer>
#include <QUndoView>

// The resources (samples, shaders) are compiled into the gyre_app static library, whose static
// initialisers the linker may drop; Q_INIT_RESOURCE registers them, and must be called outside any
// namespace.
static void registerResources()
{
    Q_INIT_RESOURCE(gyre);
}

namespace gyre::app {

namespace {

constexpr int kMaxRecentFiles = 8;
const char* const kRecentFilesKey = "recentFiles";
const char* const kGeometryKey = "mainWindow/geometry";
const char* const kStateKey = "mainWindow/state";

bool isProjectFile(const QString& path)
{
    return QFileInfo(path).suffix().compare(QLatin1String("gyre"), Qt::CaseInsensitive) == 0;
}

QString projectFilter()
{
    return MainWindow::tr("Gyre projects (*.gyre)");
}

// `panel` in a scroll area that fills `dockLayout`: the panel keeps its own height, and the dock can be
// made shorter than it, leaving the height of the window to the plots that need it.
void addScrolled(QLayout* dockLayout, QWidget* panel)
{
    auto* scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(panel);
    dockLayout->addWidget(scroll);
}

// With NumLock off, the number pad sends its other keys (End for 1, Delete for the period, ...), still
// with Qt::KeypadModifier: each number-pad shortcut gets its twin, so that the views work either way,
// as Blender's do.
void addNumLockOffTwin(QAction* action)
{
    static const std::pair<Qt::Key, Qt::Key> kTwins[] = {{Qt::Key_1, Qt::Key_End}, {Qt::Key_3, Qt::Key_PageDown},
                                                         {Qt::Key_5, Qt::Key_Clear}, {Qt::Key_7, Qt::Key_Home},
                                                         {Qt::Key_Period, Qt::Key_Delete}};
    const QKeyCombination numLockOn = action->shortcut()[0];
    if (!(numLockOn.keyboardModifiers() & Qt::KeypadModifier))
        return;
    for (const auto& [on, off] : kTwins)
        if (numLockOn.key() == on)
            action->setShortcuts({action->shortcut(), QKeySequence(QKeyCombination(numLockOn.keyboardModifiers(), off))});
}

} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent)
    , ui_(std::make_unique<Ui::MainWindow>())
    , selection_(document_)
    , playback_(document_)
{
    registerResources();
    // Before any box is made, so that every one is guarded from its first polish.
    WheelGuard::install(this);
    ui_->setupUi(this);
    setUpActions();
    setUpDocks();
    createViews();
    restoreLayout();
    setAcceptDrops(true);
    connect(&document_, &model::Document::modifiedChanged, this, &MainWindow::updateTitle);
    connect(&document_, &model::Document::filePathChanged, this, &MainWindow::updateTitle);
    updateTitle();
    updateRecentFilesMenu();
    fillSamplesMenu();
}

MainWindow::~MainWindow()
{
    // The views hold references to the document, the selection and the playback, which are members
    // and so would go before the views, the window's children: the views go first.
    delete takeCentralWidget();
    qDeleteAll(findChildren<QDockWidget*>(Qt::FindDirectChildrenOnly));
    setStatusBar(nullptr);
    delete fitController_;
    delete sceneFiles_;
}

void MainWindow::setUpActions()
{
    QStyle* style = this->style();
    ui_->actionNew->setShortcut(QKeySequence::New);
    ui_->actionNew->setIcon(style->standardIcon(QStyle::SP_FileIcon));
    ui_->actionOpen->setShortcut(QKeySequence::Open);
    ui_->actionOpen->setIcon(style->standardIcon(QStyle::SP_DialogOpenButton));
    ui_->actionSave->setShortcut(QKeySequence::Save);
    ui_->actionSave->setIcon(style->standardIcon(QStyle::SP_DialogSaveButton));
    ui_->actionSaveAs->setShortcut(QKeySequence::SaveAs);
    ui_->actionQuit->setShortcut(QKeySequence::Quit);
    ui_->actionPreferences->setShortcut(QKeySequence::Preferences);
    ui_->actionPlay->setIcon(style->standardIcon(QStyle::SP_MediaPlay));
    ui_->actionStepForward->setIcon(style->standardIcon(QStyle::SP_MediaSeekForward));
    ui_->actionStepBackward->setIcon(style->standardIcon(QStyle::SP_MediaSeekBackward));
    ui_->actionGoToStart->setIcon(style->standardIcon(QStyle::SP_MediaSkipBackward));
    ui_->actionGoToEnd->setIcon(style->standardIcon(QStyle::SP_MediaSkipForward));
    ui_->actionLoop->setIcon(style->standardIcon(QStyle::SP_BrowserReload));

    connect(ui_->actionNew, &QAction::triggered, this, &MainWindow::newProject);
    connect(ui_->actionOpen, &QAction::triggered, this, &MainWindow::chooseProjectToOpen);
    connect(ui_->actionSave, &QAction::triggered, this, &MainWindow::save);
    connect(ui_->actionSaveAs, &QAction::triggered, this, &MainWindow::saveAs);
    connect(ui_->actionQuit, &QAction::triggered, this, &QWidget::close);
    connect(ui_->actionAbout, &QAction::triggered, this, &MainWindow::showAbout);
    connect(ui_->actionPreferences, &QAction::triggered, this, [this] { PreferencesDialog(this).exec(); });

    sceneFiles_ = new SceneFileActions(document_, selection_, this, statusBar(), this);
    connect(ui_->actionImportScene, &QAction::triggered, sceneFiles_, &SceneFileActions::chooseSceneToImport);
    connect(ui_->actionExportScene, &QAction::triggered, sceneFiles_, &SceneFileActions::chooseSceneToExport);
    new AddObjectActions(document_, selection_, *ui_->menuAdd, this);
    // Blender's second keys for these: X deletes (in the views that take it), Insert keys.
    ui_->actionAddKeyframe->setShortcuts({QKeySequence(Qt::Key_K), QKeySequence(Qt::Key_Insert)});
    deleteKeysByX_ = new QAction(ui_->actionDeleteKeyframe->text(), this);
    deleteKeysByX_->setShortcut(Qt::Key_X);
    deleteKeysByX_->setShortcutContext(Qt::WidgetShortcut);
    connect(deleteKeysByX_, &QAction::triggered, ui_->actionDeleteKeyframe, &QAction::trigger);
    new KeyframeActions(document_, selection_,
                        {ui_->actionAddKeyframe, ui_->actionDeleteKeyframe, ui_->actionToggleConstraint,
                         ui_->actionEulerFilter, ui_->actionNextFlightSolution, ui_->actionPreviousFlightSolution,
                         ui_->actionSelectAllKeys, ui_->actionSelectNoKeys},
                        statusBar(), this);
    new KeyClipboardActions(document_, selection_, ui_->actionCopyKeys, ui_->actionPasteKeys, statusBar(), this);

    QAction* undo = document_.undoStack().createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    undo->setIcon(style->standardIcon(QStyle::SP_ArrowBack));
    undo->setObjectName("actionUndo");
    QAction* redo = document_.undoStack().createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    redo->setIcon(style->standardIcon(QStyle::SP_ArrowForward));
    redo->setObjectName("actionRedo");
    ui_->menuEdit->insertActions(ui_->actionUndoHistory, {undo, redo});
    ui_->menuEdit->insertSeparator(ui_->actionUndoHistory);
    ui_->editToolBar->addActions({undo, redo});

    connect(ui_->actionPlay, &QAction::triggered, &playback_, &Playback::togglePlaying);
    connect(&playback_, &Playback::playingChanged, this, [this](bool playing) {
        ui_->actionPlay->setChecked(playing);
        ui_->actionPlay->setIcon(this->style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    });
    connect(ui_->actionStepForward, &QAction::triggered, &playback_, &Playback::stepForward);
    connect(ui_->actionStepBackward, &QAction::triggered, &playback_, &Playback::stepBackward);
    connect(ui_->actionGoToStart, &QAction::triggered, &playback_, &Playback::goToStart);
    connect(ui_->actionGoToEnd, &QAction::triggered, &playback_, &Playback::goToEnd);
    connect(ui_->actionLoop, &QAction::toggled, &playback_, &Playback::setLoops);
    playback_.setLoops(ui_->actionLoop->isChecked());
}

void MainWindow::setUpDocks()
{
    auto* history = new QUndoView(&document_.undoStack(), ui_->historyDockContents);
    history->setEmptyLabel(tr("<opened>"));
    ui_->historyDockLayout->addWidget(history);
    ui_->historyDock->hide();
    // The outliner heads the right column, above the inspector of what it selects.
    auto* outlinerDock = new QDockWidget(tr("Outliner"), this);
    outlinerDock->setObjectName(QStringLiteral("outlinerDock")); // saveState's name for it
    outlinerDock->setWidget(new OutlinerPanel(document_, selection_, outlinerDock));
    addDockWidget(Qt::RightDockWidgetArea, outlinerDock);
    splitDockWidget(outlinerDock, ui_->inspectorDock, Qt::Vertical);
    for (QDockWidget* dock : {outlinerDock, ui_->inspectorDock, ui_->screwBenderDock, ui_->historyDock, ui_->timelineDock,
                              ui_->smoothnessDock, ui_->sphereDock, ui_->fitDock, ui_->magnitudeDock,
                              ui_->graphEditorDock})
        ui_->menuPanels->addAction(dock->toggleViewAction());
    // The history dock has its own action in the Edit menu, checked while the dock is open, as the
    // dock's own action in View ▸ Panels is (tabbed behind another dock included).
    connect(ui_->actionUndoHistory, &QAction::triggered, this, &MainWindow::toggleUndoHistory);
    connect(ui_->historyDock->toggleViewAction(), &QAction::toggled, ui_->actionUndoHistory, &QAction::setChecked);
    // Three smoothness plots need height more than width: they share the right side with the
    // inspector, leaving the bottom to the speed plot and the timeline.
    tabifyDockWidget(ui_->inspectorDock, ui_->smoothnessDock);
    tabifyDockWidget(ui_->inspectorDock, ui_->historyDock);
    // The fit's settings are as tall as the inspector, and the sphere on the left needs that height.
    tabifyDockWidget(ui_->inspectorDock, ui_->fitDock);
    ui_->inspectorDock->raise();
    // The left column holds the motion's own tools: the sphere above ScrewBender's settings.
    splitDockWidget(ui_->sphereDock, ui_->screwBenderDock, Qt::Vertical);
    // The speed plot shares the timeline's time axis: above it, as wide as the window.
    splitDockWidget(ui_->magnitudeDock, ui_->timelineDock, Qt::Vertical);
    // The graph editor's curves run over time too: a tab beside the speed plot, as wide as the window,
    // closed until View ▸ Panels opens it, so that its tab bar takes no height from the speed plot.
    tabifyDockWidget(ui_->magnitudeDock, ui_->graphEditorDock);
    ui_->graphEditorDock->hide();
    ui_->magnitudeDock->raise();
}

void MainWindow::toggleUndoHistory()
{
    QDockWidget* dock = ui_->historyDock;
    // Tabbed behind another dock, it is open but unseen: it comes to the front rather than closing.
    const bool inFront = !dock->isHidden() && !dock->visibleRegion().isEmpty();
    if (inFront) {
        dock->hide();
    } else {
        dock->show();
        dock->raise();
    }
    ui_->actionUndoHistory->setChecked(!dock->isHidden());
}

void MainWindow::createViews()
{
    ui_->inspectorDockLayout->addWidget(new InspectorWidget(document_, selection_, ui_->inspectorDockContents));
    // Scrolled, so that the sphere above it and the speed plot below can be given the column's height.
    addScrolled(ui_->screwBenderDockLayout, new ScrewBenderPanel(document_, selection_));
    ui_->timelineDockLayout->addWidget(new TimeBar(document_, ui_->timelineDockContents));
    auto* timeline = new TimelineWidget(document_, selection_, playback_, ui_->timelineDockContents);
    timeline->addAction(deleteKeysByX_);
    ui_->timelineDockLayout->addWidget(timeline, 1);
    addScrolled(ui_->smoothnessDockLayout, new SmoothnessPanel(document_, selection_));
    ui_->magnitudeDockLayout->addWidget(new MagnitudePlot(document_, selection_, ui_->magnitudeDockContents));
    auto* graphEditor = new GraphEditorPanel(document_, selection_, ui_->graphEditorDockContents);
    ui_->graphEditorDockLayout->addWidget(graphEditor);
    // Its Euler angles are those the inspector shows, in one convention chosen in either.
    auto* inspectorOrder = findChild<QComboBox*>(QStringLiteral("eulerOrderCombo"));
    auto* inspectorFrame = findChild<QComboBox*>(QStringLiteral("eulerFrameCombo"));
    linkConventionChoosers(*inspectorOrder, *inspectorFrame, *graphEditor->orderChooser(), *graphEditor->frameChooser());
    createFitViews();
    createViewport();
    new ViewPreferences(*ui_->menuView, *ui_->actionShowTrail, *ui_->actionOrthographic, viewport_, this);
    ui_->sphereDockLayout->addWidget(new DirectionSketchPanel(document_, selection_, ui_->sphereDockContents));
}

void MainWindow::createFitViews()
{
    fitController_ = new FitController(document_, selection_, this);
    // Scrolled, like the inspector it shares its tabs with, so its height does not set the window's.
    addScrolled(ui_->fitDockLayout, new FitPanel(document_, selection_, *fitController_));
    statusBar()->addPermanentWidget(new FitProgress(*fitController_, *statusBar(), statusBar()));
}

void MainWindow::createViewport()
{
    if (!Viewport::isSupported()) {
        // Everything but the 3D view still works: editing, files, the panels, the timeline.
        auto* missing = new QLabel(tr("The 3D viewport needs OpenGL 3.3, which this display does not offer. "
                                      "Editing, the panels and the timeline work without it."),
                                   ui_->centralWidget);
        missing->setAlignment(Qt::AlignCenter);
        missing->setWordWrap(true);
        ui_->centralLayout->addWidget(missing);
        for (QAction* action : {ui_->actionShowGhost, ui_->actionShowTrajectory, ui_->actionShowControlPoses,
                                ui_->actionShowTrail, ui_->actionFrameAll, ui_->actionFrameSelected, ui_->actionViewFront,
                                ui_->actionViewBack, ui_->actionViewRight, ui_->actionViewLeft, ui_->actionViewTop,
                                ui_->actionViewBottom, ui_->actionOrthographic, ui_->actionWireframe, ui_->actionXray})
            action->setEnabled(false);
        return;
    }
    viewport_ = new Viewport(document_, selection_, ui_->centralWidget);
    viewport_->addAction(deleteKeysByX_);
    ui_->centralLayout->addWidget(viewport_);
    viewport_->setShowGhost(ui_->actionShowGhost->isChecked());
    viewport_->setShowTrajectory(ui_->actionShowTrajectory->isChecked());
    viewport_->setShowControlPoses(ui_->actionShowControlPoses->isChecked());
    viewport_->setShowTrail(ui_->actionShowTrail->isChecked());
    connect(ui_->actionShowGhost, &QAction::toggled, viewport_, &Viewport::setShowGhost);
    connect(ui_->actionShowTrajectory, &QAction::toggled, viewport_, &Viewport::setShowTrajectory);
    connect(ui_->actionShowControlPoses, &QAction::toggled, viewport_, &Viewport::setShowControlPoses);
    connect(ui_->actionShowTrail, &QAction::toggled, viewport_, &Viewport::setShowTrail);
    connect(ui_->actionShowAngularMomentum, &QAction::toggled, viewport_, &Viewport::setShowAngularMomentum);
    connect(ui_->actionShowPrincipalAxes, &QAction::toggled, viewport_, &Viewport::setShowPrincipalAxes);
    connect(viewport_, &Viewport::drawingFailed, this, [this](const QString& message) { statusBar()->showMessage(message); });
    connect(ui_->actionFrameAll, &QAction::triggered, viewport_, &Viewport::frameScene);
    connect(ui_->actionFrameSelected, &QAction::triggered, viewport_, &Viewport::frameSelected);
    connect(sceneFiles_, &SceneFileActions::objectsImported, viewport_, &Viewport::frameSceneWhenDrawn);
    using ViewPoint = Viewport::ViewPoint;
    for (const auto& [action, point] : {std::pair{ui_->actionViewFront, ViewPoint::Front}, std::pair{ui_->actionViewBack, ViewPoint::Back},
                                        std::pair{ui_->actionViewRight, ViewPoint::Right}, std::pair{ui_->actionViewLeft, ViewPoint::Left},
                                        std::pair{ui_->actionViewTop, ViewPoint::Top}, std::pair{ui_->actionViewBottom, ViewPoint::Bottom}})
        connect(action, &QAction::triggered, viewport_, [this, view = point] { viewport_->viewFrom(view); });
    connect(ui_->actionOrthographic, &QAction::toggled, viewport_, &Viewport::setOrthographic);
    for (QAction* action : {ui_->actionFrameSelected, ui_->actionViewFront, ui_->actionViewBack, ui_->actionViewRight,
                            ui_->actionViewLeft, ui_->actionViewTop, ui_->actionViewBottom, ui_->actionOrthographic})
        addNumLockOffTwin(action);
    for (QAction* action : {ui_->actionWireframe, ui_->actionXray})
        connect(action, &QAction::toggled, viewport_, [this] {
            viewport_->setShading({ui_->actionWireframe->isChecked(), ui_->actionXray->isChecked()});
        });
    // A live fit's motion follows the pen while a stroke is drawn.
    connect(fitController_, &FitController::previewChanged, viewport_, &Viewport::setPreviewTrack);

    showFrameRateWhileMoving();
}

void MainWindow::showFrameRateWhileMoving()
{
    auto* frameStats = new QLabel(statusBar());
    frameStats->setObjectName(QStringLiteral("frameRateLabel"));
    frameStats->setToolTip(tr("Viewport frame rate while something moves, and the time to subdivide the trail: "
                              "on the worker, and from the request to its arrival"));
    frameStats->hide();
    statusBar()->addPermanentWidget(frameStats);
    // An idle window redraws now and then (a tooltip, a panel's resize): its rate says nothing.
    const auto moving = [this] { return playback_.isPlaying() || viewport_->isDragging(); };
    connect(viewport_, &Viewport::frameStatsChanged, frameStats,
            [frameStats, moving](double framesPerSecond, double subdivisionMs, double latencyMs) {
                if (!moving())
                    return;
                frameStats->setText(tr("%1 fps · subdivision %2 ms (%3 ms to arrive)")
                                        .arg(framesPerSecond, 0, 'f', 0)
                                        .arg(subdivisionMs, 0, 'f', 1)
                                        .arg(latencyMs, 0, 'f', 1));
                frameStats->show();
            });
    const auto hideWhenStill = [frameStats, moving] {
        if (!moving()) {
            frameStats->hide();
            frameStats->clear();
        }
    };
    connect(&playback_, &Playback::playingChanged, frameStats, hideWhenStill);
    connect(viewport_, &Viewport::draggingChanged, frameStats, hideWhenStill);
}

void MainWindow::restoreLayout()
{
    QSettings settings;
    // The first start: most of the screen, since the viewport shares it with five panels.
    if (!restoreGeometry(settings.value(kGeometryKey).toByteArray()) && screen() != nullptr)
        resize(screen()->availableGeometry().size() * 0.9);
    if (restoreState(settings.value(kStateKey).toByteArray()))
        return;
    // The first start: most of the window for the viewport, panels at the sizes they need. Docks
    // take their sizes once the window is laid out, so this waits for the event loop.
    QTimer::singleShot(0, this, [this] {
        resizeDocks({ui_->inspectorDock}, {400}, Qt::Horizontal);
        resizeDocks({findChild<QDockWidget*>(QStringLiteral("outlinerDock"))}, {220}, Qt::Vertical);
        resizeDocks({ui_->timelineDock, ui_->magnitudeDock}, {130, 220}, Qt::Vertical);
        resizeDocks({ui_->sphereDock}, {340}, Qt::Horizontal);
    });
}

void MainWindow::saveLayout() const
{
    QSettings settings;
    settings.setValue(kGeometryKey, saveGeometry());
    settings.setValue(kStateKey, saveState());
}

void MainWindow::updateTitle()
{
    const QString& path = document_.filePath();
    const QString name = path.isEmpty() ? tr("Untitled") : QFileInfo(path).fileName();
    // Qt shows "[*]" as the unsaved-changes mark, where the platform has one.
    setWindowTitle(tr("%1[*] — Gyre").arg(name));
    setWindowModified(document_.isModified());
    setWindowFilePath(path);
}

void MainWindow::newProject()
{
    if (maybeSave())
        document_.startNewProject();
}

void MainWindow::chooseProjectToOpen()
{
    if (!maybeSave())
        return;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Project"), QString(), projectFilter());
    if (!path.isEmpty())
        openProject(path);
}

void MainWindow::openFile(const QString& path)
{
    if (!isProjectFile(path))
        sceneFiles_->importScene(path);
    else if (maybeSave())
        openProject(path);
}

bool MainWindow::openProject(const QString& path)
{
    try {
        document_.load(path);
    } catch (const InputError& error) {
        QMessageBox::warning(this, tr("Cannot open the project"), QString::fromUtf8(error.what()));
        return false;
    }
    addRecentFile(document_.filePath());
    return true;
}

void MainWindow::openSample(const QString& resourcePath)
{
    document_.loadAsUntitled(resourcePath);
    // Its first key selected, so the inspector and the pose's handles show at once.
    selection_.selectKey(selection_.object(), 0);
    playback_.play();
}

void MainWindow::openBundledSample()
{
    openSample(QStringLiteral(":/samples/l-cycle.gyre"));
}

void MainWindow::fillSamplesMenu()
{
    const std::pair<QString, QString> samples[] = {
        {tr("L-shaped cycle (ScrewBender)"), QStringLiteral(":/samples/l-cycle.gyre")},
        {tr("Spinning top (sketched angular velocity)"), QStringLiteral(":/samples/spinning-top.gyre")},
        {tr("Letter M (sketched angular velocity)"), QStringLiteral(":/samples/letter-m.gyre")},
        {tr("Hat (sketched angular velocity)"), QStringLiteral(":/samples/hat.gyre")},
        {tr("Falling leaf (sketched angular velocity)"), QStringLiteral(":/samples/falling-leaf.gyre")},
        {tr("Pen (sketched angular speed)"), QStringLiteral(":/samples/pen.gyre")},
        {tr("Pendulum (ScrewBender)"), QStringLiteral(":/samples/pendulum.gyre")},
        {tr("Spinning block (ScrewBender)"), QStringLiteral(":/samples/spinning-block.gyre")},
        {tr("Critter's non-planar cycle (ScrewBender)"), QStringLiteral(":/samples/critter-cycle.gyre")},
        {tr("Tossed T-handle (free flight)"), QStringLiteral(":/samples/t-handle.gyre")},
        {tr("Flipped coin (free flight)"), QStringLiteral(":/samples/flipped-coin.gyre")},
        {tr("Thrown book (free flight)"), QStringLiteral(":/samples/thrown-book.gyre")},
    };
    for (const auto& [title, path] : samples) {
        QAction* action = ui_->menuOpenSample->addAction(title);
        action->setObjectName(QFileInfo(path).baseName());
        connect(action, &QAction::triggered, this, [this, path] {
            if (maybeSave())
                openSample(path);
        });
    }
}

bool MainWindow::save()
{
    return document_.filePath().isEmpty() ? saveAs() : saveTo(document_.filePath());
}

bool MainWindow::saveAs()
{
    QString path = QFileDialog::getSaveFileName(this, tr("Save Project As"), document_.filePath(), projectFilter());
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".gyre");
    return saveTo(path);
}

bool MainWindow::saveTo(const QString& path)
{
    try {
        document_.save(path);
    } catch (const OutputError& error) {
        QMessageBox::warning(this, tr("Cannot save the project"), QString::fromUtf8(error.what()));
        return false;
    }
    addRecentFile(path);
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(path).fileName()), 3000);
    return true;
}

bool MainWindow::maybeSave()
{
    if (!document_.isModified())
        return true;
    const auto answer = QMessageBox::warning(
        this, tr("Unsaved changes"), tr("The project has unsaved changes. Save them first?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::addRecentFile(const QString& path)
{
    QSettings settings;
    QStringList files = settings.value(kRecentFilesKey).toStringList();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    files.removeAll(absolute);
    files.prepend(absolute);
    while (files.size() > kMaxRecentFiles)
        files.removeLast();
    settings.setValue(kRecentFilesKey, files);
    updateRecentFilesMenu();
}

void MainWindow::updateRecentFilesMenu()
{
    QMenu* menu = ui_->menuOpenRecent;
    menu->clear();
    const QStringList files = QSettings().value(kRecentFilesKey).toStringList();
    for (const QString& file : files) {
        QAction* action = menu->addAction(QFileInfo(file).fileName());
        action->setStatusTip(file);
        connect(action, &QAction::triggered, this, [this, file] {
            if (maybeSave())
                openProject(file);
        });
    }
    menu->setEnabled(!files.isEmpty());
}

void MainWindow::showAbout()
{
    QMessageBox::about(
        this, tr("About Gyre"),
        tr("<h3>Gyre %1</h3>"
           "<p>Edit the rotations of animated rigid objects: every way of writing an orientation, "
           "interpolation that behaves, sketched angular velocity, and ScrewBender motions.</p>"
           "<p>Built on Qt %2, Eigen %3.%4.%5, Ceres Solver %6, Assimp %7 and QCustomPlot %8.</p>")
            .arg(QApplication::applicationVersion(), QString::fromLatin1(qVersion()))
            .arg(EIGEN_WORLD_VERSION)
            .arg(EIGEN_MAJOR_VERSION)
            .arg(EIGEN_MINOR_VERSION)
            .arg(QString::fromLatin1(CERES_VERSION_STRING), io::assimpVersion(),
                 QString::fromLatin1(QCUSTOMPLOT_VERSION_STR)));
}

bool MainWindow::recoverAndStartAutosave(std::chrono::milliseconds interval)
{
    const QString directory = QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation)
                              + QStringLiteral("/autosave");
    const std::vector<jobs::RecoveryFile> crashed = jobs::Autosave::recoverableFiles(directory);
    try {
        autosave_ = std::make_unique<jobs::Autosave>(document_, directory, interval);
        connect(autosave_.get(), &jobs::Autosave::autosaveFailed, this, [this](const QString& message) {
            statusBar()->showMessage(tr("Autosave failed: %1").arg(message));
        });
    } catch (const OutputError& error) {
        statusBar()->showMessage(tr("Autosave is off: %1").arg(QString::fromUtf8(error.what())));
    }
    if (crashed.empty())
        return false;

    const jobs::RecoveryFile& newest = crashed.front();
    const QString name = newest.documentPath.isEmpty() ? tr("an untitled project")
                                                       : QDir::toNativeSeparators(newest.documentPath);
    const auto answer = QMessageBox::question(
        this, tr("Recover unsaved work"),
        tr("Gyre ended without saving changes to %1 (last copy %2). Recover them?")
            .arg(name, QLocale().toString(newest.savedAt, QLocale::ShortFormat)),
        QMessageBox::Yes | QMessageBox::Discard, QMessageBox::Yes);
    if (answer != QMessageBox::Yes) {
        jobs::Autosave::discard(newest);
        return false;
    }
    try {
        // Without a session of its own the copy stays where it is, to be offered again.
        if (autosave_)
            autosave_->recover(newest);
        else
            document_.recover(newest.recoveryPath, newest.documentPath);
        return true;
    } catch (const InputError& error) {
        QMessageBox::warning(this, tr("Cannot recover"), QString::fromUtf8(error.what()));
        return false;
    }
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    if (event->mimeData()->hasUrls())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event)
{
    for (const QUrl& url : event->mimeData()->urls()) {
        if (url.isLocalFile()) {
            openFile(url.toLocalFile());
            event->acceptProposedAction();
            return; // one file at a time: an import runs alone
        }
    }
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    playback_.pause();
    saveLayout();
    event->accept();
}

} // namespace gyre::app
