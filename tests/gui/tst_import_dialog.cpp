// The import dialog in the main window, on files Blender 3.4 exported with its default settings
// (tests/data): it lists every take with the nodes it moves, the automatic choice checked, and the
// settings the file states; a file whose takes overlap opens it even when dropped, and what is chosen
// there is what the document gets.

#include "app/import_dialog.h"
#include "app/main_window.h"
#include "built_scene_worker.h"
#include "gui_test_support.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QTest>
#include <QUndoStack>

using namespace gyre;

namespace {

QString dataFile(const char* name) { return QStringLiteral(GYRE_TEST_DATA "/") + QLatin1String(name); }

// The rows of the takes list that are checked.
QList<int> checkedRows(const app::ImportDialog& dialog)
{
    QList<int> rows;
    for (int row = 0; row < dialog.takes()->rowCount(); ++row)
        if (dialog.takes()->item(row, app::ImportDialog::NameColumn)->checkState() == Qt::Checked)
            rows << row;
    return rows;
}

// The turn between the first and the last key of the document's first object, in degrees.
double turnOfFirstObject(const app::MainWindow& window)
{
    const auto& keys = window.document().scene().objects.front().track.keys;
    return keys.front().pose.orientation.angularDistance(keys.back().pose.orientation) * 180.0 / M_PI;
}

} // namespace

class TestImportDialog : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        test::useTestSettings();
        test::useBuiltSceneWorker();
    }

    // Import Scene shows Blender's nine FBX takes, each object's own checked, and 30 fps, 1 cm, Y-up
    // from the file; accepted as it is, the scene read first joins the document without a second read.
    void importSceneShowsTheTakesAndTheFileSettings()
    {
        app::MainWindow window;
        window.show();
        QSignalSpy opened(&window.sceneFiles(), &app::SceneFileActions::importDialogOpened);
        QSignalSpy read(&window.sceneFiles().jobs(), &jobs::SceneFileJobs::imported);
        window.sceneFiles().importScene(dataFile("blender_three_objects.fbx"), true);
        QTRY_COMPARE_WITH_TIMEOUT(opened.count(), 1, 30000);
        auto* dialog = qobject_cast<app::ImportDialog*>(opened.front().front().value<QDialog*>());
        QVERIFY(dialog);
        QCOMPARE(dialog->takes()->rowCount(), 9);
        QCOMPARE(checkedRows(*dialog), (QList<int>{2, 4, 6}));
        QCOMPARE(dialog->takes()->item(2, app::ImportDialog::NameColumn)->text(), QStringLiteral("Quat|QuatAction"));
        QCOMPARE(dialog->takes()->item(2, app::ImportDialog::NodesColumn)->text(), QStringLiteral("Quat"));
        QCOMPARE(dialog->fps()->value(), 30.0);
        QCOMPARE(dialog->unit()->value(), 0.01);
        QCOMPARE(dialog->upAxis()->currentData().toInt(), static_cast<int>(io::UpAxis::Y));
        QVERIFY(dialog->keepsTheDefaults());
        dialog->accept();
        QCOMPARE(read.count(), 1);
        QCOMPARE(window.document().scene().objects.size(), std::size_t{3});
        QCOMPARE(window.document().scene().fps, 30.0); // the project keeps the file's rate
    }

    // Opened by name, a file whose two animations move the same object asks which; the other one
    // chosen is read again and imported.
    void overlappingTakesAskWhichToImport()
    {
        app::MainWindow window;
        window.show();
        QSignalSpy opened(&window.sceneFiles(), &app::SceneFileActions::importDialogOpened);
        QSignalSpy read(&window.sceneFiles().jobs(), &jobs::SceneFileJobs::imported);
        window.openFile(dataFile("blender_two_actions.glb"));
        QTRY_COMPARE_WITH_TIMEOUT(opened.count(), 1, 30000);
        auto* dialog = qobject_cast<app::ImportDialog*>(opened.front().front().value<QDialog*>());
        QVERIFY(dialog);
        QVERIFY(window.document().scene().objects.empty()); // nothing imported before the choice
        QCOMPARE(dialog->takes()->rowCount(), 2);
        QCOMPARE(checkedRows(*dialog), QList<int>{0});
        QCOMPARE(dialog->takes()->item(1, app::ImportDialog::NameColumn)->text(), QStringLiteral("Wobble"));
        QCOMPARE(dialog->takes()->item(1, app::ImportDialog::NodesColumn)->text(), QStringLiteral("Wheel"));
        dialog->takes()->item(0, app::ImportDialog::NameColumn)->setCheckState(Qt::Unchecked);
        QCOMPARE(dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->isEnabled(), false);
        dialog->takes()->item(1, app::ImportDialog::NameColumn)->setCheckState(Qt::Checked);
        QVERIFY(!dialog->keepsTheDefaults());
        dialog->accept();
        QTRY_COMPARE_WITH_TIMEOUT(read.count(), 2, 30000);
        QCOMPARE(window.document().scene().objects.size(), std::size_t{1});
        QVERIFY(turnOfFirstObject(window) < 0.2); // Wobble tilts and comes back; Spin would turn 180°
    }

    void aCancelledDialogImportsNothing()
    {
        app::MainWindow window;
        window.show();
        QSignalSpy opened(&window.sceneFiles(), &app::SceneFileActions::importDialogOpened);
        window.sceneFiles().importScene(dataFile("blender_three_objects.glb"), true);
        QTRY_COMPARE_WITH_TIMEOUT(opened.count(), 1, 30000);
        opened.front().front().value<QDialog*>()->reject();
        QVERIFY(window.document().scene().objects.empty());
        QCOMPARE(window.document().undoStack().count(), 0);
    }
};

QTEST_MAIN(TestImportDialog)
#include "tst_import_dialog.moc"
