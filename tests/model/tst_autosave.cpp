// Autosave as a crashed user meets it: unsaved work is copied at an interval, a running session's
// copy is never offered for recovery, a crashed session's copy is, and recovering it gives back the
// unsaved document. Copies go away when the document is saved or the session ends cleanly. The crash
// is a real one: autosave_crasher ends without running any destructor.

#include "model/autosave.h"
#include "model/commands/import_objects_command.h"
#include "model/commands/rename_object_command.h"
#include "model/project_file.h"

#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <chrono>

using namespace gyre::model;
using namespace std::chrono_literals;

namespace {

constexpr auto kInterval = 20ms;

void importOne(Document& document, const QString& name)
{
    SceneObject object;
    object.id = 1;
    object.name = name;
    document.undoStack().push(new ImportObjectsCommand(document, {object}));
}

QStringList filesIn(const QString& directory) { return QDir(directory).entryList(QDir::Files); }

} // namespace

class TstAutosave : public QObject {
    Q_OBJECT

private slots:
    void copiesOnlyUnsavedWork();
    void savingRemovesTheCopy();
    void aCleanEndLeavesNothing();
    void offersACrashedSessionForRecovery();
    void discardRemovesTheCopy();
};

void TstAutosave::copiesOnlyUnsavedWork()
{
    QTemporaryDir directory;
    Document document;
    Autosave autosave(document, directory.path(), kInterval);
    QSignalSpy autosaved(&autosave, &Autosave::autosaved);
    QTest::qWait(10 * kInterval.count());
    QCOMPARE(autosaved.count(), 0);
    QVERIFY(!QFileInfo::exists(autosave.recoveryPath()));

    importOne(document, QStringLiteral("first"));
    QVERIFY(autosaved.wait());
    QCOMPARE(autosaved.front().front().toString(), autosave.recoveryPath());
    QCOMPARE(projectJson(readProject(autosave.recoveryPath())), projectJson(document.scene()));
    // Nothing new, nothing written.
    QTest::qWait(10 * kInterval.count());
    QCOMPARE(autosaved.count(), 1);

    document.undoStack().push(new RenameObjectCommand(document, 1, QStringLiteral("second")));
    QVERIFY(autosaved.wait());
    QCOMPARE(readProject(autosave.recoveryPath()).objects.front().name, QStringLiteral("second"));
    // The session is running, so its copy is not offered.
    QVERIFY(Autosave::recoverableFiles(directory.path()).empty());
}

void TstAutosave::savingRemovesTheCopy()
{
    QTemporaryDir directory;
    QTemporaryDir documents;
    Document document;
    Autosave autosave(document, directory.path(), kInterval);
    QSignalSpy autosaved(&autosave, &Autosave::autosaved);
    importOne(document, QStringLiteral("work"));
    QVERIFY(autosaved.wait());
    document.save(documents.filePath("work.gyre"));
    QVERIFY(!QFileInfo::exists(autosave.recoveryPath()));
    QTest::qWait(10 * kInterval.count());
    QVERIFY(!QFileInfo::exists(autosave.recoveryPath()));
    // Undoing past the saved state is unsaved work again.
    document.undoStack().undo();
    QVERIFY(autosaved.wait());
    QVERIFY(QFileInfo::exists(autosave.recoveryPath()));
}

void TstAutosave::aCleanEndLeavesNothing()
{
    QTemporaryDir directory;
    Document document;
    {
        Autosave autosave(document, directory.path(), kInterval);
        QSignalSpy autosaved(&autosave, &Autosave::autosaved);
        importOne(document, QStringLiteral("work"));
        QVERIFY(autosaved.wait());
        QCOMPARE(filesIn(directory.path()).size(), 3); // copy, info, lock
    }
    QCOMPARE(filesIn(directory.path()), QStringList());
}

void TstAutosave::offersACrashedSessionForRecovery()
{
    QTemporaryDir directory;
    QTemporaryDir documents;
    const QString documentPath = documents.filePath("crashed.gyre");
    QProcess crasher;
    crasher.start(QStringLiteral(AUTOSAVE_CRASHER_PATH), {directory.path(), documentPath});
    QVERIFY(crasher.waitForFinished(60'000));
    QCOMPARE(crasher.exitCode(), 0);
    QVERIFY(filesIn(directory.path()).filter(".lock").size() == 1); // the crash left its lock behind

    const std::vector<RecoveryFile> files = Autosave::recoverableFiles(directory.path());
    QCOMPARE(files.size(), std::size_t{1});
    QCOMPARE(files.front().documentPath, documentPath);
    QVERIFY(files.front().savedAt.isValid());

    Document document;
    Autosave autosave(document, directory.path(), kInterval); // the new session
    Autosave::recover(document, files.front());
    QVERIFY(document.isModified());
    QCOMPARE(document.filePath(), documentPath);
    QCOMPARE(document.scene().objects.size(), std::size_t{1});
    QCOMPARE(document.scene().objects.front().name, QStringLiteral("unsaved work"));
    QVERIFY(!QFileInfo::exists(files.front().recoveryPath));
    // Only the new session's lock remains; its copy of the recovered work follows.
    QCOMPARE(filesIn(directory.path()), QStringList{QFileInfo(autosave.recoveryPath()).completeBaseName() + ".lock"});
    QSignalSpy autosaved(&autosave, &Autosave::autosaved);
    QVERIFY(autosaved.wait());
}

void TstAutosave::discardRemovesTheCopy()
{
    QTemporaryDir directory;
    QTemporaryDir documents;
    QProcess crasher;
    crasher.start(QStringLiteral(AUTOSAVE_CRASHER_PATH), {directory.path(), documents.filePath("lost.gyre")});
    QVERIFY(crasher.waitForFinished(60'000));
    const std::vector<RecoveryFile> files = Autosave::recoverableFiles(directory.path());
    QCOMPARE(files.size(), std::size_t{1});
    Autosave::discard(files.front());
    QVERIFY(Autosave::recoverableFiles(directory.path()).empty());
    QCOMPARE(filesIn(directory.path()), QStringList());
}

QTEST_GUILESS_MAIN(TstAutosave)
#include "tst_autosave.moc"
