// Scene import and export through gyre-scene-worker: what comes back equals an import in this process;
// a file that crashes Assimp, one that exhausts the memory limit, a worker that hangs, one that
// answers nonsense and one that is missing each end in `failed` naming the file, and the same
// SceneFileJobs then imports a good file. One worker process answers imports in a row, and any failure
// but the file's own error reply replaces it.

#include "built_scene_worker.h"
#include "io/bvh_fixture.h"
#include "io/damaged_scenes.h"
#include "jobs/scene_file_jobs.h"
#include "model/project_file.h"

#include <QElapsedTimer>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace gyre;
using namespace gyre::io;
using gyre::jobs::SceneFileJobs;

namespace {

QString writeFile(const QTemporaryDir& folder, const QString& name, const QByteArray& contents,
                  QFile::Permissions permissions = QFile::ReadOwner | QFile::WriteOwner)
{
    const QString path = folder.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(contents) != contents.size() || !file.setPermissions(permissions))
        qFatal("cannot write %s", qPrintable(path));
    return path;
}

// A stand-in for the worker that never answers.
// Whether `spy` sees its signal within `milliseconds`; never before the job's start has returned,
// which would leave the app showing a job that has ended.
bool arrives(QSignalSpy& spy, int milliseconds = 30000) { return spy.isEmpty() && spy.wait(milliseconds); }

QString hangingWorker(const QTemporaryDir& folder)
{
    return writeFile(folder, QStringLiteral("hanging-worker"), "#!/bin/sh\nexec sleep 600\n",
                     QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
}

} // namespace

class TestSceneFileJobs : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        test::useBuiltSceneWorker();
        builtWorker_ = qgetenv(kSceneWorkerVariable);
        QVERIFY(folder_.isValid());
        goodFile_ = writeFile(folder_, QStringLiteral("walk.bvh"), test::bvhChain(3, 50, 1.0 / 30.0));
    }

    void cleanup() { qputenv(kSceneWorkerVariable, builtWorker_); }

    // Two imports in a row are answered by one worker process, started once.
    void oneWorkerAnswersImportsInARow()
    {
        const QString log = useCountingWorker(QStringLiteral("in-a-row"));
        QVERIFY(importGood());
        QVERIFY(importGood());
        QCOMPARE(startsIn(log), 1);
    }

    // A worker that crashed is replaced: the next import starts a new one, which reads the file.
    void aCrashedWorkerIsReplaced()
    {
        const QString log = useCountingWorker(QStringLiteral("crash"));
        QVERIFY(importGood());
        const QString path = writeFile(folder_, QStringLiteral("crash-then-good.dae"), test::crashingCollada());
        QVERIFY(failureOf(path).contains(QStringLiteral("the scene reader crashed on this file")));
        QCOMPARE(startsIn(log), 1);
        QVERIFY(importGood());
        QCOMPARE(startsIn(log), 2);
        QVERIFY(importGood());
        QCOMPARE(startsIn(log), 2);
    }

    // A worker stopped at the time limit, in the middle of a reply, is replaced.
    void aWorkerStoppedAtTheTimeLimitIsReplaced()
    {
        const QString log = useCountingWorker(QStringLiteral("time-limit"));
        QVERIFY(importGood());
        jobs_.setWorkerLimits({SceneWorkerLimits{}.memoryBytes, std::chrono::milliseconds(1)});
        const QString message = failureOf(largeFile());
        jobs_.setWorkerLimits({});
        QVERIFY2(message.contains(QStringLiteral("the scene reader took longer than 0.001 s")), qPrintable(message));
        QVERIFY(importGood());
        QCOMPARE(startsIn(log), 2);
    }

    // A cancelled import kills its worker; the next import starts a new one.
    void aCancelledWorkerIsReplaced()
    {
        const QString log = useCountingWorker(QStringLiteral("cancel"));
        QVERIFY(importGood());
        QSignalSpy cancelled(&jobs_, &SceneFileJobs::cancelled);
        QVERIFY(jobs_.startImport(largeFile()));
        jobs_.cancelImport();
        QVERIFY(arrives(cancelled, 10000));
        QVERIFY(importGood());
        QCOMPARE(startsIn(log), 2);
    }

    // A reused worker whose memory runs out gets the file again in a fresh worker, since heap left from
    // earlier imports counts against its limit; a file too large for a fresh one fails as before.
    void aReusedWorkerOutOfMemoryRetriesInAFreshOne()
    {
        const QString log = useCountingWorker(QStringLiteral("memory"));
        jobs_.setWorkerLimits({qint64{1} << 30, SceneWorkerLimits{}.time});
        QVERIFY(importGood());
        const QString path = writeFile(folder_, QStringLiteral("huge-after-good.dae"), test::hugeCollada());
        const QString message = failureOf(path);
        QVERIFY(importGood());
        jobs_.setWorkerLimits({});
        QCOMPARE(message, path + QStringLiteral(": the scene reader needed more than 1 GiB of memory for this file "
                                                "and was stopped"));
        QCOMPARE(startsIn(log), 3); // the first, the retry of the huge file, the one after its failure
    }

    // Every field the worker sends equals an import in this process: the project text holds them all.
    void importsExactlyAsAnImportInThisProcess()
    {
        const std::shared_ptr<const SceneImport> imported = importGood();
        QVERIFY(imported);
        const SceneImport here = importScene(goodFile_);
        QCOMPARE(model::projectBytes(imported->scene), model::projectBytes(here.scene));
        QVERIFY(imported->scene.objects.size() >= 3);
        QCOMPARE(imported->animations.size(), here.animations.size());
        QCOMPARE(imported->animations.front().nodes, here.animations.front().nodes);
        QCOMPARE(imported->warnings, here.warnings);
    }

    void exportsThroughTheWorker()
    {
        const SceneImport here = importScene(goodFile_);
        const QString path = folder_.filePath(QStringLiteral("walk.glb"));
        QSignalSpy exported(&jobs_, &SceneFileJobs::exported);
        QVERIFY(jobs_.startExport(here.scene, path, SceneFormat::Glb, 30.0));
        QVERIFY(arrives(exported));
        QCOMPARE(exported.front().at(0).toString(), path);
        QCOMPARE(exported.front().at(1).value<ExportReport>().files, QStringList{path});
        // The worker writes what an export in this process writes, byte for byte.
        const QString pathHere = folder_.filePath(QStringLiteral("walk-here.glb"));
        exportScene(here.scene, pathHere, SceneFormat::Glb, 30.0);
        QFile written(path);
        QFile writtenHere(pathHere);
        QVERIFY(written.open(QIODevice::ReadOnly) && writtenHere.open(QIODevice::ReadOnly));
        QVERIFY(written.size() > 0);
        QCOMPARE(written.readAll(), writtenHere.readAll());
    }

    void aFileThatCrashesTheReaderFailsByName()
    {
        const QString path = writeFile(folder_, QStringLiteral("crash.dae"), test::crashingCollada());
        const QString message = failureOf(path);
        QVERIFY2(message.startsWith(path + QStringLiteral(": the scene reader crashed on this file (signal ") +
                                    test::kCrashSignal),
                 qPrintable(message));
        QVERIFY(importGood());
    }

    void aFileThatExhaustsTheMemoryLimitFailsByName()
    {
        // Under AddressSanitizer, whose shadow memory needs an unlimited address space, its bound on one
        // allocation stands in for the limit (io/scene_worker.cpp): the message is the same.
        jobs_.setWorkerLimits({qint64{1} << 30, SceneWorkerLimits{}.time});
        const QString path = writeFile(folder_, QStringLiteral("huge.dae"), test::hugeCollada());
        const QString message = failureOf(path);
        jobs_.setWorkerLimits({});
        QCOMPARE(message, path + QStringLiteral(": the scene reader needed more than 1 GiB of memory for this file "
                                                "and was stopped"));
        QVERIFY(importGood());
    }

    void aHangingWorkerIsStoppedAtTheTimeLimit()
    {
        qputenv(kSceneWorkerVariable, QFile::encodeName(hangingWorker(folder_)));
        jobs_.setWorkerLimits({SceneWorkerLimits{}.memoryBytes, std::chrono::milliseconds(500)});
        QElapsedTimer clock;
        clock.start();
        const QString message = failureOf(goodFile_);
        jobs_.setWorkerLimits({});
        QVERIFY2(message.startsWith(goodFile_ + QStringLiteral(": the scene reader took longer than 0.5 s")),
                 qPrintable(message));
        QVERIFY(clock.elapsed() >= 500);
        qputenv(kSceneWorkerVariable, builtWorker_);
        QVERIFY(importGood());
    }

    // With the default limit of minutes, only stopping the worker can end the job in seconds.
    void cancellingStopsTheWorker()
    {
        qputenv(kSceneWorkerVariable, QFile::encodeName(hangingWorker(folder_)));
        QSignalSpy cancelled(&jobs_, &SceneFileJobs::cancelled);
        QSignalSpy failed(&jobs_, &SceneFileJobs::failed);
        QVERIFY(jobs_.startImport(goodFile_));
        jobs_.cancelImport();
        QVERIFY(arrives(cancelled, 10000));
        QCOMPARE(cancelled.front().at(0).toString(), goodFile_);
        QCOMPARE(failed.count(), 0);
        QVERIFY(!jobs_.isBusy());
    }

    // cat sends the request back: a message, but not a reply.
    void aMalformedReplyFailsByName()
    {
        qputenv(kSceneWorkerVariable, "/bin/cat");
        const QString message = failureOf(goodFile_);
        QCOMPARE(message, goodFile_ + QStringLiteral(": the scene reader's reply is malformed: a request where a reply "
                                                     "was expected"));
    }

    void aMissingWorkerFailsByName()
    {
        qputenv(kSceneWorkerVariable, QFile::encodeName(folder_.filePath(QStringLiteral("no-such-worker"))));
        const QString message = failureOf(goodFile_);
        QCOMPARE(message, goodFile_ + QStringLiteral(": the scene reader %1 is missing or not executable")
                                          .arg(folder_.filePath(QStringLiteral("no-such-worker"))));
    }

    // The worker words its errors in the language the app chose; the translation is built into it.
    void theWorkerSpeaksTheAppsLanguage()
    {
        const QString missing = folder_.filePath(QStringLiteral("missing.bvh"));
        setSceneWorkerLocale(QLocale(QLocale::German, QLocale::Germany));
        const QString german = failureOf(missing);
        setSceneWorkerLocale(QLocale::c());
        QCOMPARE(german, missing + QStringLiteral(": Datei nicht vorhanden"));
        QCOMPARE(failureOf(missing), missing + QStringLiteral(": no such file"));
    }

private:
    // Points GYRE_SCENE_WORKER at a script that writes a line to a log, then becomes the built worker:
    // the log's lines count the workers started. Returns the log's path.
    QString useCountingWorker(const QString& name)
    {
        const QString log = folder_.filePath(name + QStringLiteral(".log"));
        const QByteArray script = "#!/bin/sh\necho started >> '" + QFile::encodeName(log) + "'\nexec '" +
                                  builtWorker_ + "'\n";
        const QString program = writeFile(folder_, name + QStringLiteral("-worker"), script,
                                          QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        qputenv(kSceneWorkerVariable, QFile::encodeName(program));
        return log;
    }

    static int startsIn(const QString& log)
    {
        QFile file(log);
        return file.open(QIODevice::ReadOnly) ? static_cast<int>(file.readAll().count('\n')) : 0;
    }

    // A motion capture the worker needs far longer than a millisecond to read and send.
    QString largeFile()
    {
        if (largeFile_.isEmpty())
            largeFile_ = writeFile(folder_, QStringLiteral("large.bvh"), test::bvhChain(40, 4000, 1.0 / 120.0));
        return largeFile_;
    }

    std::shared_ptr<const SceneImport> importGood()
    {
        QSignalSpy imported(&jobs_, &SceneFileJobs::imported);
        if (!jobs_.startImport(goodFile_) || !arrives(imported))
            return nullptr;
        return imported.front().at(1).value<std::shared_ptr<const SceneImport>>();
    }

    // The message of the import of `path`, which must fail.
    QString failureOf(const QString& path)
    {
        QSignalSpy failed(&jobs_, &SceneFileJobs::failed);
        QSignalSpy imported(&jobs_, &SceneFileJobs::imported);
        if (!jobs_.startImport(path))
            return QStringLiteral("refused to start");
        if (!arrives(failed))
            return QStringLiteral("no failure; imported %1 times").arg(imported.count());
        return failed.front().at(0).toString() == path ? failed.front().at(1).toString()
                                                        : QStringLiteral("failed for another path");
    }

    QTemporaryDir folder_;
    QString goodFile_;
    QString largeFile_;
    QByteArray builtWorker_;
    SceneFileJobs jobs_;
};

QTEST_GUILESS_MAIN(TestSceneFileJobs)
#include "tst_scene_file_jobs.moc"
