// gyre-cli fit as a pipeline sees it: fixtures of a nutating top written here (fit_test_support.h),
// the real binary run on them, and its output read back with the tests' own parser.

#include "cli_test_support.h"
#include "fit_test_support.h"

#include <QDir>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace gyre::test;

namespace {

constexpr double kDuration = 4.2;
constexpr double kKeySpacing = 0.3;

double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    return a.normalized().angularDistance(b.normalized());
}

QByteArray keysCsv(const NutatingTop& top)
{
    QString text = QStringLiteral("time,qw,qx,qy,qz,x,y,z\n");
    for (const gyre::fit::FitKey& key : top.keys(kDuration, kKeySpacing)) {
        const Eigen::Quaterniond& q = key.rotation;
        // Positions along a line, so that the output's positions can be checked too.
        text += QStringList{number(key.time), number(q.w()), number(q.x()), number(q.y()), number(q.z()),
                            number(2.0 * key.time), "0", "1"}
                    .join(',') +
                '\n';
    }
    return text.toUtf8();
}

QByteArray omegaCsv(const NutatingTop& top, double start, double end)
{
    QString text = QStringLiteral("time,wx,wy,wz\n");
    const int count = static_cast<int>(std::lround((end - start) * 240.0));
    for (int i = 0; i <= count; ++i) {
        const double t = start + (end - start) * i / count;
        const Eigen::Vector3d w = top.angularVelocity(t);
        text += QStringList{number(t), number(w.x()), number(w.y()), number(w.z())}.join(',') + '\n';
    }
    return text.toUtf8();
}

} // namespace

// The fit verb has nothing to warn about: every run here refuses a message on standard error.
class TstCliFit : public CliTestCase {
    Q_OBJECT

private slots:
    void initTestCase();
    void omegaTargetFollowsTheTop();
    void fpsChangesOnlyTheOutput();
    void windowKeepsTheOutside();
    void freedKeysMove();
    void sketchOfASteadySpin();
    void patternAddsWobble();
    void badInput_data();
    void badInput();
};

void TstCliFit::initTestCase()
{
    QVERIFY(dir_.isValid());
    const NutatingTop top;
    writeFile("keys.csv", keysCsv(top));
    writeFile("omega.csv", omegaCsv(top, 0.0, kDuration));
}

void TstCliFit::omegaTargetFollowsTheTop()
{
    const NutatingTop top;
    QVERIFY(succeeds({"fit", path("keys.csv"), "--omega", path("omega.csv"), "-o", path("frames.csv"), "--fps", "24",
                      "--report", path("report.json")}, Warnings::Refused));
    const Csv frames = readCsv(path("frames.csv"));
    QVERIFY2(frames.problem.isEmpty(), qPrintable(frames.problem));
    QCOMPARE(frames.header, QStringList({"time", "qw", "qx", "qy", "qz", "x", "y", "z"}));
    // 101 frames at k/24 s up to 4.2 s and 15 keys 0.3 s apart, of which those at 0, 1.5 and 3 s fall
    // on frames.
    QCOMPARE(frames.rows.size(), std::size_t{101 + 15 - 3});
    double largestAngle = 0.0;
    for (std::size_t row = 0; row < frames.rows.size(); ++row) {
        const double t = frames.at(row, "time");
        largestAngle = std::max(largestAngle, angleBetween(frames.quaternion(row), top.rotation(t)));
        QVERIFY(std::abs(frames.at(row, "x") - 2.0 * t) < 1e-12);  // the line of key positions, untouched
        const double keyIndex = t / kKeySpacing;
        if (std::abs(keyIndex - std::round(keyIndex)) < 1e-9)
            QVERIFY(angleBetween(frames.quaternion(row), top.rotation(t)) < 1e-9);
    }
    QVERIFY2(largestAngle < 1.5 * std::numbers::pi / 180.0, qPrintable(QString::number(largestAngle)));

    QFile reportFile(path("report.json"));
    QVERIFY(reportFile.open(QIODevice::ReadOnly));
    const QJsonObject report = QJsonDocument::fromJson(reportFile.readAll()).object();
    QCOMPARE(report["outcome"].toString(), QStringLiteral("converged"));
    QVERIFY(report["converged"].toBool());
    QVERIFY(report["rounds"].toInt() >= 1);
    QVERIFY(report["iterations"].toInt() >= 1);
    QVERIFY(report["variableFrames"].toInt() >= 0);
    QVERIFY(report["largestRelativeError"].toDouble() <= 0.1);
    QCOMPARE(report["largestRelativeError"].toDouble(),
             report["largestFragmentError"].toDouble() / report["targetMeanSquare"].toDouble());
    QVERIFY(!report.contains("drawnErrorBefore"));  // ω samples are the target; nothing was drawn
    QVERIFY(report["solveSeconds"].toDouble() > 0.0);
    QVERIFY(report["largestNormDeviation"].toDouble() < 1e-3);
    const QJsonObject before = report["energyBefore"].toObject();
    const QJsonObject after = report["energyAfter"].toObject();
    QVERIFY(after["angular"].toDouble() < 0.1 * before["angular"].toDouble());
    QCOMPARE(after["total"].toDouble(), 0.002 * after["tangential"].toDouble() + after["angular"].toDouble());
}

void TstCliFit::fpsChangesOnlyTheOutput()
{
    QVERIFY(succeeds({"fit", path("keys.csv"), "--omega", path("omega.csv"), "-o", path("at24.csv"), "--fps", "24"}, Warnings::Refused));
    QVERIFY(succeeds({"fit", path("keys.csv"), "--omega", path("omega.csv"), "-o", path("at60.csv"), "--fps", "60"}, Warnings::Refused));
    const Csv at24 = readCsv(path("at24.csv"));
    const Csv at60 = readCsv(path("at60.csv"));
    int shared = 0;
    for (std::size_t a = 0; a < at24.rows.size(); ++a)
        for (std::size_t b = 0; b < at60.rows.size(); ++b)
            if (at24.at(a, "time") == at60.at(b, "time")) {
                QCOMPARE(at24.quaternion(a).coeffs(), at60.quaternion(b).coeffs());
                ++shared;
            }
    QVERIFY(shared >= 15);  // the keys and the frames at multiples of 1/12 s
}

void TstCliFit::windowKeepsTheOutside()
{
    QVERIFY(succeeds({"fit", path("keys.csv"), "--omega", path("omega.csv"), "-o", path("window.csv"), "--fps", "24",
                      "--window", "1.1,2.95"}, Warnings::Refused));
    // Outside the window the motion is the Hermite spline through the keys, as interpolate gives it.
    QVERIFY(succeeds({"interpolate", path("keys.csv"), "-o", path("hermite.csv"), "--fps", "24", "--method", "hermite"}, Warnings::Refused));
    const Csv fitted = readCsv(path("window.csv"));
    const Csv plain = readCsv(path("hermite.csv"));
    QCOMPARE(fitted.rows.size(), plain.rows.size());
    bool changedInside = false;
    for (std::size_t row = 0; row < fitted.rows.size(); ++row) {
        const double t = fitted.at(row, "time");
        const double difference = angleBetween(fitted.quaternion(row), plain.quaternion(row));
        if (t < 1.1 || t > 2.95)
            QVERIFY2(difference < 1e-12, qPrintable(QStringLiteral("t = %1: %2").arg(t).arg(difference)));
        else
            changedInside = changedInside || difference > 1e-3;
    }
    QVERIFY(changedInside);
}

void TstCliFit::freedKeysMove()
{
    // Keys from a top without nutation and the nutating top's ω: constrained keys stay, freed ones follow ω.
    NutatingTop steady;
    steady.nutation = 0.0;
    const QString keys = writeFile("steady.csv", keysCsv(steady));
    QVERIFY(succeeds({"fit", keys, "--omega", path("omega.csv"), "-o", path("freed.csv"), "--fps", "24", "--free",
                      "2,3,5"}, Warnings::Refused));
    const Csv frames = readCsv(path("freed.csv"));
    for (std::size_t row = 0; row < frames.rows.size(); ++row) {
        const double t = frames.at(row, "time");
        const double keyIndex = t / kKeySpacing;
        if (std::abs(keyIndex - std::round(keyIndex)) > 1e-9)
            continue;
        const long index = std::lround(keyIndex);
        const double moved = angleBetween(frames.quaternion(row), steady.rotation(t));
        if (index == 2 || index == 3 || index == 5)
            QVERIFY2(moved > 1e-4, qPrintable(QStringLiteral("key %1 moved %2").arg(index).arg(moved)));
        else
            QVERIFY2(moved < 1e-9, qPrintable(QStringLiteral("key %1 moved %2").arg(index).arg(moved)));
    }
}

void TstCliFit::sketchOfASteadySpin()
{
    // Keys of a steady turn about z at 1.5 rad/s, and the sketch of exactly that: the direction z
    // (untimed, one point) times a constant magnitude. The fit must keep the steady turn.
    QString keys = QStringLiteral("time,qw,qx,qy,qz\n");
    for (int i = 0; i <= 8; ++i) {
        const double t = 0.5 * i;
        keys += QStringList{number(t), number(std::cos(0.75 * t)), "0", "0", number(std::sin(0.75 * t))}.join(',') + '\n';
    }
    writeFile("spin.csv", keys.toUtf8());
    writeFile("direction.csv", "x,y,z\n0,0,1\n");
    writeFile("magnitude.csv", "time,magnitude\n0,1.5\n4,1.5\n");
    QVERIFY(succeeds({"fit", path("spin.csv"), "--direction", path("direction.csv"), "--magnitude",
                      path("magnitude.csv"), "-o", path("spin-fit.csv"), "--fps", "30"}, Warnings::Refused));
    const Csv frames = readCsv(path("spin-fit.csv"));
    for (std::size_t row = 0; row < frames.rows.size(); ++row) {
        const double t = frames.at(row, "time");
        const Eigen::Quaterniond expected(std::cos(0.75 * t), 0.0, 0.0, std::sin(0.75 * t));
        QVERIFY2(angleBetween(frames.quaternion(row), expected) < 1e-3, qPrintable(QString::number(t)));
    }
}

void TstCliFit::patternAddsWobble()
{
    // The same sketch with a zigzag repeated along a direction arc: the motion leaves the plain turn.
    writeFile("arc.csv", "x,y,z\n0,0.2588190451025208,0.9659258262890683\n0.2588190451025208,0,0.9659258262890683\n");
    writeFile("zigzag.csv", "x,y\n0,0\n1,1\n2,-1\n3,0\n");
    QVERIFY(succeeds({"fit", path("spin.csv"), "--direction", path("arc.csv"), "--magnitude", path("magnitude.csv"),
                      "-o", path("plain.csv"), "--fps", "30"}, Warnings::Refused));
    QVERIFY(succeeds({"fit", path("spin.csv"), "--direction", path("arc.csv"), "--magnitude", path("magnitude.csv"),
                      "--pattern", path("zigzag.csv"), "--repeat", "4", "-o", path("wobble.csv"), "--fps", "30"}, Warnings::Refused));
    const Csv plain = readCsv(path("plain.csv"));
    const Csv wobble = readCsv(path("wobble.csv"));
    QCOMPARE(plain.rows.size(), wobble.rows.size());
    double largest = 0.0;
    for (std::size_t row = 0; row < plain.rows.size(); ++row)
        largest = std::max(largest, angleBetween(plain.quaternion(row), wobble.quaternion(row)));
    QVERIFY2(largest > 1e-3, qPrintable(QString::number(largest)));
}

void TstCliFit::badInput_data()
{
    QTest::addColumn<QStringList>("arguments");  // KEYS, OMEGA, OUT, REPORT stand for the files
    QTest::addColumn<QByteArray>("extra");       // the contents of EXTRA, where an argument names it
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("message");
    const QStringList fit{"fit", "KEYS", "-o", "OUT", "--fps", "24", "--report", "REPORT"};
    const QStringList omega = fit + QStringList{"--omega", "OMEGA"};
    const QStringList extraOmega = fit + QStringList{"--omega", "EXTRA"};
    const QStringList sketch = fit + QStringList{"--direction", "EXTRA", "--magnitude", "MAGNITUDE"};

    QTest::newRow("target outside the keys") << extraOmega << QByteArray("time,wx,wy,wz\n-1,0,0,1\n2,0,0,1\n") << 1
                                             << "KEYS: cannot fit: the target [-1.000000, 2.000000] s reaches outside";
    QTest::newRow("nan in the target") << extraOmega << QByteArray("time,wx,wy,wz\n0,0,0,1\n1,nan,0,1\n") << 1
                                       << "EXTRA:3: column wx: 'nan' is not a finite number";
    QTest::newRow("one target sample") << extraOmega << QByteArray("time,wx,wy,wz\n0,0,0,1\n") << 1
                                       << "EXTRA:2: an angular-velocity target needs at least two samples";
    QTest::newRow("target times") << extraOmega << QByteArray("time,wx,wy,wz\n1,0,0,1\n0.5,0,0,1\n") << 1
                                  << "EXTRA:3: column time: 0.5 does not come after 1 on line 2";
    QTest::newRow("one key") << QStringList{"fit", "EXTRA", "-o", "OUT", "--fps", "24", "--omega", "OMEGA"}
                             << QByteArray("time,qw,qx,qy,qz\n0,1,0,0,0\n") << 1 << "EXTRA:2: fit needs at least two keys";
    QTest::newRow("window outside the keys") << omega + QStringList{"--window", "1,9"} << QByteArray() << 1
                                             << "lies outside the keys' span";
    QTest::newRow("window reversed") << omega + QStringList{"--window", "2,1"} << QByteArray() << 2
                                     << "fit: --window: give two times ta,tb with ta < tb";
    QTest::newRow("direction off the sphere") << sketch << QByteArray("x,y,z\n0,0,1\n0,0.5,0.5\n") << 1
                                              << "EXTRA:3: x,y,z has length 0.7071067811865476";
    QTest::newRow("non-positive magnitude")
        << fit + QStringList{"--direction", "DIRECTION", "--magnitude", "EXTRA"}
        << QByteArray("time,magnitude\n0,1\n1,-2\n") << 1 << "EXTRA:3: column magnitude: -2 is not positive";
    QTest::newRow("free out of range") << omega + QStringList{"--free", "1,99"} << QByteArray() << 2
                                       << "fit: --free: '99' is not a key index from 0 to 14";
    QTest::newRow("two targets") << omega + QStringList{"--direction", "DIRECTION"} << QByteArray() << 2
                                 << "fit: give the target as either --omega or a sketch, --direction and/or --magnitude";
    QTest::newRow("no target") << fit << QByteArray() << 2
                               << "fit: give the target as either --omega or a sketch, --direction and/or --magnitude";
    QTest::newRow("pattern without repeat") << sketch + QStringList{"--pattern", "PATTERN"}
                                            << QByteArray("x,y,z\n0,0,1\n") << 2
                                            << "fit: --pattern and --repeat go together";
    QTest::newRow("pattern without direction")
        << fit + QStringList{"--magnitude", "MAGNITUDE", "--pattern", "PATTERN", "--repeat", "2"} << QByteArray() << 2
        << "fit: --pattern follows the direction curve: give --direction too";
    QTest::newRow("object of a keys file") << omega + QStringList{"--object", "top"} << QByteArray() << 2
                                           << "fit: --object names an object of a project (a .gyre file)";
    QTest::newRow("negative alpha") << omega + QStringList{"--alpha", "-1"} << QByteArray() << 2 << "fit: --alpha: must be ≥ 0";
    QTest::newRow("zero delta") << omega + QStringList{"--delta", "0"} << QByteArray() << 2
                                << "fit: --delta: '0' is not positive";
}

// Every bad input: a message naming the file or option, a non-zero status, and neither output file.
void TstCliFit::badInput()
{
    QFETCH(QStringList, arguments);
    QFETCH(QByteArray, extra);
    QFETCH(int, exitCode);
    QFETCH(QString, message);
    writeFile("extra.csv", extra);
    writeFile("direction.csv", "x,y,z\n0,0,1\n");
    writeFile("magnitude.csv", "time,magnitude\n0,1.5\n4,1.5\n");
    writeFile("pattern.csv", "x,y\n0,0\n1,1\n2,0\n");
    const QList<std::pair<QString, QString>> names{{"KEYS", path("keys.csv")},   {"OMEGA", path("omega.csv")},
                                                   {"OUT", path("out.csv")},     {"REPORT", path("report-out.json")},
                                                   {"EXTRA", path("extra.csv")}, {"DIRECTION", path("direction.csv")},
                                                   {"MAGNITUDE", path("magnitude.csv")},
                                                   {"PATTERN", path("pattern.csv")}};
    for (const auto& [name, file] : names) {
        arguments.replaceInStrings(QRegularExpression("^" + name + "$"), file);
        message.replace(name, file);
    }
    QFile::remove(path("out.csv"));
    QFile::remove(path("report-out.json"));
    const CliRun run = runCli(arguments);
    QVERIFY(run.exitedNormally);
    QCOMPARE(run.exitCode, exitCode);
    QVERIFY2(run.err.startsWith("gyre-cli: ") && run.err.count('\n') == 1, qPrintable(run.err));
    QVERIFY2(run.err.contains(message), qPrintable(run.err));
    QVERIFY(!QFile::exists(path("out.csv")));
    QVERIFY(!QFile::exists(path("report-out.json")));
}

QTEST_GUILESS_MAIN(TstCliFit)
#include "tst_cli_fit.moc"
