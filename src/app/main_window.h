#pragma once
// The main window: menus, toolbars, the viewport in the middle and the panels in docks around it, all
// laid out in ui/main_window.ui. It owns the document and the selection the views share, opens and
// saves files, and asks before unsaved work is lost. Its layout and geometry persist in QSettings.

#include "app/keyframe_actions.h"
#include "app/playback.h"
#include "app/scene_file_actions.h"
#include "app/selection.h"
#include "jobs/autosave.h"
#include "model/document.h"

#include <QMainWindow>
#include <QString>

#include <chrono>
#include <memory>

namespace Ui {
class MainWindow;
}

namespace gyre::app {

class FitController;
class Viewport;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    model::Document& document() { return document_; }
    const model::Document& document() const { return document_; }
    Selection& selection() { return selection_; }
    const Selection& selection() const { return selection_; }
    Playback& playback() { return playback_; }
    SceneFileActions& sceneFiles() { return *sceneFiles_; }

    // Opens the project at `path` in place of the current one, after asking to keep unsaved work.
    // Reports a file it cannot read in a message box, naming the file and what is wrong, and keeps
    // the current project. Returns whether the project was opened.
    bool openProject(const QString& path);
    // A project (.gyre) opens in place of the current one; any other file is imported as a scene
    // into the current project. What the command line and dropped files go through.
    void openFile(const QString& path);

    // Opens a sample bundled in the resources (":/samples/...") as an untitled project, its first key
    // selected, playing. The samples are compiled in: failing to read one is a broken build.
    void openSample(const QString& resourcePath);
    // Opens the first sample, the L-shaped cycle of the ScrewBender paper, so that a newcomer sees a
    // moving object at once.
    void openBundledSample();
    // Offers to recover the work of a session that crashed, then autosaves this session's unsaved
    // work every `interval` (a crash loses at most that much work). Returns whether work was recovered into the document.
    bool recoverAndStartAutosave(std::chrono::milliseconds interval = std::chrono::seconds(30));

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void setUpActions();
    void setUpDocks();
    // Edit ▸ Undo History: brings the history to the front, open or tabbed behind another dock, or
    // closes it when it is in front.
    void toggleUndoHistory();
    void createViews();
    // The fit panel, and the fit's progress in the status bar, sharing one controller.
    void createFitViews();
    // The 3D viewport in the middle, or a note saying why there is none.
    void createViewport();
    // The viewport's frame rate in the status bar, shown only while playback or a drag moves the view.
    void showFrameRateWhileMoving();
    void restoreLayout();
    void saveLayout() const;
    void updateTitle();

    void newProject();
    void chooseProjectToOpen();
    bool save();
    bool saveAs();
    bool saveTo(const QString& path);
    // Asks whether to save unsaved changes; false if the user cancels the action that asked.
    bool maybeSave();
    void addRecentFile(const QString& path);
    void updateRecentFilesMenu();
    void fillSamplesMenu();
    void showAbout();

    std::unique_ptr<Ui::MainWindow> ui_;
    model::Document document_;
    Selection selection_;
    Playback playback_;
    SceneFileActions* sceneFiles_ = nullptr;
    std::unique_ptr<jobs::Autosave> autosave_;
    FitController* fitController_ = nullptr; // a child of the window, shared by the fit panel and status bar
    Viewport* viewport_ = nullptr; // owned by the central widget
    // X, Blender's second key for Delete Keyframe, only in the timeline and the viewport: window-wide
    // it would take the X typed into a chooser (an Euler order) or a name.
    QAction* deleteKeysByX_ = nullptr;
};

} // namespace gyre::app
