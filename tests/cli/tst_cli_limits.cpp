// gyre-cli against inputs that are small but ask for unbounded work, or hold values no motion can be
// evaluated from: each is refused quickly, with a non-zero exit status and a message that names the
// file and field or the option, and the number it would have needed.

#include "cli_test_support.h"

#include <QElapsedTimer>
#include <QTest>

#include <cmath>

using namespace gyre::test;

namespace {

// A project with one object, "spinner", of two keys; `fitted` is its sketch's fittedCurve and `endTime`
// the scene's end, as JSON text.
QByteArray project(const char* fitted, const char* endTime = "2")
{
    return QByteArray(R"({"format": "gyre-project", "version": 2, "fps": 24, "startTime": 0, "endTime": )") + endTime +
           R"(, "currentTime": 0, "meshes": [], "objects": [{"id": 1, "name": "spinner", "parent": null, "mesh": null,
  "interpolation": "hermite", "subdivision": {"scheme": "jarek", "levels": 4, "cyclic": true, "decoupled": false},
  "keyframes": [{"time": 0, "orientation": [1, 0, 0, 0], "position": [0, 0, 0], "constrained": true},
                {"time": 2, "orientation": [0, 0, 0, 1], "position": [0, 0, 0], "constrained": true}],
  "sketch": {"directionStrokes": [], "magnitude": [], "pattern": [], "patternRepeat": 0, "window": null,
             "alpha": 0.002, "beta": 1, "delta": 0.1, "fittedCurve": )" + fitted + "}}]}";
}

} // namespace

class TstCliLimits : public QObject {
    Q_OBJECT

private slots:
    void refusesFittedValuesWithoutDirection_data();
    void refusesFittedValuesWithoutDirection();
    void refusesUnboundedRatesAndTimes();
    void refusesUnboundedFits();

private:
    QString path(const QString& name) const { return directory_.filePath(name); }
    QString writeFile(const QString& name, const QByteArray& contents) const
    {
        QFile file(path(name));
        if (!file.open(QIODevice::WriteOnly) || file.write(contents) != contents.size())
            qFatal("cannot write %s", qPrintable(name));
        return path(name);
    }
    // Runs gyre-cli, which must fail with `status` within a few seconds, its message containing `message`.
    static bool refuses(const QStringList& arguments, int status, const QString& message)
    {
        QElapsedTimer clock;
        clock.start();
        const CliRun run = runCli(arguments);
        if (run.exitedNormally && run.exitCode == status && run.err.contains(message) && clock.elapsed() < 10'000)
            return true;
        qWarning("exit %d after %lld ms: %s", run.exitCode, static_cast<long long>(clock.elapsed()), qPrintable(run.err));
        return false;
    }

    QTemporaryDir directory_;
};

void TstCliLimits::refusesFittedValuesWithoutDirection_data()
{
    QTest::addColumn<QByteArray>("fitted");
    QTest::addColumn<QString>("message");
    const auto curve = [](const char* value, const char* derivative) {
        return QByteArray(R"([{"time": 0, "value": [1, 0, 0, 0], "derivative": [0, 0, 0, 0]}, {"time": 1, "value": )") +
               value + R"(, "derivative": )" + derivative + "}]";
    };
    QTest::newRow("zero") << curve("[0, 0, 0, 0]", "[0, 0, 0, 0]")
                          << "objects[0].sketch.fittedCurve[1].value: the value has length 0";
    QTest::newRow("denormal") << curve("[1e-300, 0, 0, 0]", "[0, 0, 0, 0]")
                              << "objects[0].sketch.fittedCurve[1].value: the value has length ";
    QTest::newRow("huge derivative") << curve("[1, 0, 0, 0]", "[0, 1e300, 0, 0]")
                                     << "objects[0].sketch.fittedCurve[1].derivative: the derivative has length 1e+300";
}

// bake and export once wrote zero quaternions and exited 0, or failed naming neither file nor field.
void TstCliLimits::refusesFittedValuesWithoutDirection()
{
    QFETCH(QByteArray, fitted);
    QFETCH(QString, message);
    const QString file = writeFile("fitted.gyre", project(fitted.constData()));
    QVERIFY(refuses({"bake", file, "--object", "spinner", "--fps", "24", "-o", path("frames.csv")}, 1, file + ": " + message));
    QVERIFY(refuses({"export", file, "-o", path("scene.gltf")}, 1, file + ": " + message));
    QVERIFY(!QFile::exists(path("frames.csv")));
    QVERIFY(!QFile::exists(path("scene.gltf")));
}

void TstCliLimits::refusesUnboundedRatesAndTimes()
{
    const QString file = writeFile("plain.gyre", project("[]"));
    QVERIFY(refuses({"export", file, "-o", path("scene.gltf"), "--fps", "1e20"}, 2, "--fps: a frame rate of 1e+20 is above 1000"));
    QVERIFY(refuses({"bake", file, "--object", "spinner", "--fps", "1e20", "-o", path("frames.csv")}, 2,
                    "--fps: a frame rate of 1e+20 is above 1000"));
    const QString late = writeFile("late.gyre", project("[]", "1e300"));
    QVERIFY(refuses({"export", late, "-o", path("scene.gltf")}, 1, late + ": endTime: time 1e+300 is beyond ±1e+06 s"));
}

void TstCliLimits::refusesUnboundedFits()
{
    QString keys = QStringLiteral("time,qw,qx,qy,qz\n");
    for (int i = 0; i <= 8; ++i) {
        const double t = 0.5 * i;
        keys += QStringList{number(t), number(std::cos(0.75 * t)), "0", "0", number(std::sin(0.75 * t))}.join(',') + '\n';
    }
    const QString spin = writeFile("spin.csv", keys.toUtf8());
    const QString omega = writeFile("omega.csv", "time,wx,wy,wz\n0,0,0,1.5\n4,0,0,1.5\n");
    QVERIFY(refuses({"fit", spin, "--omega", omega, "--fragment", "1e-9", "--fps", "30", "-o", path("fit.csv")}, 2,
                    "--fragment: a window of 4 s in fragments of 1e-09 s makes 4e+09 fragments; the budget is 1e+05"));
    const QString arc = writeFile("arc.csv", "x,y,z\n0,0.2588190451025208,0.9659258262890683\n0.2588190451025208,0,0.9659258262890683\n");
    const QString magnitude = writeFile("magnitude.csv", "time,magnitude\n0,1.5\n4,1.5\n");
    const QString zigzag = writeFile("zigzag.csv", "x,y\n0,0\n1,1\n2,-1\n3,0\n");
    QVERIFY(refuses({"fit", spin, "--direction", arc, "--magnitude", magnitude, "--pattern", zigzag, "--repeat",
                     "1000000000", "--fps", "30", "-o", path("fit.csv")},
                    2, "--repeat: 1000000000 repeats of a pattern of 4 points make 3000000001 points; the budget is 1048576"));
}

QTEST_GUILESS_MAIN(TstCliLimits)
#include "tst_cli_limits.moc"
