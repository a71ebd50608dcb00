// gyre-cli interpolate --method ballistic: the frames it writes meet the keys, conserve the angular momentum
// and kinetic energy of the body whose inertia the command line gives (ω from the frames themselves, by central
// differences), and put the body on the parabola under gravity; --solution picks solutions in order of energy;
// a bad --inertia, --solution, --gravity or --up is refused with a message that names the option.

#include "cli_test_support.h"
#include "core/core_test_support.h"
#include "core/mass_properties.h"
#include "core/torque_free.h"

#include <QTest>

#include <cmath>

using namespace gyre;
using namespace gyre::test;

namespace {

// The world angular velocity at row i by the central difference of its neighbours' orientations.
Eigen::Vector3d omegaAt(const Csv& csv, std::size_t i)
{
    const Eigen::Quaterniond d = csv.quaternion(i + 1).normalized() * csv.quaternion(i - 1).normalized().conjugate();
    const Eigen::AngleAxisd turn(d.w() < 0 ? Eigen::Quaterniond(-d.coeffs()) : d);
    return turn.angle() * turn.axis() / (csv.at(i + 1, "time") - csv.at(i - 1, "time"));
}

} // namespace

class TstCliBallistic : public QObject {
    Q_OBJECT

private slots:
    void framesFlyBetweenTheKeys();
    void solutionsByEnergy();
    void refusesBadOptions_data();
    void refusesBadOptions();

private:
    QString path(const QString& name) const { return directory_.filePath(name); }
    QString keysFile() const
    {
        return writeFileIn(directory_, "keys.csv", "time,qw,qx,qy,qz,x,y,z\n"
                                     "0,1,0,0,0,0,0,1\n"
                                     "0.8,0.5,0.5,-0.5,0.5,2,0,1.5\n");
    }
    QTemporaryDir directory_;
};

void TstCliBallistic::framesFlyBetweenTheKeys()
{
    const QString out = path("flight.csv");
    const CliRun run = runCli({"interpolate", keysFile(), "-o", out, "--method", "ballistic", "--inertia",
                               "0.5,1,1.3,0.1,0,-0.05", "--fps", "1000"});
    QVERIFY2(run.exitedNormally && run.exitCode == 0, qPrintable(run.err));
    const Csv csv = readCsv(out);
    QVERIFY2(csv.problem.isEmpty(), qPrintable(csv.problem));
    QCOMPARE(csv.rows.size(), std::size_t(801));
    const std::size_t last = csv.rows.size() - 1;
    QVERIFY(angleBetween(csv.quaternion(0), Eigen::Quaterniond::Identity()) < 1e-10);
    QVERIFY(angleBetween(csv.quaternion(last), Eigen::Quaterniond(0.5, 0.5, -0.5, 0.5)) < 1e-10);
    QVERIFY((csv.position(last) - Eigen::Vector3d(2, 0, 1.5)).norm() < 1e-9);

    const Eigen::Matrix3d inertia = inertiaTensor({0.5, 1.0, 1.3, 0.1, 0.0, -0.05});
    const auto momentum = [&](std::size_t i) {
        const Eigen::Matrix3d r = csv.quaternion(i).normalized().toRotationMatrix();
        return Eigen::Vector3d(r * inertia * r.transpose() * omegaAt(csv, i));
    };
    const Eigen::Vector3d l0 = momentum(1);
    const double e0 = 0.5 * l0.dot(omegaAt(csv, 1));
    for (std::size_t i = 2; i < last; i += 7) {
        // A central difference over 2 ms is good to about 1e-5 at these rates: the bound is the difference's.
        const Eigen::Vector3d l = momentum(i);
        QVERIFY2((l - l0).norm() < 1e-4 * l0.norm(), qPrintable(QStringLiteral("L at row %1").arg(i)));
        QVERIFY(std::abs(0.5 * l.dot(omegaAt(csv, i)) - e0) < 1e-4 * e0);
        // The parabola: constant acceleration −9.81 along +Z.
        const Eigen::Vector3d a = (csv.position(i + 1) - 2 * csv.position(i) + csv.position(i - 1)) / 1e-6;
        QVERIFY2((a - Eigen::Vector3d(0, 0, -9.81)).norm() < 1e-3, qPrintable(QStringLiteral("a at row %1").arg(i)));
    }
}

void TstCliBallistic::solutionsByEnergy()
{
    const Eigen::Matrix3d inertia = inertiaTensor({0.5, 1.0, 1.3});
    double previous = 0.0;
    for (int k = 0; k < 3; ++k) {
        const QString out = path(QStringLiteral("solution%1.csv").arg(k));
        const CliRun run = runCli({"interpolate", keysFile(), "-o", out, "--method", "ballistic", "--inertia", "0.5,1,1.3",
                                   "--fps", "500", "--solution", QString::number(k), "--gravity", "0"});
        QVERIFY2(run.exitedNormally && run.exitCode == 0, qPrintable(run.err));
        const Csv csv = readCsv(out);
        const Eigen::Matrix3d r = csv.quaternion(1).normalized().toRotationMatrix();
        const Eigen::Vector3d omega = omegaAt(csv, 1);
        const double energy = 0.5 * omega.dot(r * inertia * r.transpose() * omega);
        QVERIFY2(energy > previous, qPrintable(QStringLiteral("solution %1: energy %2 after %3").arg(k).arg(energy).arg(previous)));
        previous = energy;
        QVERIFY((csv.position(100) - Eigen::Vector3d(0.5, 0, 1.125)).norm() < 1e-9);  // no gravity: a line
    }
}

void TstCliBallistic::refusesBadOptions_data()
{
    QTest::addColumn<QStringList>("options");
    QTest::addColumn<QString>("message");
    const QStringList ballistic{"--method", "ballistic", "--fps", "24"};
    QTest::newRow("no inertia") << ballistic << "interpolate: --method ballistic needs --inertia";
    QTest::newRow("two numbers") << ballistic + QStringList{"--inertia", "1,2"}
                                 << "interpolate: --inertia: give 3 numbers (Ixx,Iyy,Izz) or 6 (Ixx,Iyy,Izz,Ixy,Ixz,Iyz), not 2";
    QTest::newRow("four numbers") << ballistic + QStringList{"--inertia", "1,2,3,0"} << "--inertia: give 3 numbers";
    QTest::newRow("not positive definite") << ballistic + QStringList{"--inertia", "1,1,1,2,0,0"}
                                           << "interpolate: --inertia: the inertia tensor is not positive definite";
    QTest::newRow("negative moment") << ballistic + QStringList{"--inertia", "1,-2,3"}
                                     << "interpolate: --inertia: the inertia tensor is not positive definite";
    QTest::newRow("not finite") << ballistic + QStringList{"--inertia", "1,inf,3"} << "interpolate: --inertia: 'inf'";
    QTest::newRow("not a number") << ballistic + QStringList{"--inertia", "1,x,3"} << "interpolate: --inertia: 'x'";
    QTest::newRow("solution too far") << ballistic + QStringList{"--inertia", "1,2,3", "--solution", "99"}
                                      << "interpolate: --solution 99: the flight from key 1 has";
    QTest::newRow("negative gravity") << ballistic + QStringList{"--inertia", "1,2,3", "--gravity", "-1"}
                                      << "interpolate: --gravity: -1 is negative";
    QTest::newRow("zero up") << ballistic + QStringList{"--inertia", "1,2,3", "--up", "0,0,0"}
                             << "interpolate: --up: give a non-zero vector";
    QTest::newRow("inertia without ballistic") << QStringList{"--method", "slerp", "--fps", "24", "--inertia", "1,2,3"}
                                               << "interpolate: --inertia is for --method ballistic alone";
}

void TstCliBallistic::refusesBadOptions()
{
    QFETCH(QStringList, options);
    QFETCH(QString, message);
    const QString out = path("refused.csv");
    const CliRun run = runCli(QStringList{"interpolate", keysFile(), "-o", out} + options);
    QVERIFY(run.exitedNormally);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains(message), qPrintable(run.err));
    QVERIFY(!QFile::exists(out));
}

QTEST_GUILESS_MAIN(TstCliBallistic)
#include "tst_cli_ballistic.moc"
