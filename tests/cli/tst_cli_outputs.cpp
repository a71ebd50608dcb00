// gyre-cli's outputs and inputs at their edges: a FIFO or a device named by -o is written in place and
// stays what it is, -o - is standard output, an output that names an input is refused before anything
// is touched, and a CSV file past the row budget is refused with its line and the budget.

#include "cli_test_support.h"
#include "io/csv_line_reader.h"

#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTest>

#include <sys/stat.h>

#include <cmath>
#include <numbers>
#include <string>

using namespace gyre;
using namespace gyre::io;
using namespace gyre::test;

namespace {

const QByteArray kKeys = "time,qw,qx,qy,qz,x,y,z\n"
                         "0,1,0,0,0,0,0,0\n"
                         "0.5,0.7071067811865476,0,0.7071067811865476,0,1,0,0\n"
                         "1.25,0,0,0,1,2,1,0\n";

QByteArray contentsOf(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray("(cannot read)");
}

// The file's type as lstat sees it, so that a FIFO or a device replaced by a regular file shows.
mode_t fileType(const QString& path)
{
    struct stat status{};
    if (::lstat(QFile::encodeName(path).constData(), &status) != 0)
        return 0;
    return status.st_mode & S_IFMT;
}

} // namespace

class TstCliOutputs : public CliTestCase {
    Q_OBJECT

private slots:
    void fifoIsWrittenThrough();
    void devNullStaysACharacterDevice();
    void dashIsStandardOutput();
    void symlinkedOutputReplacesItsTarget();
    void outputNamingAnInputIsRefused_data();
    void outputNamingAnInputIsRefused();
    void convertMayRewriteItsInput();
    void eulerOutputUnwrapsAcrossBlocks();
    void rowsPastTheBudgetAreRefused();
    void rowCountStopsAtTheBudget();

private:
    // What convert writes for kKeys into a regular file: the bytes every other target must receive.
    QByteArray convertedToMatrix()
    {
        const QString in = writeFile("reference-in.csv", kKeys);
        const QString out = path("reference-out.csv");
        if (!succeeds({"convert", in, "-o", out, "--to", "matrix"}))
            return {};
        return contentsOf(out);
    }

    bool fifoPassed_ = false;
};

void TstCliOutputs::fifoIsWrittenThrough()
{
    const QByteArray expected = convertedToMatrix();
    QVERIFY(!expected.isEmpty());
    const QString in = writeFile("in.csv", kKeys);
    const QString fifo = path("out.fifo");
    QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);

    // The reader opens the FIFO first and gets everything written until the writer closes it.
    QProcess reader;
    reader.start(QStringLiteral("cat"), {fifo});
    QVERIFY(reader.waitForStarted());
    QVERIFY(succeeds({"convert", in, "-o", fifo, "--to", "matrix"}));
    QVERIFY(reader.waitForFinished(60'000));
    QCOMPARE(reader.readAllStandardOutput(), expected);
    QCOMPARE(fileType(fifo), mode_t{S_IFIFO});
    fifoPassed_ = true;
}

void TstCliOutputs::devNullStaysACharacterDevice()
{
    // Replacing /dev/null would break the machine the test runs on (as root QSaveFile could rename
    // over it), so this runs only once a FIFO has been shown to be written in place.
    if (!fifoPassed_)
        QSKIP("the FIFO was not written in place; /dev/null is not put at risk");
    if (fileType(QStringLiteral("/dev/null")) != S_IFCHR)
        QSKIP("/dev/null is not a character device here");
    const QString in = writeFile("in.csv", kKeys);
    QVERIFY(succeeds({"convert", in, "-o", "/dev/null", "--to", "euler"}));
    QCOMPARE(fileType(QStringLiteral("/dev/null")), mode_t{S_IFCHR});
}

void TstCliOutputs::dashIsStandardOutput()
{
    const QByteArray expected = convertedToMatrix();
    QVERIFY(!expected.isEmpty());
    const QString in = writeFile("in.csv", kKeys);
    const CliRun run = runCli({"convert", in, "-o", "-", "--to", "matrix"});
    QVERIFY(run.exitedNormally);
    QCOMPARE(run.exitCode, 0);
    QCOMPARE(run.out.toUtf8(), expected);
    QVERIFY(!QFileInfo::exists(path("-")));

    // export alone cannot: the extension names the scene format.
    const CliRun scene = runCli({"export", path("none.gyre"), "-o", "-"});
    QCOMPARE(scene.exitCode, 2);
    QVERIFY2(scene.err.contains("export: -o -: a scene is written to a file"), qPrintable(scene.err));
}

void TstCliOutputs::symlinkedOutputReplacesItsTarget()
{
    const QByteArray expected = convertedToMatrix();
    QVERIFY(!expected.isEmpty());
    const QString in = writeFile("in.csv", kKeys);
    const QString target = writeFile("target.csv", "old contents\n");
    const QString link = path("link.csv");
    QVERIFY(QFile::link(target, link));
    QVERIFY(succeeds({"convert", in, "-o", link, "--to", "matrix"}));
    QCOMPARE(fileType(link), mode_t{S_IFLNK});
    QCOMPARE(contentsOf(target), expected);
}

void TstCliOutputs::outputNamingAnInputIsRefused_data()
{
    QTest::addColumn<QStringList>("arguments"); // IN is the input file, LINK a symbolic link to it
    QTest::addColumn<QString>("message");
    QTest::addColumn<bool>("inputKept");        // whether IN's bytes must be unchanged

    const QString inputAndOutput = "the input file and -o name the same file";
    QTest::newRow("subdivide") << QStringList{"subdivide", "IN", "-o", "IN", "--scheme", "bspline", "--levels", "1"}
                               << "subdivide: " + inputAndOutput << true;
    QTest::newRow("interpolate through a link")
        << QStringList{"interpolate", "LINK", "-o", "IN", "--method", "slerp", "--fps", "4"}
        << "interpolate: " + inputAndOutput << true;
    QTest::newRow("import") << QStringList{"import", "IN", "-o", "IN"} << "import: " + inputAndOutput << true;
    QTest::newRow("fit: -o is --omega")
        << QStringList{"fit", "KEYS", "--omega", "IN", "--fps", "4", "-o", "IN"}
        << "fit: --omega and -o name the same file" << true;
    QTest::newRow("fit: --report is -o")
        << QStringList{"fit", "KEYS", "--omega", "IN", "--fps", "4", "-o", "OUT", "--report", "OUT"}
        << "fit: -o and --report name the same file" << true;
    QTest::newRow("fit: -o and --report both standard output")
        << QStringList{"fit", "KEYS", "--omega", "IN", "--fps", "4", "-o", "-", "--report", "-"}
        << "fit: -o and --report both name standard output" << true;
}

void TstCliOutputs::outputNamingAnInputIsRefused()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    QFETCH(bool, inputKept);
    const QString in = writeFile("shared.csv", kKeys);
    const QString link = path("shared-link.csv");
    QFile::remove(link);
    QVERIFY(QFile::link(in, link));
    const QString keys = writeFile("keys.csv", kKeys);
    const QString out = path("out.csv");
    for (QString& argument : arguments)
        argument = argument == "IN" ? in : argument == "LINK" ? link : argument == "KEYS" ? keys
                 : argument == "OUT" ? out : argument;

    const CliRun run = runCli(arguments);
    QVERIFY(run.exitedNormally);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains(message), qPrintable(run.err));
    QVERIFY2(run.out.isEmpty(), qPrintable(run.out));
    if (inputKept)
        QCOMPARE(contentsOf(in), kKeys);
    QVERIFY(!QFileInfo::exists(out));
}

void TstCliOutputs::convertMayRewriteItsInput()
{
    // The same poses in another column set replace the file, as a whole, but not a FIFO read and
    // written at once.
    const QByteArray expected = convertedToMatrix();
    const QString in = writeFile("in-place.csv", kKeys);
    QVERIFY(succeeds({"convert", in, "-o", in, "--to", "matrix"}));
    QCOMPARE(contentsOf(in), expected);

    const QString fifo = path("in-place.fifo");
    QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
    const CliRun run = runCli({"convert", fifo, "-o", fifo, "--to", "matrix"});
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains("convert: the input file and -o name the same file"), qPrintable(run.err));
}

void TstCliOutputs::eulerOutputUnwrapsAcrossBlocks()
{
    // A steady turn about z of 1° a row, 10000 rows: rows are written in blocks of a few thousand,
    // and the Euler filter must carry across them, so e3 climbs by exactly 1° from row to row.
    constexpr int kRows = 10000;
    QByteArray contents = "qw,qx,qy,qz\n";
    for (int i = 0; i < kRows; ++i) {
        const double half = i * std::numbers::pi / 360.0;
        contents += (number(std::cos(half)) + ",0,0," + number(std::sin(half)) + "\n").toUtf8();
    }
    const QString in = writeFile("turn.csv", contents);
    const QString out = path("turn-euler.csv");
    QVERIFY(succeeds({"convert", in, "-o", out, "--to", "euler"}));
    const Csv csv = readCsv(out);
    QVERIFY2(csv.problem.isEmpty(), qPrintable(csv.problem));
    QCOMPARE(csv.rows.size(), std::size_t{kRows});
    for (std::size_t i = 1; i < csv.rows.size(); ++i)
        QVERIFY2(std::abs(csv.at(i, "e3") - csv.at(i - 1, "e3") - 1.0) < 1e-6,
                 qPrintable(QStringLiteral("row %1: e3 %2 after %3").arg(i).arg(csv.at(i, "e3")).arg(csv.at(i - 1, "e3"))));
}

void TstCliOutputs::rowsPastTheBudgetAreRefused()
{
    // One pose more than the budget, each on a short line; a comment line first so that the line
    // named is not simply the row's number.
    const std::size_t rows = CsvLineReader::kRowBudget + 1;
    QByteArray contents = "# one pose too many\nqw,qx,qy,qz\n";
    contents.reserve(contents.size() + static_cast<qsizetype>(rows) * 8);
    for (std::size_t i = 0; i < rows; ++i)
        contents += "1,0,0,0\n";
    const QString in = writeFile("too-many.csv", contents);
    contents.clear();
    const QString out = path("too-many-out.csv");

    const CliRun run = runCli({"convert", in, "-o", out, "--to", "matrix"});
    QVERIFY(run.exitedNormally);
    QCOMPARE(run.exitCode, 1);
    const QString expected = QStringLiteral("%1:%2: the file holds %3 poses, more than the %4 a file may hold")
                                 .arg(in)
                                 .arg(CsvLineReader::kRowBudget + 3)
                                 .arg(rows)
                                 .arg(CsvLineReader::kRowBudget);
    QVERIFY2(run.err.contains(expected), qPrintable(run.err + " expected " + expected));
    QVERIFY(!QFileInfo::exists(out));
}

void TstCliOutputs::rowCountStopsAtTheBudget()
{
    // The count itself, with a small budget: blank and comment lines are not rows, the header is not
    // one, and a line the parse would refuse ends the count rather than being reported out of turn.
    const QString file = writeFile("count.csv", "# c\nqw,qx,qy,qz\n1,0,0,0\n\n# c\n1,0,0,0\n1,0,0,0\n");
    QCOMPARE(CsvLineReader::countRows(file, 3, "poses"), std::optional<std::size_t>(3));
    try {
        CsvLineReader::countRows(file, 2, "poses");
        QFAIL("three rows were accepted with a budget of two");
    } catch (const InputError& error) {
        QCOMPARE(QString::fromUtf8(error.what()),
                 file + ":7: the file holds 3 poses, more than the 2 a file may hold (docs/pose-csv.md)");
    }
    const QString binary = writeFile("binary.csv", QByteArray("qw,qx,qy,qz\n1,0,0,0\n\0\n1,0,0,0\n", 30));
    QCOMPARE(CsvLineReader::countRows(binary, 1, "poses"), std::optional<std::size_t>(1));
    QCOMPARE(CsvLineReader::countRows(QStringLiteral("/dev/null"), 0, "poses"), std::nullopt);
}

QTEST_GUILESS_MAIN(TstCliOutputs)
#include "tst_cli_outputs.moc"
