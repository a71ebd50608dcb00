// gyre-cli import and info on the files Blender 3.4 exported with its default settings
// (tests/data, made by tests/interop/make_fixtures.py): the takes are listed, Blender's FBX takes give
// each object its own action and say so, overlapping animations are refused until --animation
// chooses, and the import options change what the file says.

#include "cli_test_support.h"

#include <QFileInfo>
#include <QTest>

#include <cmath>

namespace gyre::test {

namespace {

QString dataFile(const char* name) { return QStringLiteral(GYRE_TEST_DATA "/") + QLatin1String(name); }

const char* const kFbx = "blender_three_objects.fbx";
const char* const kGlb = "blender_three_objects.glb";
const char* const kTwoActions = "blender_two_actions.glb";

} // namespace

class TstCliImport : public CliTestCase {
    Q_OBJECT

private slots:
    void infoListsEveryTakeAndWhatItMoves();
    void blenderTakesGiveEachObjectItsOwnAction();
    void overlappingAnimationsAreRefusedUntilChosen();
    void optionsChangeWhatTheFileSays();
    void badOptionsAreRefused_data();
    void badOptionsAreRefused();

private:
    // The rows of `object`'s keys in the project `project`.
    Csv keysOf(const QString& project, const char* object)
    {
        const QString out = path(QStringLiteral("%1-keys.csv").arg(object));
        if (!succeeds({"keys", project, "--object", object, "-o", out}))
            return {};
        return readCsv(out);
    }
};

void TstCliImport::infoListsEveryTakeAndWhatItMoves()
{
    const CliRun info = runCli({"info", dataFile(kFbx)});
    QCOMPARE(info.exitCode, 0);
    QVERIFY2(info.out.contains("9 animations:\n"), qPrintable(info.out));
    for (const char* take : {"  0: 'Quat|ChildZXYAction', 0.3333333333333333 s, moves Quat\n",
                             "  2: 'Quat|QuatAction', 0.3333333333333333 s, moves Quat (imported)\n",
                             "  4: 'EulerXYZ|EulerXYZAction', 0.3333333333333333 s, moves EulerXYZ (imported)\n",
                             "  6: 'ChildZXY|ChildZXYAction', 0.3333333333333333 s, moves ChildZXY (imported)\n",
                             "  8: 'ChildZXY|QuatAction', 0.3333333333333333 s, moves ChildZXY\n"})
        QVERIFY2(info.out.contains(QString::fromUtf8(take)), qPrintable(info.out));
    QVERIFY2(info.out.contains("imported: 2, 4, 6, Blender's takes"), qPrintable(info.out));
    QVERIFY2(info.out.contains("import settings: 30 fps (the FBX time mode), 1 unit = 0.01 m (the FBX UnitScaleFactor, "
                               "1 cm), Y-up turned Z-up (the FBX UpAxis)\n"),
             qPrintable(info.out));
    QVERIFY2(info.out.contains("time range: 0 to 0.3333333333333333 s at 30 fps\n"), qPrintable(info.out));

    const CliRun glb = runCli({"info", dataFile(kGlb)});
    QCOMPARE(glb.exitCode, 0);
    QVERIFY2(glb.out.contains("imported: all of them, merged"), qPrintable(glb.out));
    QVERIFY2(glb.out.contains("30 fps (every key is on a frame of 30 fps)"), qPrintable(glb.out));
}

void TstCliImport::blenderTakesGiveEachObjectItsOwnAction()
{
    const QString project = path("three.gyre");
    const CliRun run = runCli({"import", dataFile(kFbx), "-o", project});
    QCOMPARE(run.exitCode, 0);
    for (const char* said : {"'Quat' plays take 2 'Quat|QuatAction'", "'EulerXYZ' plays take 4 'EulerXYZ|EulerXYZAction'",
                             "'ChildZXY' plays take 6 'ChildZXY|ChildZXYAction'"})
        QVERIFY2(run.err.contains(QString::fromUtf8(said)), qPrintable(run.err));
    QVERIFY2(run.err.contains("gyre-cli: imported at 30 fps (the FBX time mode)"), qPrintable(run.err));
    const CliRun info = runCli({"info", project});
    QVERIFY2(info.out.contains("at 30 fps\n"), qPrintable(info.out)); // the project keeps the file's rate
    // Every object moves: its last key is another orientation than its first.
    for (const char* object : {"Quat", "EulerXYZ", "ChildZXY"}) {
        const Csv keys = keysOf(project, object);
        QCOMPARE(keys.rows.size(), std::size_t{11});
        QVERIFY2(keys.quaternion(0).angularDistance(keys.quaternion(10)) > 0.3, object);
    }
}

void TstCliImport::overlappingAnimationsAreRefusedUntilChosen()
{
    const QString project = path("wheel.gyre");
    const CliRun refused = runCli({"import", dataFile(kTwoActions), "-o", project});
    QCOMPARE(refused.exitCode, 2);
    for (const char* said : {"has 2 animations that move the same nodes; choose with --animation",
                             "  0: 'Spin', 0.36666668701171873 s, moves Wheel", "  1: 'Wobble', 0.36666668701171873 s, moves Wheel"})
        QVERIFY2(refused.err.contains(QString::fromUtf8(said)), qPrintable(refused.err));
    QVERIFY(!QFileInfo::exists(project));

    // Spin turns 180° about Blender's Z; Wobble tilts 30° and back.
    QVERIFY(succeeds({"import", dataFile(kTwoActions), "-o", project, "--animation", "0"}));
    Csv keys = keysOf(project, "Wheel");
    QVERIFY(std::abs(keys.quaternion(0).angularDistance(keys.quaternion(keys.rows.size() - 1)) - M_PI) < 1e-3);
    QVERIFY(succeeds({"import", dataFile(kTwoActions), "-o", project, "--animation", "1"}));
    keys = keysOf(project, "Wheel");
    QVERIFY(keys.quaternion(0).angularDistance(keys.quaternion(keys.rows.size() - 1)) < 1e-3);
    const CliRun all = runCli({"import", dataFile(kTwoActions), "-o", project, "--animation", "all"});
    QCOMPARE(all.exitCode, 0);
    QVERIFY2(all.err.contains("node 'Wheel' is moved by more than one of the chosen animations; the later one, "
                              "'Wobble', is used"),
             qPrintable(all.err));

    const CliRun missing = runCli({"import", dataFile(kTwoActions), "-o", path("none.gyre"), "--animation", "0,5"});
    QCOMPARE(missing.exitCode, 1);
    QVERIFY2(missing.err.contains("there is no animation 5"), qPrintable(missing.err));
}

void TstCliImport::optionsChangeWhatTheFileSays()
{
    const QString asFile = path("as-file.gyre");
    const QString asked = path("asked.gyre");
    QVERIFY(succeeds({"import", dataFile(kFbx), "-o", asFile}));
    const CliRun run = runCli({"import", dataFile(kFbx), "-o", asked, "--fps", "60", "--unit", "1", "--up", "z"});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.err.contains("imported at 60 fps (as asked; the file says 30 fps), 1 unit = 1 m (as asked; the file "
                              "says 0.01 m), Z-up (as asked; the file says Y-up)"),
             qPrintable(run.err));
    QVERIFY(runCli({"info", asked}).out.contains("at 60 fps\n"));
    // The child's keys are relative to its parent, so neither the turn nor the rate changes them; the
    // unit scales its position 100 times.
    const Csv before = keysOf(asFile, "ChildZXY");
    const Csv after = keysOf(asked, "ChildZXY");
    QCOMPARE(after.rows.size(), before.rows.size());
    for (std::size_t row = 0; row < before.rows.size(); ++row) {
        QCOMPARE(after.at(row, "time"), before.at(row, "time"));
        QVERIFY((after.position(row) - 100.0 * before.position(row)).norm() < 1e-9);
    }

    // Blender's glb puts frame 1 at 1/30 s; the default moves it to 0, --time-origin file keeps it.
    const QString fileTimes = path("file-times.gyre");
    QVERIFY(succeeds({"import", dataFile(kGlb), "-o", fileTimes, "--time-origin", "file"}));
    QVERIFY(std::abs(keysOf(fileTimes, "Quat").at(0, "time") - 1.0 / 30.0) < 1e-7);
    QVERIFY(succeeds({"import", dataFile(kGlb), "-o", fileTimes}));
    QCOMPARE(keysOf(fileTimes, "Quat").at(0, "time"), 0.0);
}

void TstCliImport::badOptionsAreRefused_data()
{
    QTest::addColumn<QStringList>("options");
    QTest::addColumn<QString>("message");
    QTest::newRow("animation word") << QStringList{"--animation", "first"} << "--animation: 'first' is not all";
    QTest::newRow("animation negative") << QStringList{"--animation", "-1"} << "--animation: '-1' is not all";
    QTest::newRow("fps 0") << QStringList{"--fps", "0"} << "--fps: '0' is not positive";
    QTest::newRow("unit negative") << QStringList{"--unit", "-0.01"} << "--unit: '-0.01' is not positive";
    QTest::newRow("up x") << QStringList{"--up", "x"} << "--up: unknown value 'x'; expected y or z";
    QTest::newRow("time origin") << QStringList{"--time-origin", "later"}
                                 << "--time-origin: unknown value 'later'; expected zero or file";
}

void TstCliImport::badOptionsAreRefused()
{
    QFETCH(QStringList, options);
    QFETCH(QString, message);
    const QString project = path("bad.gyre");
    const CliRun run = runCli(QStringList{"import", dataFile(kFbx), "-o", project} + options);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains(message), qPrintable(run.err));
    QVERIFY(!QFileInfo::exists(project));
}

} // namespace gyre::test

QTEST_GUILESS_MAIN(gyre::test::TstCliImport)
#include "tst_cli_import.moc"
