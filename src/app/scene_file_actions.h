#pragma once
// File > Import Scene and File > Export Scene: choosing the file, running the job off the UI thread
// with a busy indicator (and, for an import, a Cancel button) in the status bar, and turning an
// imported scene into one undo step. An import first reads the file with its default options; the
// import dialog (import_dialog.h) then shows its takes and settings, always from File > Import Scene,
// and for a dropped or opened file when its takes need a choice. Changed options read it again.
// The dialog's Euler filter choice is kept in the settings (kEulerFilterKey) and applies to every import
// after it, dialog or not: the objects read are put in Euler mode in the same undo step.

#include "app/selection.h"
#include "jobs/scene_file_jobs.h"
#include "model/document.h"

#include <QObject>
#include <QString>

#include <memory>

class QDialog;
class QLabel;
class QProgressBar;
class QPushButton;
class QStatusBar;
class QWidget;

namespace gyre::app {

class SceneFileActions : public QObject {
    Q_OBJECT

public:
    SceneFileActions(model::Document& document, Selection& selection, QWidget* window, QStatusBar* statusBar,
                     QObject* parent = nullptr);

    jobs::SceneFileJobs& jobs() { return jobs_; }

    void chooseSceneToImport();
    void chooseSceneToExport();
    // Starts reading the scene; its objects join the document when it is read, after the import
    // dialog when `askForOptions` or when the file's takes need a choice.
    void importScene(const QString& path, bool askForOptions = false);
    void exportScene(const QString& path);

signals:
    // The import dialog opened for a file that has been read (for tests and tours).
    void importDialogOpened(QDialog* dialog);
    // An import's objects were added to the document (one undo step).
    void objectsImported();

private:
    void startImport(const QString& path, const io::ImportOptions& options);
    void receiveImport(const QString& path, const std::shared_ptr<const io::SceneImport>& imported);
    void askForOptions(const QString& path, const std::shared_ptr<const io::SceneImport>& firstRead);
    void addImportedObjects(const QString& path, const std::shared_ptr<const io::SceneImport>& imported);
    void reportExport(const QString& path, const io::ExportReport& report);
    // `message` names the file and says what was wrong.
    void reportFailure(const QString& message);
    void showWarnings(const QString& title, const QStringList& warnings);
    void showBusy(const QString& text, bool cancellable);
    void hideBusy();

    model::Document& document_;
    Selection& selection_;
    QWidget* window_;
    QStatusBar* statusBar_;
    jobs::SceneFileJobs jobs_;
    QLabel* busyLabel_;
    QProgressBar* busyBar_;
    QPushButton* cancelButton_;
    // Whether the running import is the first read of its file, and whether to show the dialog then.
    bool firstRead_ = false;
    bool askForOptions_ = false;
};

// The settings key of the import's Euler filter choice (a bool, false when unset).
inline constexpr char kEulerFilterKey[] = "import/eulerFilter";

} // namespace gyre::app
