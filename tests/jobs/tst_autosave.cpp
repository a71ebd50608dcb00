// Autosave as a crashed user meets it: unsaved work is copied at an interval, a running session's
// copy is never offered for recovery, a crashed session's copy is, and recovering it gives back the
// unsaved document and keeps the copy through a second crash. Copies go away when the document is
// saved or the session ends cleanly; what crashed sessions leave besides copies is cleared away; a
// copy that cannot be written is reported and tried again. The crashes are real ones:
// autosave_crasher ends without running any destructor.

#include "jobs/autosave.h"
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

using namespace gyre::jobs;
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

// Runs autosave_crasher with `arguments` (its usage says which session it crashes); its exit code, or
// -1 if it did not end within a minute.
int crashSession(const QStringList& arguments)
{
    QProcess crasher;
    crasher.start(QStringLiteral(AUTOSAVE_CRASHER_PATH), arguments);
    return crasher.waitForFinished(60'000) ? crasher.exitCode() : -1;
}

} // namespace

class TstAutosave : public QObject {
    Q_OBJECT

private slots:
    void copiesOnlyUnsavedWork();
    void savingRemovesTheCopy();
    void aCleanEndLeavesNothing();
    void offersACrashedSessionForRecovery();
    void discardRemovesTheCopy();
    void aRecoveredCopyOutlivesASecondCrash();
    void leftoversOfEndedSessionsAreRemoved();
    void aFailedCopyIsReportedAndTriedAgain();
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
    QCOMPARE(projectBytes(readProject(autosave.recoveryPath())), projectBytes(document.scene()));
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
    // The worker removes it, after any write under way.
    QTRY_VERIFY(!QFileInfo::exists(autosave.recoveryPath()));
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
    QCOMPARE(crashSession({directory.path(), documentPath}), 0);
    QVERIFY(filesIn(directory.path()).filter(".lock").size() == 1); // the crash left its lock behind

    const std::vector<RecoveryFile> files = Autosave::recoverableFiles(directory.path());
    QCOMPARE(files.size(), std::size_t{1});
    QCOMPARE(files.front().documentPath, documentPath);
    QVERIFY(files.front().savedAt.isValid());

    Document document;
    Autosave autosave(document, directory.path(), kInterval); // the new session
    autosave.recover(files.front());
    QVERIFY(document.isModified());
    QCOMPARE(document.filePath(), documentPath);
    QCOMPARE(document.scene().objects.size(), std::size_t{1});
    QCOMPARE(document.scene().objects.front().name, QStringLiteral("unsaved work"));
    // The crashed session's copy is the new session's copy now: its files and its lock, nothing else.
    QVERIFY(!QFileInfo::exists(files.front().recoveryPath));
    const QString session = QFileInfo(autosave.recoveryPath()).completeBaseName();
    QCOMPARE(filesIn(directory.path()), (QStringList{session + ".gyre", session + ".json", session + ".lock"}));
    QCOMPARE(projectBytes(readProject(autosave.recoveryPath())), projectBytes(document.scene()));
    QSignalSpy autosaved(&autosave, &Autosave::autosaved);
    QVERIFY(autosaved.wait());
    // Saving the recovered work ends the need for its copy.
    document.save(documentPath);
    QTRY_VERIFY(!QFileInfo::exists(autosave.recoveryPath()));
}

void TstAutosave::discardRemovesTheCopy()
{
    QTemporaryDir directory;
    QTemporaryDir documents;
    QCOMPARE(crashSession({directory.path(), documents.filePath("lost.gyre")}), 0);
    const std::vector<RecoveryFile> files = Autosave::recoverableFiles(directory.path());
    QCOMPARE(files.size(), std::size_t{1});
    Autosave::discard(files.front());
    QVERIFY(Autosave::recoverableFiles(directory.path()).empty());
    QCOMPARE(filesIn(directory.path()), QStringList());
}

// The session that recovers crashes too, before it has edited or autosaved anything: the recovered
// work is offered again at the next start.
void TstAutosave::aRecoveredCopyOutlivesASecondCrash()
{
    QTemporaryDir directory;
    QTemporaryDir documents;
    const QString documentPath = documents.filePath("twice.gyre");
    QCOMPARE(crashSession({directory.path(), documentPath}), 0);
    const QByteArray firstCopy = projectBytes(readProject(Autosave::recoverableFiles(directory.path()).front().recoveryPath));

    QCOMPARE(crashSession({QStringLiteral("--recover"), directory.path()}), 0);

    const std::vector<RecoveryFile> files = Autosave::recoverableFiles(directory.path());
    QCOMPARE(files.size(), std::size_t{1});
    QCOMPARE(files.front().documentPath, documentPath);
    QCOMPARE(projectBytes(readProject(files.front().recoveryPath)), firstCopy);
}

void TstAutosave::leftoversOfEndedSessionsAreRemoved()
{
    QTemporaryDir directory;
    for (int session = 0; session < 3; ++session) {
        QCOMPARE(crashSession({QStringLiteral("--idle"), directory.path()}), 0);
    }
    QCOMPARE(filesIn(directory.path()).filter(".lock").size(), 3);
    // A running session's lock stays.
    Document document;
    Autosave running(document, directory.path(), kInterval);
    QVERIFY(Autosave::recoverableFiles(directory.path()).empty());
    QCOMPARE(filesIn(directory.path()), QStringList{QFileInfo(running.recoveryPath()).completeBaseName() + ".lock"});
}

void TstAutosave::aFailedCopyIsReportedAndTriedAgain()
{
    QTemporaryDir directory;
    Document document;
    Autosave autosave(document, directory.path(), kInterval);
    QSignalSpy autosaved(&autosave, &Autosave::autosaved);
    QSignalSpy failed(&autosave, &Autosave::autosaveFailed);
    // A folder where the copy should go: no file can be renamed over it.
    QVERIFY(QDir().mkpath(autosave.recoveryPath()));
    importOne(document, QStringLiteral("work"));
    QVERIFY(failed.wait());
    QVERIFY(failed.front().front().toString().contains(QFileInfo(autosave.recoveryPath()).fileName()));
    QCOMPARE(autosaved.count(), 0);

    QVERIFY(QDir(autosave.recoveryPath()).removeRecursively());
    QVERIFY(autosaved.wait());
    QCOMPARE(readProject(autosave.recoveryPath()).objects.front().name, QStringLiteral("work"));
}

QTEST_GUILESS_MAIN(TstAutosave)
#include "tst_autosave.moc"
