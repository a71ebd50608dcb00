// gyre-cli reads scene files through gyre-scene-worker: a file that crashes Assimp ends the verb with
// a message naming the file and status 1, not with the signal, and writes nothing.

#include "cli_test_support.h"
#include "io/damaged_scenes.h"

#include <QDir>
#include <QTest>

using namespace gyre::test;

class TstCliSceneWorker : public QObject {
    Q_OBJECT

private slots:
    void aSceneThatCrashesTheReaderFailsByName_data()
    {
        QTest::addColumn<QStringList>("arguments"); // IN and OUT stand for the files
        QTest::newRow("import") << QStringList{"import", "IN", "-o", "OUT"};
        QTest::newRow("info") << QStringList{"info", "IN"};
    }

    void aSceneThatCrashesTheReaderFailsByName()
    {
        QFETCH(QStringList, arguments);
        QTemporaryDir folder;
        const QString in = folder.filePath(QStringLiteral("crash.dae"));
        const QString out = folder.filePath(QStringLiteral("crash.gyre"));
        QFile file(in);
        const QByteArray contents = crashingCollada();
        QVERIFY(file.open(QIODevice::WriteOnly) && file.write(contents) == contents.size());
        file.close();
        arguments.replaceInStrings(QStringLiteral("IN"), in).replaceInStrings(QStringLiteral("OUT"), out);
        const CliRun run = runCli(arguments);
        QVERIFY(run.exitedNormally);
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.err.startsWith("gyre-cli: " + in + ": the scene reader crashed on this file (signal " +
                                    kCrashSignal) &&
                     run.err.count('\n') == 1,
                 qPrintable(run.err));
        QCOMPARE(run.out, QString());
        QCOMPARE(QDir(folder.path()).entryList(QDir::Files), QStringList{QStringLiteral("crash.dae")});
    }
};

QTEST_GUILESS_MAIN(TstCliSceneWorker)
#include "tst_cli_scene_worker.moc"
