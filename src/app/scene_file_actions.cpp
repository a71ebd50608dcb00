#include "app/scene_file_actions.h"

#include "app/import_dialog.h"
#include "model/commands/import_objects_command.h"
#include "model/commands/set_time_range_command.h"
#include "model/rotation_mode.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace gyre::app {

namespace {

constexpr int kMessageMilliseconds = 8000;

QString importFilter()
{
    return SceneFileActions::tr("Scenes (*.fbx *.gltf *.glb *.dae *.obj *.bvh *.3ds *.x *.ase *.ply *.stl);;"
                                "All files (*)");
}

QString exportFilter()
{
    return SceneFileActions::tr("glTF 2.0 (*.gltf);;glTF 2.0 binary (*.glb);;Collada (*.dae);;FBX (*.fbx);;"
                                "OBJ, meshes only (*.obj)");
}

// The scene's time range after an import: the imported one for a document with no keys yet (empty,
// or a new project's block), else the document's, widened to cover the imported motion.
model::TimeRange rangeAfterImport(const model::Scene& current, const model::Scene& imported)
{
    const bool keyed = std::any_of(current.objects.begin(), current.objects.end(),
                                   [](const model::SceneObject& object) { return !object.track.keys.empty(); });
    if (!keyed)
        return {imported.fps, imported.startTime, imported.endTime};
    return {current.fps, std::min(current.startTime, imported.startTime),
            std::max(current.endTime, imported.endTime)};
}

} // namespace

SceneFileActions::SceneFileActions(model::Document& document, Selection& selection, QWidget* window,
                                   QStatusBar* statusBar, QObject* parent)
    : QObject(parent)
    , document_(document)
    , selection_(selection)
    , window_(window)
    , statusBar_(statusBar)
    , busyLabel_(new QLabel(statusBar))
    , busyBar_(new QProgressBar(statusBar))
    , cancelButton_(new QPushButton(tr("Cancel"), statusBar))
{
    // Assimp reports no progress, so the bar only says that work is going on.
    busyBar_->setRange(0, 0);
    busyBar_->setMaximumWidth(160);
    cancelButton_->setObjectName(QStringLiteral("cancelSceneJob"));
    for (QWidget* widget : std::initializer_list<QWidget*>{busyLabel_, busyBar_, cancelButton_}) {
        statusBar_->addPermanentWidget(widget);
        widget->hide();
    }
    connect(cancelButton_, &QPushButton::clicked, &jobs_, &jobs::SceneFileJobs::cancelImport);
    connect(&jobs_, &jobs::SceneFileJobs::imported, this, &SceneFileActions::receiveImport);
    connect(&jobs_, &jobs::SceneFileJobs::exported, this, &SceneFileActions::reportExport);
    connect(&jobs_, &jobs::SceneFileJobs::failed, this,
            [this](const QString&, const QString& message) { reportFailure(message); });
    connect(&jobs_, &jobs::SceneFileJobs::cancelled, this, [this](const QString& path) {
        hideBusy();
        statusBar_->showMessage(tr("Import of %1 cancelled").arg(QFileInfo(path).fileName()), kMessageMilliseconds);
    });
}

void SceneFileActions::chooseSceneToImport()
{
    const QString path = QFileDialog::getOpenFileName(window_, tr("Import Scene"), QString(), importFilter());
    if (!path.isEmpty())
        importScene(path, true);
}

void SceneFileActions::chooseSceneToExport()
{
    QString selectedFilter;
    QString path = QFileDialog::getSaveFileName(window_, tr("Export Scene"), QString(), exportFilter(), &selectedFilter);
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty()) {
        // The extension names the format; take it from the chosen filter, "(*.glb)" for example.
        const qsizetype star = selectedFilter.lastIndexOf(QLatin1String("*."));
        path += selectedFilter.mid(star + 1).chopped(1);
    }
    exportScene(path);
}

void SceneFileActions::importScene(const QString& path, bool askForOptions)
{
    if (jobs_.isBusy()) {
        statusBar_->showMessage(tr("Wait for the scene file being read or written first"), kMessageMilliseconds);
        return;
    }
    firstRead_ = true;
    askForOptions_ = askForOptions;
    startImport(path, {});
}

void SceneFileActions::startImport(const QString& path, const io::ImportOptions& options)
{
    if (!jobs_.startImport(path, options)) {
        statusBar_->showMessage(tr("Wait for the scene file being read or written first"), kMessageMilliseconds);
        return;
    }
    showBusy(tr("Importing %1…").arg(QFileInfo(path).fileName()), true);
}

void SceneFileActions::receiveImport(const QString& path, const std::shared_ptr<const io::SceneImport>& imported)
{
    hideBusy();
    const bool wasFirstRead = std::exchange(firstRead_, false);
    if (wasFirstRead && (askForOptions_ || imported->takeRule == io::TakeRule::ChoiceNeeded))
        askForOptions(path, imported);
    else
        addImportedObjects(path, imported);
}

void SceneFileActions::askForOptions(const QString& path, const std::shared_ptr<const io::SceneImport>& firstRead)
{
    auto* dialog = new ImportDialog(path, *firstRead, QSettings().value(QLatin1String(kEulerFilterKey)).toBool(), window_);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog, path, firstRead] {
        QSettings().setValue(QLatin1String(kEulerFilterKey), dialog->eulerFilter());
        if (dialog->keepsTheDefaults())
            addImportedObjects(path, firstRead);
        else
            startImport(path, dialog->options());
    });
    connect(dialog, &QDialog::rejected, this, [this, path] {
        statusBar_->showMessage(tr("Import of %1 cancelled").arg(QFileInfo(path).fileName()), kMessageMilliseconds);
    });
    dialog->open();
    emit importDialogOpened(dialog);
}

void SceneFileActions::exportScene(const QString& path)
{
    const std::optional<io::SceneFormat> format = io::sceneFormatOfPath(path);
    if (!format) {
        QMessageBox::warning(window_, tr("Cannot export"),
                             tr("%1: Gyre writes .gltf, .glb, .dae, .fbx and .obj scenes; the file name's "
                                "extension says which.")
                                 .arg(QDir::toNativeSeparators(path)));
        return;
    }
    const model::Scene& scene = document_.scene();
    if (!jobs_.startExport(scene, path, *format, scene.fps)) {
        statusBar_->showMessage(tr("Wait for the scene file being read or written first"), kMessageMilliseconds);
        return;
    }
    showBusy(tr("Exporting %1…").arg(QFileInfo(path).fileName()), false);
}

void SceneFileActions::addImportedObjects(const QString& path, const std::shared_ptr<const io::SceneImport>& imported)
{
    const QString name = QFileInfo(path).fileName();
    if (imported->scene.objects.empty()) {
        reportFailure(tr("%1: the file holds no objects.").arg(QDir::toNativeSeparators(path)));
        return;
    }
    auto* step = new QUndoCommand(tr("Import %1").arg(name));
    try {
        const model::TimeRange range = rangeAfterImport(document_.scene(), imported->scene);
        std::vector<model::SceneObject> objects = imported->scene.objects;
        if (QSettings().value(QLatin1String(kEulerFilterKey)).toBool())
            for (model::SceneObject& object : objects)
                model::putInEulerMode(object.track, {}); // extrinsic xyz: Blender's default XYZ Euler
        new model::ImportObjectsCommand(document_, std::move(objects), step);
        new model::SetTimeRangeCommand(document_, range, step);
    } catch (const std::invalid_argument& error) {
        delete step;
        reportFailure(QStringLiteral("%1: %2").arg(QDir::toNativeSeparators(path), QString::fromUtf8(error.what())));
        return;
    }
    const auto* objects = static_cast<const model::ImportObjectsCommand*>(step->child(0));
    const model::ObjectId first = objects->ids().front();
    document_.push(step);
    selection_.selectObject(first);
    emit objectsImported();
    statusBar_->showMessage(tr("Objects imported from %1: %n", nullptr, static_cast<int>(imported->scene.objects.size()))
                                .arg(name),
                            kMessageMilliseconds);
    showWarnings(tr("Imported %1").arg(name), imported->warnings);
}

void SceneFileActions::reportExport(const QString& path, const io::ExportReport& report)
{
    hideBusy();
    statusBar_->showMessage(tr("Exported %1").arg(QFileInfo(path).fileName()), kMessageMilliseconds);
    showWarnings(tr("Exported %1").arg(QFileInfo(path).fileName()), report.warnings);
}

void SceneFileActions::reportFailure(const QString& message)
{
    hideBusy();
    QMessageBox::warning(window_, tr("Scene file"), message);
}

void SceneFileActions::showWarnings(const QString& title, const QStringList& warnings)
{
    if (warnings.isEmpty())
        return;
    // Not modal: the artist reads it beside the result.
    auto* box = new QMessageBox(QMessageBox::Information, title,
                                tr("Done. Warnings about what the file could not keep: %n.", nullptr,
                                   static_cast<int>(warnings.size())),
                                QMessageBox::Ok, window_);
    box->setDetailedText(warnings.join(QLatin1Char('\n')));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setModal(false);
    box->show();
}

void SceneFileActions::showBusy(const QString& text, bool cancellable)
{
    busyLabel_->setText(text);
    busyLabel_->show();
    busyBar_->show();
    cancelButton_->setVisible(cancellable);
}

void SceneFileActions::hideBusy()
{
    busyLabel_->hide();
    busyBar_->hide();
    cancelButton_->hide();
}

} // namespace gyre::app
