// The import dialog in the main window, on files Blender 3.4 exported with its default settings
// (tests/data): it lists every take with the nodes it moves, the automatic choice checked, and the
// settings the file states; a file whose takes overlap opens it even when dropped, and what is chosen
// there is what the document gets; its Euler filter box puts the imported rotations in Euler mode with continuous
// angles in the import's one undo step, and is remembered for imports without the dialog.

#include "app/import_dialog.h"
#include "app/main_window.h"
#include "built_scene_worker.h"
#include "gui_test_support.h"
#include "model/rotation_mode.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSettings>
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

// The main window, watching its imports: the dialogs opened and the files read.
struct ImportSession {
    app::MainWindow window;
    QSignalSpy opened{&window.sceneFiles(), &app::SceneFileActions::importDialogOpened};
    QSignalSpy read{&window.sceneFiles().jobs(), &jobs::SceneFileJobs::imported};

    ImportSession() { window.show(); }

    // File ▸ Import Scene on the test file `name`: its dialog once open, or null.
    app::ImportDialog* importWithDialog(const char* name)
    {
        window.sceneFiles().importScene(dataFile(name), true);
        if (!QTest::qWaitFor([this] { return opened.count() == 1; }, 30000))
            return nullptr;
        return qobject_cast<app::ImportDialog*>(opened.front().front().value<QDialog*>());
    }
};

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
        ImportSession session;
        app::MainWindow& window = session.window;
        app::ImportDialog* dialog = session.importWithDialog("blender_three_objects.fbx");
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
        QCOMPARE(session.read.count(), 1);
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

    void theEulerFilterBoxImportsEulerModeKeysInOneStep()
    {
        ImportSession session;
        app::MainWindow& window = session.window;
        app::ImportDialog* dialog = session.importWithDialog("blender_three_objects.fbx");
        QVERIFY(dialog);
        QVERIFY(!dialog->eulerFilterBox()->isChecked());
        QTest::mouseClick(dialog->eulerFilterBox(), Qt::LeftButton);
        QVERIFY(dialog->eulerFilter());
        QVERIFY(dialog->keepsTheDefaults()); // the box changes what is done with the objects, not the reading
        dialog->accept();
        QCOMPARE(session.read.count(), 1);
        const auto checkEulerMode = [&window] {
            QCOMPARE(window.document().undoStack().count(), 1);
            QCOMPARE(window.document().scene().objects.size(), std::size_t{3});
            for (const model::SceneObject& object : window.document().scene().objects) {
                const model::MotionTrack& track = object.track;
                QVERIFY(track.rotationMode.isEuler());
                QCOMPARE(track.rotationMode.convention, EulerConvention{});
                QVERIFY(model::keepsRotationMode(track)); // every key's angles give its orientation
                for (std::size_t k = 1; k < track.keys.size(); ++k)
                    QVERIFY((*track.keys[k].eulerAngles - *track.keys[k - 1].eulerAngles).cwiseAbs().maxCoeff() < M_PI);
            }
        };
        checkEulerMode();
        window.document().undoStack().undo();
        QVERIFY(window.document().scene().objects.empty());

        // Remembered: a file opened without the dialog gets it too.
        QVERIFY(QSettings().value(QLatin1String(app::kEulerFilterKey)).toBool());
        window.document().undoStack().clear();
        window.sceneFiles().importScene(dataFile("blender_three_objects.fbx"), false);
        QTRY_COMPARE_WITH_TIMEOUT(session.read.count(), 2, 30000);
        checkEulerMode();
        QSettings().remove(QLatin1String(app::kEulerFilterKey));
    }

    void aCancelledDialogImportsNothing()
    {
        ImportSession session;
        app::ImportDialog* dialog = session.importWithDialog("blender_three_objects.glb");
        QVERIFY(dialog);
        dialog->reject();
        QVERIFY(session.window.document().scene().objects.empty());
        QCOMPARE(session.window.document().undoStack().count(), 0);
    }
};

QTEST_MAIN(TestImportDialog)
#include "tst_import_dialog.moc"
