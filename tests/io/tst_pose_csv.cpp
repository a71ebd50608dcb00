// The pose CSV format: exact number text, every rotation column set both ways, the parsing rules,
// and every kind of bad input with the exact line and column in its message. Expected rotations are
// built here from Eigen's AngleAxis, not from the conversions under test.

#include "core/number_text.h"
#include "io/pose_csv.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

using namespace gyre;
using namespace gyre::io;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;

bool sameBits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// q and −q are the same rotation.
double rotationDistance(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    return std::min((a.coeffs() - b.coeffs()).norm(), (a.coeffs() + b.coeffs()).norm());
}

Eigen::Quaterniond about(const Eigen::Vector3d& axis, double degrees)
{
    return Eigen::Quaterniond(Eigen::AngleAxisd(degrees * kDegree, axis.normalized()));
}

Eigen::Vector3d axisVector(char axis)
{
    return axis == 'x' ? Eigen::Vector3d::UnitX() : axis == 'y' ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
}

// docs/conventions.md: intrinsic ijk is R = Ri(e1)·Rj(e2)·Rk(e3); extrinsic ijk is R = Rk(e3)·Rj(e2)·Ri(e1).
Eigen::Quaterniond fromEulerDegrees(const char* order, AngleFrame frame, double e1, double e2, double e3)
{
    const Eigen::Quaterniond r1 = about(axisVector(order[0]), e1);
    const Eigen::Quaterniond r2 = about(axisVector(order[1]), e2);
    const Eigen::Quaterniond r3 = about(axisVector(order[2]), e3);
    return frame == AngleFrame::Intrinsic ? r1 * r2 * r3 : r3 * r2 * r1;
}

EulerConvention convention(const char* order, AngleFrame frame) { return *EulerConvention::parse(order, frame); }

// Poses that visit the awkward places: the identity, half turns, gimbal lock of xyz, tiny angles.
PoseTable awkwardTable()
{
    std::mt19937_64 random(7);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> uniform(-100.0, 100.0);
    std::vector<Eigen::Quaterniond> rotations{Eigen::Quaterniond::Identity(), about({1, 0, 0}, 180),
                                              about({0, 1, 0}, 90), about({1, 2, 3}, 1e-7), about({0, 0, 1}, -179.9)};
    for (int i = 0; i < 20; ++i)
        rotations.push_back(Eigen::Quaterniond(normal(random), normal(random), normal(random), normal(random)).normalized());
    PoseTable table;
    table.hasTime = true;
    table.hasPosition = true;
    double time = -1.0 / 3.0;
    for (const Eigen::Quaterniond& q : rotations) {
        time += 0.1 + std::abs(uniform(random));
        table.rows.push_back({time, {q, {uniform(random), 1e-300 * uniform(random), -0.0}}, 0});
    }
    return table;
}

class TstPoseCsv : public QObject {
    Q_OBJECT

private:
    QTemporaryDir dir_;

    QString writeFile(const QString& name, const QByteArray& contents)
    {
        const QString path = dir_.filePath(name);
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(contents) != contents.size())
            qFatal("cannot write the fixture %s", qPrintable(path));
        return path;
    }

    static QByteArray contentsOf(const QString& path)
    {
        QFile file(path);
        return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray("<cannot open>");
    }

    // The message of the InputError that reading `path` throws, or "<no error>".
    static QString readError(const QString& path, TimeColumn timeColumn = TimeColumn::Optional)
    {
        try {
            readPoseCsv(path, EulerConvention{}, timeColumn);
        } catch (const InputError& error) {
            return QString::fromStdString(error.what());
        }
        return QStringLiteral("<no error>");
    }

private slots:
    void numbersReadBackBitForBit();
    void numberText_data();
    void numberText();
    void badNumberText_data();
    void badNumberText();

    void everyColumnSetRoundTrips_data();
    void everyColumnSetRoundTrips();
    void quaternionFileIsAFixedPoint();
    void writesTheRequestedColumns();
    void eulerOutputHasNoJumps();

    void readsEachColumnSet_data();
    void readsEachColumnSet();
    void normalisesSmallQuaternionDrift();
    void projectsNearlyOrthonormalMatrices();
    void layoutRules();
    void rowsKnowTheirLines();

    void errors_data();
    void errors();
    void timeColumnCanBeRequired();
    void lineLengthLimit();
    void binaryGarbage();
    void unreadableFiles();

    void abandonedWriteLeavesFileUntouched();
    void unwritablePath();
};

void TstPoseCsv::numbersReadBackBitForBit()
{
    std::vector<double> values{0.0,
                               -0.0,
                               0.1,
                               1.0 / 3.0,
                               -2.5e-17,
                               std::numeric_limits<double>::max(),
                               std::numeric_limits<double>::lowest(),
                               std::numeric_limits<double>::min(),
                               std::numeric_limits<double>::denorm_min(),
                               std::nextafter(1.0, 2.0)};
    std::mt19937_64 random(1);
    while (values.size() < 20000) {
        const double value = std::bit_cast<double>(random());
        if (std::isfinite(value))
            values.push_back(value);
    }
    for (const double value : values) {
        const std::string text = formatNumber(value);
        if (!sameBits(parseFiniteNumber(text), value))
            QFAIL(qPrintable(QStringLiteral("%1 did not read back exactly").arg(QString::fromStdString(text))));
    }
}

void TstPoseCsv::numberText_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<double>("value");
    QTest::newRow("integer") << "42" << 42.0;
    QTest::newRow("spaces and tabs around") << " \t-1.5 \t" << -1.5;
    QTest::newRow("scientific") << "2.5E-3" << 0.0025;
    QTest::newRow("no leading digit") << ".5" << 0.5;
    QTest::newRow("no digit after the point") << "5." << 5.0;
    QTest::newRow("negative zero") << "-0" << -0.0;
}

void TstPoseCsv::numberText()
{
    QFETCH(QString, text);
    QFETCH(double, value);
    QVERIFY(sameBits(parseFiniteNumber(text.toStdString()), value));
}

void TstPoseCsv::badNumberText_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("message");
    QTest::newRow("empty") << "  " << "empty field; expected a number";
    QTest::newRow("word") << "abc" << "'abc' is not a number";
    QTest::newRow("trailing text") << "1.5x" << "'1.5x' is not a number";
    QTest::newRow("decimal comma") << "1;5" << "'1;5' is not a number";
    QTest::newRow("plus sign") << "+1" << "'+1' is not a number";
    QTest::newRow("hexadecimal") << "0x10" << "'0x10' is not a number";
    QTest::newRow("two numbers") << "1 2" << "'1 2' is not a number";
    QTest::newRow("nan") << "nan" << "'nan' is not a finite number";
    QTest::newRow("NaN") << "NaN" << "'NaN' is not a finite number";
    QTest::newRow("inf") << "inf" << "'inf' is not a finite number";
    QTest::newRow("-infinity") << "-infinity" << "'-infinity' is not a finite number";
    QTest::newRow("overflow") << "1e999" << "'1e999' is out of the range of a double";
    QTest::newRow("long text is cut") << QString(60, 'a') << "'" + QString(40, 'a') + "…' is not a number";
}

void TstPoseCsv::badNumberText()
{
    QFETCH(QString, text);
    QFETCH(QString, message);
    try {
        parseFiniteNumber(text.toStdString());
        QFAIL("accepted");
    } catch (const std::invalid_argument& error) {
        QCOMPARE(QString::fromUtf8(error.what()), message);
    }
}

void TstPoseCsv::everyColumnSetRoundTrips_data()
{
    QTest::addColumn<RotationColumns>("columns");
    QTest::addColumn<QString>("order");
    QTest::addColumn<AngleFrame>("frame");
    QTest::newRow("quat") << RotationColumns::Quaternion << "xyz" << AngleFrame::Extrinsic;
    QTest::newRow("matrix") << RotationColumns::Matrix << "xyz" << AngleFrame::Extrinsic;
    QTest::newRow("axis-angle") << RotationColumns::AxisAngle << "xyz" << AngleFrame::Extrinsic;
    QTest::newRow("rotvec") << RotationColumns::RotationVector << "xyz" << AngleFrame::Extrinsic;
    QTest::newRow("euler extrinsic xyz") << RotationColumns::Euler << "xyz" << AngleFrame::Extrinsic;
    QTest::newRow("euler intrinsic zyx") << RotationColumns::Euler << "zyx" << AngleFrame::Intrinsic;
    QTest::newRow("euler extrinsic zxz") << RotationColumns::Euler << "zxz" << AngleFrame::Extrinsic;
    QTest::newRow("euler intrinsic yxy") << RotationColumns::Euler << "yxy" << AngleFrame::Intrinsic;
}

// Time and position come back bit for bit, and so do quaternions; the other sets are converted on
// the way and come back to rounding.
void TstPoseCsv::everyColumnSetRoundTrips()
{
    QFETCH(RotationColumns, columns);
    QFETCH(QString, order);
    QFETCH(AngleFrame, frame);
    const EulerConvention euler = convention(qPrintable(order), frame);
    PoseTable written = awkwardTable();
    written.rotationColumns = columns;
    const QString path = dir_.filePath(QStringLiteral("round-trip.csv"));
    writePoseCsv(path, written, euler);
    const PoseTable read = readPoseCsv(path, euler);
    QCOMPARE(read.rotationColumns, columns);
    QVERIFY(read.hasTime);
    QVERIFY(read.hasPosition);
    QCOMPARE(read.rows.size(), written.rows.size());
    for (std::size_t i = 0; i < read.rows.size(); ++i) {
        const PoseRow& a = written.rows[i];
        const PoseRow& b = read.rows[i];
        QVERIFY(sameBits(a.time, b.time));
        for (int k = 0; k < 3; ++k)
            QVERIFY(sameBits(a.pose.position[k], b.pose.position[k]));
        if (columns == RotationColumns::Quaternion) {
            for (int k = 0; k < 4; ++k)
                QVERIFY(sameBits(a.pose.orientation.coeffs()[k], b.pose.orientation.coeffs()[k]));
        } else {
            QVERIFY2(rotationDistance(a.pose.orientation, b.pose.orientation) < 1e-14, qPrintable(QString::number(i)));
        }
    }
}

void TstPoseCsv::quaternionFileIsAFixedPoint()
{
    const QString first = dir_.filePath(QStringLiteral("first.csv"));
    const QString second = dir_.filePath(QStringLiteral("second.csv"));
    writePoseCsv(first, awkwardTable());
    writePoseCsv(second, readPoseCsv(first, {}));
    QCOMPARE(contentsOf(second), contentsOf(first));
}

void TstPoseCsv::writesTheRequestedColumns()
{
    PoseTable table;
    table.rows.push_back({0.5, {about({0, 0, 1}, 90), {1, 2, 3}}, 0});
    const QString path = dir_.filePath(QStringLiteral("columns.csv"));

    table.rotationColumns = RotationColumns::Matrix;
    writePoseCsv(path, table);
    // Rz(90°) maps x to y: row-major m10 = 1, m01 = −1.
    const QList<QByteArray> matrix = contentsOf(path).split('\n');
    QCOMPARE(matrix[0], QByteArray("m00,m01,m02,m10,m11,m12,m20,m21,m22"));
    const QList<QByteArray> m = matrix[1].split(',');
    QCOMPARE(m.size(), 9);
    QCOMPARE(m[1].toDouble(), -1.0);
    QCOMPARE(m[3].toDouble(), 1.0);
    QCOMPARE(m[8].toDouble(), 1.0);

    table.hasTime = true;
    table.hasPosition = true;
    table.rotationColumns = RotationColumns::AxisAngle;
    writePoseCsv(path, table);
    const QList<QByteArray> axisAngle = contentsOf(path).split('\n');
    QCOMPARE(axisAngle[0], QByteArray("time,ax,ay,az,angle,x,y,z"));
    const QList<QByteArray> a = axisAngle[1].split(',');
    QCOMPARE(a[0], QByteArray("0.5"));
    QVERIFY(std::abs(a[3].toDouble() - 1.0) < 1e-15);
    QVERIFY(std::abs(a[4].toDouble() - 90.0) < 1e-12); // degrees
    QCOMPARE(a.mid(5), (QList<QByteArray>{"1", "2", "3"}));

    table.rotationColumns = RotationColumns::RotationVector;
    writePoseCsv(path, table);
    const QList<QByteArray> rotvec = contentsOf(path).split('\n');
    QCOMPARE(rotvec[0], QByteArray("time,rx,ry,rz,x,y,z"));
    QVERIFY(std::abs(rotvec[1].split(',')[3].toDouble() - kPi / 2) < 1e-15); // radians
}

// A turn about z past ±180° continues to 190°, 210°, … instead of jumping to −170°.
void TstPoseCsv::eulerOutputHasNoJumps()
{
    PoseTable table;
    table.rotationColumns = RotationColumns::Euler;
    for (double degrees = 150; degrees <= 400; degrees += 20)
        table.rows.push_back({0, {about({0, 0, 1}, degrees), {0, 0, 0}}, 0});
    const QString path = dir_.filePath(QStringLiteral("euler.csv"));
    writePoseCsv(path, table, convention("xyz", AngleFrame::Extrinsic));
    const QList<QByteArray> lines = contentsOf(path).trimmed().split('\n');
    QCOMPARE(lines.size(), static_cast<qsizetype>(table.rows.size() + 1));
    double previous = 130;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const double e3 = lines[i].split(',')[2].toDouble();
        QVERIFY2(std::abs(e3 - previous - 20) < 1e-9, lines[i].constData());
        previous = e3;
    }
}

void TstPoseCsv::readsEachColumnSet_data()
{
    QTest::addColumn<QByteArray>("contents");
    QTest::addColumn<QString>("order");
    QTest::addColumn<AngleFrame>("frame");
    QTest::addColumn<Eigen::Quaterniond>("expected");
    const auto extrinsic = AngleFrame::Extrinsic;
    const auto intrinsic = AngleFrame::Intrinsic;
    QTest::newRow("quat") << QByteArray("qw,qx,qy,qz\n0.5,0.5,0.5,0.5\n") << "xyz" << extrinsic
                          << Eigen::Quaterniond(0.5, 0.5, 0.5, 0.5);
    QTest::newRow("matrix, row-major, v' = M v") << QByteArray("m00,m01,m02,m10,m11,m12,m20,m21,m22\n0,-1,0,1,0,0,0,0,1\n")
                                                 << "xyz" << extrinsic << about({0, 0, 1}, 90);
    QTest::newRow("axis-angle, degrees, axis normalised") << QByteArray("ax,ay,az,angle\n0,0,2,90\n") << "xyz"
                                                          << extrinsic << about({0, 0, 1}, 90);
    QTest::newRow("axis-angle, zero angle") << QByteArray("ax,ay,az,angle\n0,0,0,0\n") << "xyz" << extrinsic
                                            << Eigen::Quaterniond::Identity();
    QTest::newRow("axis-angle, tiny axis") << QByteArray("ax,ay,az,angle\n0,1e-200,0,30\n") << "xyz" << extrinsic
                                           << about({0, 1, 0}, 30);
    QTest::newRow("rotvec, radians") << QByteArray("rx,ry,rz\n0,0,1.5707963267948966\n") << "xyz" << extrinsic
                                     << about({0, 0, 1}, 90);
    QTest::newRow("euler extrinsic xyz") << QByteArray("e1,e2,e3\n10,20,30\n") << "xyz" << extrinsic
                                         << fromEulerDegrees("xyz", extrinsic, 10, 20, 30);
    QTest::newRow("euler intrinsic xyz") << QByteArray("e1,e2,e3\n10,20,30\n") << "xyz" << intrinsic
                                         << fromEulerDegrees("xyz", intrinsic, 10, 20, 30);
    QTest::newRow("euler intrinsic zxz") << QByteArray("e1,e2,e3\n-100,45,170\n") << "zxz" << intrinsic
                                         << fromEulerDegrees("zxz", intrinsic, -100, 45, 170);
    QTest::newRow("euler extrinsic yzx") << QByteArray("e3,e1,e2\n5,-60,89\n") << "yzx" << extrinsic
                                         << fromEulerDegrees("yzx", extrinsic, -60, 89, 5);
}

void TstPoseCsv::readsEachColumnSet()
{
    QFETCH(QByteArray, contents);
    QFETCH(QString, order);
    QFETCH(AngleFrame, frame);
    QFETCH(Eigen::Quaterniond, expected);
    const PoseTable table = readPoseCsv(writeFile(QStringLiteral("set.csv"), contents), convention(qPrintable(order), frame));
    QCOMPARE(table.rows.size(), std::size_t{1});
    const Eigen::Quaterniond& q = table.rows[0].pose.orientation;
    QVERIFY2(rotationDistance(q, expected) < 1e-15, qPrintable(QStringLiteral("distance %1").arg(rotationDistance(q, expected))));
    QVERIFY(std::abs(q.norm() - 1.0) < 1e-15);
    QVERIFY(!table.hasTime);
    QVERIFY(!table.hasPosition);
    QCOMPARE(table.rows[0].pose.position, Eigen::Vector3d::Zero().eval());
}

void TstPoseCsv::normalisesSmallQuaternionDrift()
{
    const PoseTable table = readPoseCsv(writeFile(QStringLiteral("drift.csv"), "qw,qx,qy,qz\n1.009,0,0,0\n0,0.6,0,0.795\n"), {});
    QCOMPARE(table.rows[0].pose.orientation.coeffs(), Eigen::Quaterniond::Identity().coeffs());
    const Eigen::Quaterniond expected = Eigen::Quaterniond(0, 0.6, 0, 0.795).normalized();
    QVERIFY(rotationDistance(table.rows[1].pose.orientation, expected) < 1e-16);
}

void TstPoseCsv::projectsNearlyOrthonormalMatrices()
{
    // Rz(90°) written with four digits.
    const PoseTable table = readPoseCsv(
        writeFile(QStringLiteral("rounded.csv"), "m00,m01,m02,m10,m11,m12,m20,m21,m22\n0.0001,-1,0,1,0.0001,0,0,0,1.0002\n"), {});
    const Eigen::Quaterniond& q = table.rows[0].pose.orientation;
    QVERIFY(std::abs(q.norm() - 1.0) < 1e-15);
    QVERIFY(rotationDistance(q, about({0, 0, 1}, 90)) < 1e-4);
}

// Comments, blank lines, spaces, CRLF, a byte order mark and any column order read as the plain file.
void TstPoseCsv::layoutRules()
{
    const PoseTable plain =
        readPoseCsv(writeFile(QStringLiteral("plain.csv"), "time,qw,qx,qy,qz,x,y,z\n0,1,0,0,0,1,2,3\n0.25,0,1,0,0,4,5,6\n"), {});
    const QByteArray decorated = "\xEF\xBB\xBF# exported by hand\r\n"
                                 "\r\n"
                                 "  z , qx,time ,\tqw,qy,x,qz,y\r\n"
                                 "   # a comment between rows\r\n"
                                 "3, 0 ,0,1,0,1,0,2\r\n"
                                 "\t\r\n"
                                 "6,1,0.25,0,0,4,0,5"; // no line end at the end of the file
    const PoseTable read = readPoseCsv(writeFile(QStringLiteral("decorated.csv"), decorated), {});
    QVERIFY(read.hasTime);
    QVERIFY(read.hasPosition);
    QCOMPARE(read.rotationColumns, RotationColumns::Quaternion);
    QCOMPARE(read.rows.size(), plain.rows.size());
    for (std::size_t i = 0; i < read.rows.size(); ++i) {
        QCOMPARE(read.rows[i].time, plain.rows[i].time);
        QCOMPARE(read.rows[i].pose.orientation.coeffs(), plain.rows[i].pose.orientation.coeffs());
        QCOMPARE(read.rows[i].pose.position, plain.rows[i].pose.position);
    }
}

void TstPoseCsv::rowsKnowTheirLines()
{
    const PoseTable table =
        readPoseCsv(writeFile(QStringLiteral("lines.csv"), "# c\nqw,qx,qy,qz\n1,0,0,0\n\n# c\n1,0,0,0\n"), {});
    QCOMPARE(table.rows.size(), std::size_t{2});
    QCOMPARE(table.rows[0].line, std::int64_t{3});
    QCOMPARE(table.rows[1].line, std::int64_t{6});
}

void TstPoseCsv::errors_data()
{
    QTest::addColumn<QByteArray>("contents");
    QTest::addColumn<QString>("message"); // after "path:"
    const QByteArray quat = "time,qw,qx,qy,qz\n";
    QTest::newRow("empty file") << QByteArray() << "1: no header row: the file is empty or holds only comments";
    QTest::newRow("only comments") << QByteArray("# a\n\n# b\n") << "3: no header row: the file is empty or holds only comments";
    QTest::newRow("header only") << quat << "1: no poses after the header on line 1";
    QTest::newRow("header and comments") << QByteArray("# x\n" + quat + "# y\n") << "3: no poses after the header on line 2";
    const QString columns = "the columns are time | qw,qx,qy,qz | m00,m01,m02,m10,m11,m12,m20,m21,m22 | "
                            "ax,ay,az,angle | rx,ry,rz | e1,e2,e3 | x,y,z";
    QTest::newRow("unknown column") << QByteArray("time,qw,qx,qy,qz,speed\n") << "1: unknown column 'speed'; " + columns;
    QTest::newRow("upper-case column") << QByteArray("Time,qw,qx,qy,qz\n") << "1: unknown column 'Time'; " + columns;
    QTest::newRow("duplicate column") << QByteArray("qw,qx,time,qy,qz,time\n") << "1: column time appears twice";
    QTest::newRow("empty header field") << QByteArray("qw,qx,qy,qz,\n") << "1: header field 5 is empty";
    QTest::newRow("partial quat") << QByteArray("time,qw,qx,qz\n") << "1: missing column qy (quat needs qw,qx,qy,qz)";
    QTest::newRow("partial matrix") << QByteArray("m00,m01,m02,m10,m11,m12,m20,m21\n")
                                    << "1: missing column m22 (matrix needs m00,m01,m02,m10,m11,m12,m20,m21,m22)";
    QTest::newRow("partial axis-angle") << QByteArray("ax,ay,az\n") << "1: missing column angle (axis-angle needs ax,ay,az,angle)";
    QTest::newRow("partial rotvec") << QByteArray("rx,rz\n") << "1: missing column ry (rotvec needs rx,ry,rz)";
    QTest::newRow("partial euler") << QByteArray("e2,e3\n") << "1: missing column e1 (euler needs e1,e2,e3)";
    QTest::newRow("partial position") << QByteArray("qw,qx,qy,qz,x,z\n") << "1: missing column y (position needs x,y,z)";
    QTest::newRow("two rotation sets") << QByteArray("qw,qx,qy,qz,rx,ry,rz\n")
                                       << "1: columns qz and rx give the rotation twice; use one column set";
    QTest::newRow("no rotation") << QByteArray("time,x,y,z\n")
                                 << "1: no rotation columns; give one set of qw,qx,qy,qz | "
                                    "m00,m01,m02,m10,m11,m12,m20,m21,m22 | ax,ay,az,angle | rx,ry,rz | e1,e2,e3";
    QTest::newRow("text") << QByteArray("# keys\n" + quat + "0,1,0,0,0\n\n1,1,0,0,abc\n") << "5: column qz: 'abc' is not a number";
    QTest::newRow("nan") << QByteArray(quat + "0,nan,0,0,0\n") << "2: column qw: 'nan' is not a finite number";
    QTest::newRow("infinity") << QByteArray(quat + "0,1,0,0,0\n-inf,1,0,0,0\n") << "3: column time: '-inf' is not a finite number";
    QTest::newRow("empty field") << QByteArray(quat + "0,1,,0,0\n") << "2: column qx: empty field; expected a number";
    QTest::newRow("short row") << QByteArray(quat + "0,1,0,0\n") << "2: 4 fields, but the header on line 1 has 5";
    QTest::newRow("extra field") << QByteArray(quat + "0,1,0,0,0,\n") << "2: 6 fields, but the header on line 1 has 5";
    QTest::newRow("equal times") << QByteArray(quat + "0,1,0,0,0\n# c\n0,1,0,0,0\n")
                                 << "4: column time: 0 does not come after 0 on line 2; times must strictly increase";
    QTest::newRow("decreasing times") << QByteArray(quat + "1,1,0,0,0\n2,1,0,0,0\n1.5,1,0,0,0\n")
                                      << "4: column time: 1.5 does not come after 2 on line 3; times must strictly increase";
    QTest::newRow("zero quaternion") << QByteArray(quat + "0,0,0,0,0\n") << "2: columns qw,qx,qy,qz: the quaternion is zero";
    QTest::newRow("quaternion norm off") << QByteArray(quat + "0,1.02,0,0,0\n")
                                         << "2: columns qw,qx,qy,qz: the quaternion has norm 1.02, not within 0.01 of 1";
    QTest::newRow("reflection") << QByteArray("m00,m01,m02,m10,m11,m12,m20,m21,m22\n1,0,0,0,1,0,0,0,-1\n")
                                << "2: columns m00,m01,m02,m10,m11,m12,m20,m21,m22: the matrix has determinant -1; "
                                   "a rotation has determinant 1";
    QTest::newRow("singular matrix") << QByteArray("m00,m01,m02,m10,m11,m12,m20,m21,m22\n0,0,0,0,0,0,0,0,0\n")
                                     << "2: columns m00,m01,m02,m10,m11,m12,m20,m21,m22: the matrix has determinant 0; "
                                        "a rotation has determinant 1";
    QTest::newRow("scaled matrix") << QByteArray("m00,m01,m02,m10,m11,m12,m20,m21,m22\n2,0,0,0,2,0,0,0,2\n")
                                   << "2: columns m00,m01,m02,m10,m11,m12,m20,m21,m22: the matrix is not a rotation: "
                                      "MᵀM differs from the identity by 3, more than 0.01";
    QTest::newRow("zero axis") << QByteArray("ax,ay,az,angle\n0,0,0,10\n")
                               << "2: columns ax,ay,az,angle: the axis is zero but the angle is not";
    QTest::newRow("NUL byte") << QByteArray(quat + "0,1,0,0,0\n0.5,1,0\0,0,0\n", 36)
                              << "3: control character 0x00 at byte 8; is this a text file?";
    QTest::newRow("escape byte") << QByteArray("qw,qx,\x1b[0m,qy,qz\n")
                                 << "1: control character 0x1B at byte 7; is this a text file?";
    QTest::newRow("old Mac line ends") << QByteArray("qw,qx,qy,qz\r1,0,0,0\r")
                                       << "1: control character 0x0D at byte 12; is this a text file?";
}

void TstPoseCsv::errors()
{
    QFETCH(QByteArray, contents);
    QFETCH(QString, message);
    const QString path = writeFile(QStringLiteral("bad.csv"), contents);
    QCOMPARE(readError(path), path + ':' + message);
}

void TstPoseCsv::timeColumnCanBeRequired()
{
    const QString path = writeFile(QStringLiteral("untimed.csv"), "# c\nqw,qx,qy,qz\n1,0,0,0\n");
    QCOMPARE(readError(path), QStringLiteral("<no error>"));
    QCOMPARE(readError(path, TimeColumn::Required), path + ":2: missing column time, which is required here");
}

// Lines up to 64 KiB read; one byte more is refused without reading the rest of it.
void TstPoseCsv::lineLengthLimit()
{
    const qsizetype limit = 64 * 1024;
    const QByteArray row = "1,0,0,0";
    const QByteArray longest = QByteArray(limit - row.size(), ' ') + row;
    QCOMPARE(longest.size(), limit);
    const QString fits = writeFile(QStringLiteral("longest.csv"), "qw,qx,qy,qz\n" + longest + "\r\n" + longest);
    QCOMPARE(readError(fits), QStringLiteral("<no error>"));
    const QString tooLong = writeFile(QStringLiteral("too-long.csv"), "qw,qx,qy,qz\n1,0,0,0\n " + longest + "\n");
    QCOMPARE(readError(tooLong), tooLong + ":3: line longer than 65536 bytes; is this a pose CSV file?");
    const QString endless = writeFile(QStringLiteral("endless.csv"), QByteArray(10 * limit, '1'));
    QCOMPARE(readError(endless), endless + ":1: line longer than 65536 bytes; is this a pose CSV file?");
}

void TstPoseCsv::binaryGarbage()
{
    std::mt19937 random(3);
    for (int trial = 0; trial < 20; ++trial) {
        QByteArray bytes(4096, '\0');
        for (char& byte : bytes)
            byte = static_cast<char>(random());
        const QString path = writeFile(QStringLiteral("garbage.csv"), bytes);
        QVERIFY(readError(path).startsWith(path + ':'));
    }
}

void TstPoseCsv::unreadableFiles()
{
    const QString missing = dir_.filePath(QStringLiteral("missing.csv"));
    QCOMPARE(readError(missing), missing + ": cannot open: No such file or directory");
    QCOMPARE(readError(dir_.path()), dir_.path() + ": is a directory, not a file");
}

// QSaveFile keeps the old file until the new one is complete; a value the format cannot hold
// abandons the write half-way through.
void TstPoseCsv::abandonedWriteLeavesFileUntouched()
{
    PoseTable table = awkwardTable();
    table.rows[10].pose.position.y() = std::numeric_limits<double>::quiet_NaN();
    const QString existing = writeFile(QStringLiteral("existing.csv"), "precious\n");
    const QString absent = dir_.filePath(QStringLiteral("absent.csv"));
    for (const QString& path : {existing, absent}) {
        try {
            writePoseCsv(path, table);
            QFAIL("wrote a value that is not finite");
        } catch (const OutputError& error) {
            QCOMPARE(QString::fromUtf8(error.what()), path + ": row 11 holds a value that is not finite");
        }
    }
    QCOMPARE(contentsOf(existing), QByteArray("precious\n"));
    QVERIFY(!QFile::exists(absent));
    QCOMPARE(QDir(dir_.path()).entryList(QDir::Files).filter(QStringLiteral("absent")), QStringList());
}

void TstPoseCsv::unwritablePath()
{
    const QString path = dir_.filePath(QStringLiteral("no-such-folder/out.csv"));
    try {
        writePoseCsv(path, awkwardTable());
        QFAIL("wrote into a missing folder");
    } catch (const OutputError& error) {
        QVERIFY(QString::fromUtf8(error.what()).startsWith(path + ": cannot write: "));
    }
    QVERIFY(!QFile::exists(path));
}

} // namespace

QTEST_GUILESS_MAIN(TstPoseCsv)
#include "tst_pose_csv.moc"
