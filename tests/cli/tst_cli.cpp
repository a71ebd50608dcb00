// gyre-cli as a pipeline sees it: the real binary run by QProcess on fixtures written here. The
// files it writes are read back with a parser of this test's own, and every expected value is built
// here from Eigen (AngleAxis products, slerp), the closed-form SE(3) exponential, or the formulas in
// docs/pose-csv.md, never from gyre-cli's own output.

#include "cli_test_support.h"
#include "core/key_time_map.h"
#include "core/quaternion_math.h"

#include <Eigen/Dense>

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace {

using namespace gyre::test;

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;
constexpr double kTolerance = 1e-12;

struct Key {
    double time = 0.0;
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

QByteArray keysCsv(const std::vector<Key>& keys)
{
    QString text = QStringLiteral("time,qw,qx,qy,qz,x,y,z\n");
    for (const Key& key : keys) {
        const Eigen::Quaterniond& q = key.rotation;
        const Eigen::Vector3d& p = key.position;
        text += QStringList{number(key.time), number(q.w()), number(q.x()), number(q.y()), number(q.z()),
                            number(p.x()), number(p.y()), number(p.z())}
                    .join(',') +
                '\n';
    }
    return text.toUtf8();
}

double rotationDistance(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    return std::min((a.coeffs() - b.coeffs()).norm(), (a.coeffs() + b.coeffs()).norm());
}

Eigen::Quaterniond about(const Eigen::Vector3d& axis, double radians)
{
    return Eigen::Quaterniond(Eigen::AngleAxisd(radians, axis.normalized()));
}

Eigen::Vector3d axisVector(QChar axis)
{
    return axis == 'x' ? Eigen::Vector3d::UnitX() : axis == 'y' ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
}

// docs/conventions.md: intrinsic ijk is R = Ri(e1)·Rj(e2)·Rk(e3); extrinsic ijk is R = Rk(e3)·Rj(e2)·Ri(e1).
Eigen::Quaterniond fromEulerDegrees(const QString& order, bool intrinsic, const Eigen::Vector3d& degrees)
{
    const Eigen::Quaterniond r1 = about(axisVector(order[0]), degrees[0] * kDegree);
    const Eigen::Quaterniond r2 = about(axisVector(order[1]), degrees[1] * kDegree);
    const Eigen::Quaterniond r3 = about(axisVector(order[2]), degrees[2] * kDegree);
    return intrinsic ? r1 * r2 * r3 : r3 * r2 * r1;
}

Eigen::Matrix3d hat(const Eigen::Vector3d& w)
{
    Eigen::Matrix3d m;
    m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    return m;
}

// V(ω) = I + (1 − cos θ)/θ²·[ω]× + (θ − sin θ)/θ³·[ω]×², θ = |ω| > 0: the translation of the SE(3)
// exponential of (ω, v) is V(ω)·v.
Eigen::Matrix3d translationJacobian(const Eigen::Vector3d& w)
{
    const double theta = w.norm();
    const Eigen::Matrix3d skew = hat(w);
    return Eigen::Matrix3d::Identity() + (1 - std::cos(theta)) / (theta * theta) * skew +
           (theta - std::sin(theta)) / (theta * theta * theta) * skew * skew;
}

// The SE(3) geodesic La·exp(t·log(La⁻¹·Lb)), which a screw motion is; the relative rotation turns
// by less than π.
Key geodesic(const Key& a, const Key& b, double t)
{
    const Eigen::AngleAxisd relativeRotation(a.rotation.conjugate() * b.rotation); // angle in [0, π]
    const Eigen::Vector3d relativePosition = a.rotation.conjugate() * (b.position - a.position);
    const Eigen::Vector3d w = relativeRotation.angle() * relativeRotation.axis();
    const Eigen::Vector3d v = translationJacobian(w).inverse() * relativePosition;
    const Eigen::Quaterniond stepRotation(Eigen::AngleAxisd(t * relativeRotation.angle(), relativeRotation.axis()));
    const Eigen::Vector3d stepPosition = translationJacobian(t * w) * (t * v);
    return {0.0, a.rotation * stepRotation, a.rotation * stepPosition + a.position};
}

std::vector<Key> randomKeys(int count, unsigned seed)
{
    std::mt19937 random(seed);
    std::normal_distribution<double> normal;
    std::vector<Key> keys;
    double time = 0.0;
    for (int i = 0; i < count; ++i) {
        time += 0.25 + std::abs(normal(random));
        keys.push_back({time, Eigen::Quaterniond(normal(random), normal(random), normal(random), normal(random)).normalized(),
                        {normal(random), normal(random), normal(random)}});
    }
    return keys;
}

const QStringList kMethods{"slerp", "nlerp", "squad", "hermite", "euler", "screw"};

// A project object as docs/file-format.md describes it, with the keys given and an empty sketch.
QString projectObject(int id, const QString& name, const QString& parent, const std::vector<Key>& keys)
{
    QStringList keyframes;
    for (const Key& key : keys) {
        const Eigen::Quaterniond& q = key.rotation;
        const Eigen::Vector3d& p = key.position;
        keyframes << QStringLiteral(R"({"time": %1, "orientation": [%2, %3, %4, %5], "position": [%6, %7, %8],)"
                                    R"( "constrained": true})")
                         .arg(number(key.time), number(q.w()), number(q.x()), number(q.y()), number(q.z()),
                              number(p.x()), number(p.y()), number(p.z()));
    }
    return QStringLiteral(R"({"id": %1, "name": "%2", "parent": %3, "mesh": null, "interpolation": "squad",)"
                          R"( "subdivision": {"scheme": "jarek", "levels": 3, "cyclic": false, "decoupled": false},)"
                          R"( "keyframes": [%4],)"
                          R"( "sketch": {"directionStrokes": [], "magnitude": [], "pattern": [], "patternRepeat": 0,)"
                          R"( "window": null, "alpha": 0.002, "beta": 1, "delta": 0.1, "fittedCurve": []}})")
        .arg(id)
        .arg(name, parent, keyframes.join(", "));
}

QByteArray project(const QStringList& objects, int version = 2)
{
    return QStringLiteral(R"({"format": "gyre-project", "version": %1, "fps": 30, "startTime": 0, "endTime": 4,)"
                          R"( "currentTime": 0, "meshes": [], "objects": [%2]})")
        .arg(version)
        .arg(objects.join(", "))
        .toUtf8();
}

class TstCli : public CliTestCase {
    Q_OBJECT

private:
    static QByteArray contentsOf(const QString& filePath)
    {
        QFile file(filePath);
        return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray("<cannot open>");
    }

private slots:
    void convertRoundTrips_data();
    void convertRoundTrips();
    void convertWarnsNearGimbalLock();
    void inputMayBeTheOutput();

    void interpolateSamplesFramesAndKeys_data();
    void interpolateSamplesFramesAndKeys();
    void slerpMidpoint();
    void cubicAndLinearPositions_data();
    void cubicAndLinearPositions();
    void screwFollowsTheGeodesicPerSpan();
    void eulerInterpolatesTheAnglesAsRead();

    void subdivideCycle();
    void subdivideOpen_data();
    void subdivideOpen();
    void subdivideWithoutTimes();

    void infoSummarisesAProject();
    void keysWritesAnObjectsKeyframes();
    void bakeIsTheInterpolationOverTheSceneRange();
    void sceneFilesRoundTripThroughTheVerbs_data();
    void sceneFilesRoundTripThroughTheVerbs();

    void badInput_data();
    void badInput();
    void missingOutputFolder();
    void helpAndVersion();
};

void TstCli::convertRoundTrips_data()
{
    QTest::addColumn<QString>("order");
    QTest::addColumn<bool>("intrinsic");
    QTest::newRow("extrinsic xyz") << "xyz" << false;
    QTest::newRow("intrinsic xyz") << "xyz" << true;
    QTest::newRow("intrinsic zyx") << "zyx" << true;
    QTest::newRow("extrinsic yzx") << "yzx" << false;
    QTest::newRow("extrinsic zxz") << "zxz" << false;
    QTest::newRow("intrinsic yxy") << "yxy" << true;
}

// quat → matrix → euler → axis-angle → rotvec → quat, each file checked against the original
// rotations by its own definition.
void TstCli::convertRoundTrips()
{
    QFETCH(QString, order);
    QFETCH(bool, intrinsic);
    std::vector<Key> keys = randomKeys(30, 11);
    keys[3].rotation = about({0, 1, 0}, kPi / 2); // gimbal lock of xyz
    keys[4].rotation = Eigen::Quaterniond::Identity(); // gimbal lock of proper orders
    keys[5].rotation = about({1, 1, 0}, kPi);          // half turn
    const QString in = writeFile("chain.csv", keysCsv(keys));
    const QStringList euler{"--order", order, intrinsic ? "--intrinsic" : "--extrinsic"};
    const QString matrix = path("chain-matrix.csv");
    const QString angles = path("chain-euler.csv");
    const QString axisAngle = path("chain-axis-angle.csv");
    const QString rotvec = path("chain-rotvec.csv");
    const QString back = path("chain-back.csv");
    QVERIFY(succeeds({"convert", in, "-o", matrix, "--to", "matrix"}));
    QVERIFY(succeeds(QStringList{"convert", matrix, "--to", "euler", "-o", angles} + euler));
    QVERIFY(succeeds(QStringList{"convert"} + euler + QStringList{angles, "-o", axisAngle, "--to", "axis-angle"}));
    QVERIFY(succeeds({"convert", "--to", "rotvec", axisAngle, "-o", rotvec}));
    QVERIFY(succeeds({"convert", rotvec, "-o", back, "--to", "quat"}));

    const Csv m = readCsv(matrix), e = readCsv(angles), a = readCsv(axisAngle), r = readCsv(rotvec), q = readCsv(back);
    for (const Csv* csv : {&m, &e, &a, &r, &q}) {
        QVERIFY2(csv->problem.isEmpty(), qPrintable(csv->problem));
        QCOMPARE(csv->rows.size(), keys.size());
    }
    QCOMPARE(m.header.join(','), QStringLiteral("time,m00,m01,m02,m10,m11,m12,m20,m21,m22,x,y,z"));
    QCOMPARE(e.header.join(','), QStringLiteral("time,e1,e2,e3,x,y,z"));
    QCOMPARE(a.header.join(','), QStringLiteral("time,ax,ay,az,angle,x,y,z"));
    QCOMPARE(r.header.join(','), QStringLiteral("time,rx,ry,rz,x,y,z"));
    QCOMPARE(q.header.join(','), QStringLiteral("time,qw,qx,qy,qz,x,y,z"));
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const Eigen::Quaterniond& expected = keys[i].rotation;
        const Eigen::Matrix3d rotation = expected.toRotationMatrix();
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 3; ++col)
                QVERIFY(std::abs(m.at(i, QStringLiteral("m%1%2").arg(row).arg(col)) - rotation(row, col)) < kTolerance);
        const Eigen::Quaterniond fromEuler = fromEulerDegrees(order, intrinsic, e.vector(i, "e1", "e2", "e3"));
        QVERIFY2(rotationDistance(fromEuler, expected) < kTolerance, qPrintable(QString::number(i)));
        const Eigen::Vector3d axis = a.vector(i, "ax", "ay", "az");
        QVERIFY(std::abs(axis.norm() - 1.0) < kTolerance);
        QVERIFY(rotationDistance(about(axis, a.at(i, "angle") * kDegree), expected) < kTolerance);
        const Eigen::Vector3d vector = r.vector(i, "rx", "ry", "rz");
        QVERIFY(rotationDistance(about(vector, vector.norm()), expected) < kTolerance);
        QVERIFY(rotationDistance(q.quaternion(i), expected) < kTolerance);
        // Time and position pass through every step unchanged.
        QCOMPARE(q.at(i, "time"), keys[i].time);
        QCOMPARE(q.position(i), keys[i].position);
    }
}

void TstCli::convertWarnsNearGimbalLock()
{
    const Eigen::Quaterniond nearLock = about({0, 1, 0}, 89.5 * kDegree) * about({1, 0, 0}, 0.3);
    const QString in = writeFile("gimbal.csv", keysCsv({{0, about({1, 0, 0}, 0.3), {0, 0, 0}}, {1, nearLock, {0, 0, 0}}}));
    const CliRun run = runCli({"convert", in, "-o", path("gimbal-euler.csv"), "--to", "euler"});
    QVERIFY(run.exitedNormally);
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.err.contains(in + ":3: rotation 0.50° from gimbal lock in extrinsic xyz"), qPrintable(run.err));
    QVERIFY(!run.err.contains(in + ":2:"));
    // Rows far from lock in zyx are not reported.
    const CliRun zyx = runCli({"convert", in, "-o", path("gimbal-zyx.csv"), "--to", "euler", "--order", "zyx"});
    QCOMPARE(zyx.exitCode, 0);
    QCOMPARE(zyx.err, QString());
}

void TstCli::inputMayBeTheOutput()
{
    const std::vector<Key> keys = randomKeys(4, 3);
    const QString file = writeFile("in-place.csv", keysCsv(keys));
    QVERIFY(succeeds({"convert", file, "-o", file, "--to", "rotvec"}));
    const Csv csv = readCsv(file);
    QCOMPARE(csv.header.join(','), QStringLiteral("time,rx,ry,rz,x,y,z"));
    QCOMPARE(csv.rows.size(), keys.size());
}

void TstCli::interpolateSamplesFramesAndKeys_data()
{
    QTest::addColumn<QString>("method");
    for (const QString& method : kMethods)
        QTest::newRow(qPrintable(method)) << method;
}

// Samples at t0 + k/F and at every key time; a frame within 1e-9 s of a key gives way to it; at a
// key time the pose is the key.
void TstCli::interpolateSamplesFramesAndKeys()
{
    QFETCH(QString, method);
    const double fps = 10;
    std::vector<Key> keys = randomKeys(5, 5);
    const std::vector<double> keyTimes{0.25, 0.6, 1.2500000004, 1.95, 2.3};
    for (std::size_t i = 0; i < keys.size(); ++i)
        keys[i].time = keyTimes[i];
    const QString in = writeFile("keys.csv", keysCsv(keys));
    const QString out = path("frames-" + method + ".csv");
    QVERIFY(succeeds({"interpolate", in, "-o", out, "--method", method, "--fps", "10"}));

    std::vector<double> expectedTimes = keyTimes;
    for (int k = 0; 0.25 + k / fps <= 2.3; ++k) {
        const double frame = 0.25 + k / fps;
        if (std::ranges::none_of(keyTimes, [frame](double key) { return std::abs(key - frame) <= 1e-9; }))
            expectedTimes.push_back(frame);
    }
    std::ranges::sort(expectedTimes);
    // 21 frames from 0.25 to 2.25, less the three at keys 0.25, 1.2500000004 and 1.95, plus 5 keys.
    QCOMPARE(expectedTimes.size(), std::size_t{23});

    const Csv csv = readCsv(out);
    QVERIFY2(csv.problem.isEmpty(), qPrintable(csv.problem));
    QCOMPARE(csv.header.join(','), QStringLiteral("time,qw,qx,qy,qz,x,y,z"));
    QCOMPARE(csv.times(), expectedTimes);
    for (const Key& key : keys) {
        const auto row = static_cast<std::size_t>(std::ranges::find(expectedTimes, key.time) - expectedTimes.begin());
        QVERIFY(rotationDistance(csv.quaternion(row), key.rotation) < kTolerance);
        QVERIFY((csv.position(row) - key.position).norm() < kTolerance);
    }
}

void TstCli::slerpMidpoint()
{
    const Key a{0.0, about({1, 2, 3}, 0.4), {1, 2, 3}};
    // In the other hemisphere: the short arc needs −b.
    const Key b{1.0, Eigen::Quaterniond(-about({-2, 1, 0.5}, 2.0).coeffs()), {-3, 0, 7}};
    QVERIFY(a.rotation.dot(b.rotation) < 0);
    const QString in = writeFile("two-keys.csv", keysCsv({a, b}));
    const QString out = path("two-keys-slerp.csv");
    QVERIFY(succeeds({"interpolate", in, "-o", out, "--method", "slerp", "--fps", "2"}));
    const Csv csv = readCsv(out);
    QCOMPARE(csv.times(), (std::vector<double>{0.0, 0.5, 1.0}));
    const Eigen::Quaterniond eigenSlerp = a.rotation.slerp(0.5, b.rotation);
    QVERIFY(rotationDistance(csv.quaternion(1), eigenSlerp) < kTolerance);
    QVERIFY(rotationDistance(csv.quaternion(1), gyre::slerp(a.rotation, b.rotation, 0.5)) < kTolerance);
    QVERIFY((csv.position(1) - Eigen::Vector3d(-1, 1, 5)).norm() < kTolerance);
}

void TstCli::cubicAndLinearPositions_data()
{
    QTest::addColumn<QString>("method");
    QTest::addColumn<bool>("cubic");
    QTest::newRow("slerp") << "slerp" << false;
    QTest::newRow("nlerp") << "nlerp" << false;
    QTest::newRow("euler") << "euler" << false;
    QTest::newRow("squad") << "squad" << true;
    QTest::newRow("hermite") << "hermite" << true;
    QTest::newRow("euler-cubic") << "euler-cubic" << true;
}

void TstCli::cubicAndLinearPositions()
{
    QFETCH(QString, method);
    QFETCH(bool, cubic);
    const std::vector<Eigen::Vector3d> p{{0, 0, 0}, {1, 2, 0}, {5, -1, 3}};
    const std::vector<double> t{0, 1, 3};
    const Eigen::Quaterniond identity = Eigen::Quaterniond::Identity();
    const QString in =
        writeFile("positions.csv", keysCsv({{t[0], identity, p[0]}, {t[1], identity, p[1]}, {t[2], identity, p[2]}}));
    const QString out = path("positions-" + method + ".csv");
    QVERIFY(succeeds({"interpolate", in, "-o", out, "--method", method, "--fps", "2"}));
    const Csv csv = readCsv(out);
    QCOMPARE(csv.times(), (std::vector<double>{0, 0.5, 1, 1.5, 2, 2.5, 3}));
    // At t = 2: the middle of the span from key 1 to key 2, which lasts h = 2.
    Eigen::Vector3d expected = (p[1] + p[2]) / 2;
    if (cubic) {
        const Eigen::Vector3d m1 = (p[2] - p[0]) / (t[2] - t[0]);
        const Eigen::Vector3d m2 = (p[2] - p[1]) / (t[2] - t[1]); // one-sided at the last key
        const double h = 2;
        // Cubic Hermite basis at u = 1/2: h00 = h01 = 1/2, h10 = 1/8, h11 = −1/8.
        expected += h / 8 * (m1 - m2);
    }
    QVERIFY((csv.position(4) - expected).norm() < kTolerance);
    QVERIFY(csv.quaternion(4).isApprox(Eigen::Quaterniond::Identity(), kTolerance));
}

// Keys read from Euler columns keep their angles: 0 then 360 about z (zyx's first angle) is a full turn, a
// quarter of it at every quarter of the time; from quaternion columns the same keys are one orientation.
void TstCli::eulerInterpolatesTheAnglesAsRead()
{
    const QString in = writeFile("spin.csv", "time,e1,e2,e3\n0,0,0,0\n1,360,0,0\n");
    const QString out = path("spin-frames.csv");
    QVERIFY(succeeds({"interpolate", in, "-o", out, "--method", "euler", "--order", "zyx", "--fps", "4"}));
    const Csv csv = readCsv(out);
    QCOMPARE(csv.times(), (std::vector<double>{0, 0.25, 0.5, 0.75, 1}));
    for (std::size_t row = 0; row < csv.rows.size(); ++row)
        QVERIFY(rotationDistance(csv.quaternion(row), about({0, 0, 1}, 2 * kPi * csv.times()[row])) < kTolerance);
    QVERIFY(rotationDistance(csv.quaternion(2), about({0, 0, 1}, kPi)) < kTolerance);
}

// Between keys i and i+1 the screw parameter is p(t) − i, p the key times' C¹ time map (KeyTimeMap,
// tested in tst_core_key_time_map), here with spans of 2 s and 1 s.
void TstCli::screwFollowsTheGeodesicPerSpan()
{
    const std::vector<Key> keys{{0.0, about({0, 0, 1}, 0.3), {1, 0, 0}},
                                {2.0, about({1, 1, 0}, 1.7), {0, 2, 1}},
                                {3.0, about({0, 1, 1}, -0.9), {-2, 1, 4}}};
    const QString in = writeFile("screw.csv", keysCsv(keys));
    const QString out = path("screw-frames.csv");
    QVERIFY(succeeds({"interpolate", in, "-o", out, "--method", "screw", "--fps", "4"}));
    const Csv csv = readCsv(out);
    QCOMPARE(csv.rows.size(), std::size_t{13});
    const gyre::KeyTimeMap timeMap({0.0, 2.0, 3.0}, false);
    const struct {
        std::size_t row;
        std::size_t span;
    } checks[] = {{1, 0}, {4, 0}, {9, 1}, {10, 1}};
    for (const auto& check : checks) {
        const double u = timeMap.parameterAt(static_cast<double>(check.row) / 4.0) - static_cast<double>(check.span);
        const Key expected = geodesic(keys[check.span], keys[check.span + 1], u);
        QVERIFY(rotationDistance(csv.quaternion(check.row), expected.rotation) < kTolerance);
        QVERIFY((csv.position(check.row) - expected.position).norm() < kTolerance);
    }
}

// A cycle of n poses becomes n·2^L; four-point interpolates, so pose i·2^L is input pose i.
void TstCli::subdivideCycle()
{
    const std::vector<Key> keys = randomKeys(5, 9);
    const QString in = writeFile("cycle.csv", keysCsv(keys));
    const QString out = path("cycle-subdivided.csv");
    QVERIFY(succeeds({"subdivide", in, "-o", out, "--scheme", "four-point", "--levels", "3"}));
    const Csv csv = readCsv(out);
    QVERIFY2(csv.problem.isEmpty(), qPrintable(csv.problem));
    QCOMPARE(csv.header.join(','), QStringLiteral("time,qw,qx,qy,qz,x,y,z"));
    QCOMPARE(csv.rows.size(), std::size_t{5 * 8});
    std::vector<double> times(keys.size());
    std::transform(keys.begin(), keys.end(), times.begin(), [](const Key& key) { return key.time; });
    const gyre::KeyTimeMap timeMap(times, true); // the closing span lasts the mean of the others
    for (std::size_t i = 0; i < keys.size(); ++i) {
        QVERIFY(rotationDistance(csv.quaternion(8 * i), keys[i].rotation) < kTolerance);
        QVERIFY((csv.position(8 * i) - keys[i].position).norm() < kTolerance);
        for (std::size_t j = 0; j < 8; ++j) // pose 8i + j at p(t) = i + j/8; at tᵢ for j = 0
            QVERIFY(std::abs(timeMap.parameterAt(csv.at(8 * i + j, "time")) - static_cast<double>(8 * i + j) / 8) < kTolerance);
    }
}

void TstCli::subdivideOpen_data()
{
    QTest::addColumn<QString>("scheme");
    QTest::addColumn<bool>("decoupled");
    for (const char* scheme : {"four-point", "four-point-b", "bspline", "jarek"}) {
        QTest::addRow("%s", scheme) << scheme << false;
        QTest::addRow("%s decoupled", scheme) << scheme << true;
    }
}

// An open sequence of n poses becomes (n−1)·2^L + 1 and keeps its end poses and times.
void TstCli::subdivideOpen()
{
    QFETCH(QString, scheme);
    QFETCH(bool, decoupled);
    const std::vector<Key> keys = randomKeys(4, 13);
    const QString in = writeFile("open.csv", keysCsv(keys));
    const QString out = path("open-subdivided.csv");
    QStringList arguments{"subdivide", "--open", in, "--levels", "2", "-o", out, "--scheme", scheme};
    if (decoupled)
        arguments << "--decoupled";
    QVERIFY(succeeds(arguments));
    const Csv csv = readCsv(out);
    QCOMPARE(csv.rows.size(), std::size_t{3 * 4 + 1});
    const std::size_t last = csv.rows.size() - 1;
    QVERIFY(rotationDistance(csv.quaternion(0), keys.front().rotation) < kTolerance);
    QVERIFY(rotationDistance(csv.quaternion(last), keys.back().rotation) < kTolerance);
    QVERIFY((csv.position(last) - keys.back().position).norm() < kTolerance);
    QCOMPARE(csv.at(0, "time"), keys.front().time);
    QCOMPARE(csv.at(last, "time"), keys.back().time);
    QCOMPARE(csv.at(4, "time"), keys[1].time);
}

void TstCli::subdivideWithoutTimes()
{
    const QString in = writeFile("untimed.csv", "rx,ry,rz\n0,0,0\n0,0,1\n0,1,1\n");
    const QString out = path("untimed-subdivided.csv");
    QVERIFY(succeeds({"subdivide", in, "-o", out, "--scheme", "bspline", "--levels", "0"}));
    const Csv csv = readCsv(out);
    QCOMPARE(csv.header.join(','), QStringLiteral("qw,qx,qy,qz,x,y,z"));
    QCOMPARE(csv.rows.size(), std::size_t{3});
    QVERIFY(rotationDistance(csv.quaternion(2), about({0, 1, 1}, std::sqrt(2.0))) < kTolerance);
}

void TstCli::infoSummarisesAProject()
{
    const std::vector<Key> keys = randomKeys(3, 4);
    const QString in = writeFile("summary.gyre", project({projectObject(1, "car", "null", keys),
                                                          projectObject(2, "wheel", "1", randomKeys(2, 5)),
                                                          projectObject(3, "light", "null", {})}));
    const CliRun run = runCli({"info", in});
    QCOMPARE(run.exitCode, 0);
    QCOMPARE(run.err, QString());
    const QStringList lines = run.out.split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 9);
    QCOMPARE(lines[0], in + ": Gyre project");
    QCOMPARE(lines[1], QStringLiteral("time range: 0 to 4 s at 30 fps"));
    QCOMPARE(lines[2], QStringLiteral("3 objects, 5 keyframes"));
    QCOMPARE(lines[3], QStringLiteral("  car: 3 keyframes from %1 to %2 s, squad")
                           .arg(QString::number(keys[0].time, 'g', QLocale::FloatingPointShortest),
                                QString::number(keys[2].time, 'g', QLocale::FloatingPointShortest)));
    // Without a mesh an object is the block, 0.332 m³ (tst_primitive_meshes) of water.
    QVERIFY2(lines[4].startsWith("    mass 332 kg (from the mesh, solid), centre ("), qPrintable(lines[4]));
    QVERIFY2(lines[5].startsWith("  wheel (child of car): 2 keyframes from "), qPrintable(lines[5]));
    QCOMPARE(lines[7], QStringLiteral("  light: 0 keyframes, squad"));
    QCOMPARE(lines[8], lines[4]);
}

void TstCli::keysWritesAnObjectsKeyframes()
{
    const std::vector<Key> keys = randomKeys(4, 6);
    const QString in = writeFile("keys.gyre", project({projectObject(1, "car", "null", randomKeys(2, 7)),
                                                       projectObject(2, "wheel", "1", keys)}));
    const QString out = path("wheel.csv");
    QVERIFY(succeeds({"keys", in, "--object", "wheel", "-o", out}));
    const Csv csv = readCsv(out);
    QVERIFY2(csv.problem.isEmpty(), qPrintable(csv.problem));
    QCOMPARE(csv.header, QString("time,qw,qx,qy,qz,x,y,z").split(','));
    QCOMPARE(csv.rows.size(), keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i) {
        // Both files hold 17 significant digits or the shortest exact form, so the numbers are equal.
        QCOMPARE(csv.at(i, "time"), keys[i].time);
        QCOMPARE(csv.quaternion(i).coeffs(), keys[i].rotation.coeffs());
        QCOMPARE(csv.position(i), keys[i].position);
    }
}

void TstCli::bakeIsTheInterpolationOverTheSceneRange()
{
    // Keys from 0.5 to 3.3 s in a scene of [0, 4] s: the bake holds the end poses outside the keys and
    // is the squad interpolation through them inside.
    std::vector<Key> keys = randomKeys(5, 12);
    for (std::size_t i = 0; i < keys.size(); ++i)
        keys[i].time = 0.5 + 0.7 * static_cast<double>(i);
    const QString in = writeFile("bake.gyre", project({projectObject(1, "top", "null", keys)}));
    QVERIFY(succeeds({"bake", in, "--object", "top", "--fps", "10", "-o", path("baked.csv")}));
    QVERIFY(succeeds({"interpolate", writeFile("bake-keys.csv", keysCsv(keys)), "--method", "squad", "--fps", "10",
                      "-o", path("squad.csv")}));
    const Csv baked = readCsv(path("baked.csv"));
    const Csv squad = readCsv(path("squad.csv"));
    QCOMPARE(baked.rows.size(), std::size_t{41});  // 0, 0.1, …, 4 s: every key falls on a frame
    std::size_t matched = 0;
    for (std::size_t row = 0; row < baked.rows.size(); ++row) {
        const double t = baked.at(row, "time");
        QVERIFY(std::abs(t - 0.1 * static_cast<double>(row)) < 1e-12);
        if (t < 0.5 || t > keys.back().time) {
            const Key& held = t < 0.5 ? keys.front() : keys.back();
            QVERIFY(rotationDistance(baked.quaternion(row), held.rotation) < kTolerance);
            QVERIFY((baked.position(row) - held.position).norm() < kTolerance);
            continue;
        }
        for (std::size_t other = 0; other < squad.rows.size(); ++other) {
            if (std::abs(squad.at(other, "time") - t) > 1e-12)
                continue;
            QVERIFY(rotationDistance(baked.quaternion(row), squad.quaternion(other)) < kTolerance);
            QVERIFY((baked.position(row) - squad.position(other)).norm() < kTolerance);
            ++matched;
        }
    }
    QCOMPARE(matched, std::size_t{29});  // the frames from 0.5 to 3.3 s
}

void TstCli::sceneFilesRoundTripThroughTheVerbs_data()
{
    QTest::addColumn<QString>("extension");
    for (const char* extension : {"glb", "gltf", "dae", "fbx"})
        QTest::newRow(extension) << extension;
}

// A project exported to a scene file and imported back bakes to the same motion at every frame, to
// the single precision the formats store.
void TstCli::sceneFilesRoundTripThroughTheVerbs()
{
    QFETCH(QString, extension);
    const QString in = writeFile("trip.gyre", project({projectObject(1, "car", "null", randomKeys(4, 21)),
                                                       projectObject(2, "wheel", "1", randomKeys(3, 22))}));
    const QString scene = path("trip." + extension);
    const QString back = path("trip-back.gyre");
    QVERIFY(succeeds({"export", in, "-o", scene}));
    QVERIFY(succeeds({"import", scene, "-o", back}));
    const CliRun info = runCli({"info", scene});
    QCOMPARE(info.exitCode, 0);
    QVERIFY2(info.out.startsWith(scene + ": scene\n1 animation:\n"), qPrintable(info.out));
    QVERIFY2(info.out.contains("  wheel (child of car): "), qPrintable(info.out));
    for (const char* object : {"car", "wheel"}) {
        QVERIFY(succeeds({"bake", in, "--object", object, "--fps", "30", "-o", path("trip-before.csv")}));
        QVERIFY(succeeds({"bake", back, "--object", object, "--fps", "30", "-o", path("trip-after.csv")}));
        const Csv before = readCsv(path("trip-before.csv"));
        const Csv after = readCsv(path("trip-after.csv"));
        std::size_t compared = 0;
        for (std::size_t row = 0; row < before.rows.size(); ++row) {
            const double t = before.at(row, "time");
            const double frame = t * 30.0;
            if (std::abs(frame - std::round(frame)) > 1e-9)
                continue;  // a key's own sample; the frames are compared
            for (std::size_t other = 0; other < after.rows.size(); ++other) {
                if (std::abs(after.at(other, "time") - t) > 1e-6)
                    continue;
                QVERIFY2(rotationDistance(before.quaternion(row), after.quaternion(other)) < 1e-5,
                         qPrintable(QStringLiteral("%1 at %2 s").arg(object).arg(t)));
                QVERIFY((before.position(row) - after.position(other)).norm() < 1e-5);
                ++compared;
                break;
            }
        }
        QCOMPARE(compared, std::size_t{121});  // every frame of [0, 4] s at 30 fps
    }
}

void TstCli::badInput_data()
{
    QTest::addColumn<QStringList>("arguments"); // IN and OUT stand for the files
    QTest::addColumn<QByteArray>("input");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("message"); // a part of standard error; IN stands for the input path

    const QStringList convert{"convert", "IN", "-o", "OUT", "--to", "quat"};
    const QStringList interpolate{"interpolate", "IN", "-o", "OUT", "--method", "slerp", "--fps", "24"};
    const QByteArray oneObject = project({projectObject(1, "car", "null", randomKeys(2, 3))});
    QTest::newRow("export to an unknown format") << QStringList{"export", "IN", "-o", "OUT"} << oneObject << 2
                                                 << "export: -o: the file's extension must name a scene format";
    QTest::newRow("import random bytes") << QStringList{"import", "IN", "-o", "OUT"}
                                         << QByteArray("\x13\x37garbage\x01\x02 not a scene") << 1 << "IN: ";
    QTest::newRow("import an empty file") << QStringList{"import", "IN", "-o", "OUT"} << QByteArray() << 1 << "IN: ";
    QTest::newRow("bake an unknown object") << QStringList{"bake", "IN", "--object", "bus", "--fps", "24", "-o", "OUT"}
                                            << oneObject << 1 << "IN: --object: no object is named 'bus'";
    QTest::newRow("bake without fps") << QStringList{"bake", "IN", "--object", "car", "-o", "OUT"} << oneObject << 2
                                      << "bake: missing option --fps";
    const QStringList subdivide{"subdivide", "IN", "-o", "OUT", "--scheme", "four-point", "--levels", "2"};
    const QByteArray keys = "time,qw,qx,qy,qz\n0,1,0,0,0\n1,0,1,0,0\n2,0,0,1,0\n";

    QTest::newRow("empty file") << convert << QByteArray() << 1 << "IN:1: no header row";
    QTest::newRow("header only") << convert << QByteArray("time,qw,qx,qy,qz\n") << 1
                                 << "IN:1: no poses after the header on line 1";
    QTest::newRow("missing column") << interpolate << QByteArray("time,qw,qx,qy\n0,1,0,0\n") << 1
                                    << "IN:1: missing column qz";
    QTest::newRow("text in a number") << convert << QByteArray("qw,qx,qy,qz\n1,0,0,0\n# c\n1,zero,0,0\n") << 1
                                      << "IN:4: column qx: 'zero' is not a number";
    QTest::newRow("NaN") << subdivide << QByteArray("qw,qx,qy,qz\n1,0,0,0\n1,0,NaN,0\n") << 1
                         << "IN:3: column qy: 'NaN' is not a finite number";
    QTest::newRow("infinity") << interpolate << QByteArray(keys + "3,1,0,0,inf\n") << 1
                              << "IN:5: column qz: 'inf' is not a finite number";
    QTest::newRow("zero quaternion") << convert << QByteArray("qw,qx,qy,qz\n0,0,0,0\n") << 1
                                     << "IN:2: columns qw,qx,qy,qz: the quaternion is zero";
    QTest::newRow("times that do not increase") << interpolate << QByteArray(keys + "1.5,1,0,0,0\n") << 1
                                                << "IN:5: column time: 1.5 does not come after 2 on line 4";
    QTest::newRow("short row") << subdivide << QByteArray(keys + "3,1,0\n") << 1
                               << "IN:5: 3 fields, but the header on line 1 has 5";
    QTest::newRow("binary garbage") << convert << QByteArray("\x7f" "ELF\x02\x01\x01\0\0\0\0", 12) << 1
                                    << "IN:1: control character 0x7F at byte 1";
    QTest::newRow("huge line") << interpolate << QByteArray(200'000, '7') << 1 << "IN:1: line longer than 65536 bytes";
    QTest::newRow("interpolate without times") << interpolate << QByteArray("qw,qx,qy,qz\n1,0,0,0\n1,0,0,0\n") << 1
                                               << "IN:1: missing column time";
    QTest::newRow("interpolate one key") << interpolate << QByteArray("time,qw,qx,qy,qz\n# one\n0,1,0,0,0\n") << 1
                                         << "IN:3: interpolate needs at least two keys";
    QTest::newRow("subdivide one pose") << subdivide << QByteArray("qw,qx,qy,qz\n1,0,0,0\n") << 1
                                        << "IN:2: subdivide needs at least two poses";
    QTest::newRow("input is missing") << convert << QByteArray("<missing>") << 1
                                      << "IN: cannot open: No such file or directory";
    QTest::newRow("input is a folder") << convert << QByteArray("<folder>") << 1 << "IN: is a directory";

    const QString wheel = projectObject(1, "wheel", "null", randomKeys(2, 8));
    const QStringList keysVerb{"keys", "IN", "-o", "OUT", "--object", "wheel"};
    QTest::newRow("project of a newer version") << keysVerb << project({wheel}, 4) << 1
                                                << "IN: version: the file has version 4, newer than this build";
    QTest::newRow("no such object") << QStringList{"keys", "IN", "-o", "OUT", "--object", "ghost"} << project({wheel})
                                    << 1 << "IN: --object: no object is named 'ghost'";
    QTest::newRow("two objects of that name")
        << keysVerb << project({wheel, projectObject(2, "wheel", "null", randomKeys(2, 9))}) << 1
        << "IN: --object: 2 objects are named 'wheel'; the name must single out one";
    QTest::newRow("object without keys") << keysVerb << project({projectObject(1, "wheel", "null", {})}) << 1
                                         << "IN: --object: object 'wheel' has no keyframes";
    QTest::newRow("keys without --object") << QStringList{"keys", "IN", "-o", "OUT"} << project({wheel}) << 2
                                           << "keys: missing option --object";
    QTest::newRow("bad project field") << QStringList{"keys", "IN", "--object", "wheel", "-o", "OUT"}
                                       << QByteArray(project({wheel})).replace("\"fps\": 30", "\"fps\": \"30\"") << 1
                                       << "IN: fps: expected a number, found the string \"30\"";
    // Only a .gyre file is read as a project; anything else goes to Assimp as a scene.
    QTest::newRow("info of a pose file") << QStringList{"info", "IN"} << keys << 1 << "IN: not a scene Gyre can read";
    QTest::newRow("info with -o") << QStringList{"info", "IN", "-o", "OUT"} << project({wheel}) << 2
                                  << "info: unknown option -o";

    QTest::newRow("unknown method") << QStringList{"interpolate", "IN", "-o", "OUT", "--method", "cubic", "--fps", "24"}
                                    << keys << 2
                                    << "interpolate: --method: unknown value 'cubic'; expected slerp, nlerp, squad, "
                                       "hermite, euler, euler-cubic, screw or ballistic";
    QTest::newRow("unknown scheme") << QStringList{"subdivide", "IN", "-o", "OUT", "--scheme", "loop", "--levels", "2"}
                                    << keys << 2
                                    << "subdivide: --scheme: unknown value 'loop'; expected four-point, four-point-b, "
                                       "bspline or jarek";
    QTest::newRow("unknown column set") << QStringList{"convert", "IN", "-o", "OUT", "--to", "quaternion"} << keys << 2
                                        << "convert: --to: unknown value 'quaternion'; expected quat, matrix, "
                                           "axis-angle, rotvec or euler";
    for (const char* fps : {"0", "-24"})
        QTest::addRow("fps %s", fps) << QStringList{"interpolate", "IN", "-o", "OUT", "--method", "slerp", "--fps", fps}
                                     << keys << 2 << QStringLiteral("interpolate: --fps: '%1' is not positive").arg(fps);
    QTest::newRow("fps text") << QStringList{"interpolate", "IN", "-o", "OUT", "--method", "slerp", "--fps", "fast"}
                              << keys << 2 << "interpolate: --fps: 'fast' is not a number";
    QTest::newRow("fps nan") << QStringList{"interpolate", "IN", "-o", "OUT", "--method", "slerp", "--fps", "nan"}
                             << keys << 2 << "interpolate: --fps: 'nan' is not a finite number";
    QTest::newRow("too many frames") << QStringList{"interpolate", "IN", "-o", "OUT", "--method", "slerp", "--fps", "1000"}
                                     << QByteArray("time,qw,qx,qy,qz\n0,1,0,0,0\n20000,0,1,0,0\n") << 2
                                     << "interpolate: --fps 1000 over 20000 s gives more than 16777216";
    QTest::newRow("frame rate above the cap")
        << QStringList{"interpolate", "IN", "-o", "OUT", "--method", "slerp", "--fps", "1e7"} << keys << 2
        << "interpolate: --fps: a frame rate of 1e+07 is above 1000";
    QTest::newRow("too deep") << QStringList{"subdivide", "IN", "-o", "OUT", "--scheme", "bspline", "--levels", "23"}
                              << keys << 2 << "subdivide: --levels 23 would turn 3 poses into more than 16777216";
    QTest::newRow("far too deep") << QStringList{"subdivide", "IN", "-o", "OUT", "--scheme", "bspline", "--levels", "2000"}
                                  << keys << 2 << "subdivide: --levels 2000 would turn 3 poses into more than 16777216";
    QTest::newRow("negative levels") << QStringList{"subdivide", "IN", "-o", "OUT", "--scheme", "jarek", "--levels", "-1"}
                                     << keys << 2 << "subdivide: --levels: '-1' is not a whole number ≥ 0";
    QTest::newRow("fractional levels") << QStringList{"subdivide", "IN", "-o", "OUT", "--scheme", "jarek", "--levels", "1.5"}
                                       << keys << 2 << "subdivide: --levels: '1.5' is not a whole number ≥ 0";
    QTest::newRow("unknown verb") << QStringList{"smooth", "IN", "-o", "OUT"} << keys << 2 << "unknown verb 'smooth'";
    QTest::newRow("unknown option") << convert + QStringList{"--colour", "red"} << keys << 2
                                    << "convert: unknown option --colour";
    QTest::newRow("missing -o") << QStringList{"convert", "IN", "--to", "quat"} << keys << 2
                                << "convert: missing option -o";
    QTest::newRow("missing --to") << QStringList{"convert", "IN", "-o", "OUT"} << keys << 2
                                  << "convert: missing option --to";
    QTest::newRow("missing --fps") << QStringList{"interpolate", "IN", "-o", "OUT", "--method", "slerp"} << keys << 2
                                   << "interpolate: missing option --fps";
    QTest::newRow("missing value") << QStringList{"subdivide", "IN", "-o", "OUT", "--scheme", "jarek", "--levels"} << keys
                                   << 2 << "subdivide: Missing value after '--levels'";
    QTest::newRow("no input file") << QStringList{"convert", "-o", "OUT", "--to", "quat"} << keys << 2
                                   << "convert: no input file";
    QTest::newRow("two input files") << QStringList{"convert", "IN", "IN", "-o", "OUT", "--to", "quat"} << keys << 2
                                     << "convert: one input file expected, got 2";
    QTest::newRow("-o twice") << convert + QStringList{"-o", "OUT"} << keys << 2
                              << "convert: option -o given more than once";
    QTest::newRow("both frames") << convert + QStringList{"--intrinsic", "--extrinsic"} << keys << 2
                                 << "convert: --intrinsic and --extrinsic exclude each other";
    QTest::newRow("bad order") << convert + QStringList{"--order", "xxz"} << keys << 2 << "convert: --order: 'xxz'";
}

// Every bad input ends with a message naming the file and line or the option, a non-zero status,
// and no output: none where there was none, the old contents where there was a file.
void TstCli::badInput()
{
    QFETCH(QStringList, arguments);
    QFETCH(QByteArray, input);
    QFETCH(int, exitCode);
    QFETCH(QString, message);
    QString in = path("bad-input.csv");
    if (input == "<folder>")
        in = dir_.path();
    else if (input == "<missing>")
        QFile::remove(in);
    else
        writeFile("bad-input.csv", input);
    const QString out = path("bad-output.csv");
    arguments.replaceInStrings(QRegularExpression("^IN$"), in);
    arguments.replaceInStrings(QRegularExpression("^OUT$"), out);
    message.replace(QStringLiteral("IN"), in);

    for (const bool outputExists : {false, true}) {
        QFile::remove(out);
        if (outputExists)
            writeFile("bad-output.csv", "precious\n");
        const CliRun run = runCli(arguments);
        QVERIFY(run.exitedNormally);
        QCOMPARE(run.exitCode, exitCode);
        // One line, so a sanitizer report or a second message cannot pass for the expected one.
        QVERIFY2(run.err.startsWith("gyre-cli: ") && run.err.count('\n') == 1 && run.err.endsWith('\n'),
                 qPrintable(run.err));
        QVERIFY2(run.err.contains(message), qPrintable(run.err));
        QCOMPARE(run.out, QString());
        if (outputExists)
            QCOMPARE(contentsOf(out), QByteArray("precious\n"));
        else
            QVERIFY(!QFile::exists(out));
    }
    // QSaveFile's temporary files do not linger either.
    QCOMPARE(QDir(dir_.path()).entryList({"bad-output*"}, QDir::Files), QStringList{"bad-output.csv"});
}

void TstCli::missingOutputFolder()
{
    const QString in = writeFile("good.csv", keysCsv(randomKeys(3, 1)));
    const QString out = path("no-such-folder/out.csv");
    const CliRun run = runCli({"convert", in, "-o", out, "--to", "matrix"});
    QVERIFY(run.exitedNormally);
    QCOMPARE(run.exitCode, 1);
    QVERIFY2(run.err.startsWith("gyre-cli: " + out + ": cannot write: "), qPrintable(run.err));
    QVERIFY(!QFileInfo::exists(path("no-such-folder")));
}

void TstCli::helpAndVersion()
{
    const CliRun help = runCli({"--help"});
    QCOMPARE(help.exitCode, 0);
    for (const char* verb : {"convert", "interpolate", "subdivide", "fit", "info", "keys"}) {
        QVERIFY(help.out.contains(verb));
        const CliRun verbHelp = runCli({"help", verb});
        QCOMPARE(verbHelp.exitCode, 0);
        QVERIFY(verbHelp.out.startsWith(QStringLiteral("Usage: gyre-cli ") + verb));
        QCOMPARE(runCli({verb, "--help"}).out, verbHelp.out);
        QCOMPARE(runCli({verb, "-o", "x.csv", "-h"}).out, verbHelp.out);
    }
    QVERIFY(runCli({"help", "convert"}).out.contains("--to SET"));
    QVERIFY(runCli({"help", "interpolate"}).out.contains("--fps F"));
    QVERIFY(runCli({"help", "subdivide"}).out.contains("--levels L"));
    const CliRun version = runCli({"--version"});
    QCOMPARE(version.exitCode, 0);
    QCOMPARE(version.out, QStringLiteral("gyre-cli " GYRE_VERSION "\n"));
    const CliRun nothing = runCli({});
    QCOMPARE(nothing.exitCode, 2);
    QCOMPARE(nothing.err, QStringLiteral("gyre-cli: no verb given (see gyre-cli --help)\n"));
    const CliRun unknownHelp = runCli({"help", "smooth"});
    QCOMPARE(unknownHelp.exitCode, 2);
    QVERIFY(unknownHelp.err.contains("unknown verb 'smooth'"));
}

} // namespace

QTEST_GUILESS_MAIN(TstCli)
#include "tst_cli.moc"
