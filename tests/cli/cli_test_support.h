#pragma once
// What the gyre-cli tests share: running the real binary, and reading the CSV files it writes with
// a parser of the tests' own.

#include <QFile>
#include <QObject>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

#include <Eigen/Geometry>

#include <vector>

namespace gyre::test {

struct CliRun {
    bool exitedNormally = false; // no crash, no hang
    int exitCode = -1;
    QString out;
    QString err;
};

inline CliRun runCli(const QStringList& arguments)
{
    QProcess process;
    process.start(QStringLiteral(GYRE_CLI_PATH), arguments);
    CliRun run;
    if (!process.waitForFinished(120'000)) {
        process.kill();
        process.waitForFinished();
        return run;
    }
    run.exitedNormally = process.exitStatus() == QProcess::NormalExit;
    run.exitCode = process.exitCode();
    run.out = QString::fromUtf8(process.readAllStandardOutput());
    run.err = QString::fromUtf8(process.readAllStandardError());
    return run;
}

// A CSV file as this test reads it: header names and rows of numbers, no comments.
struct Csv {
    QStringList header;
    std::vector<std::vector<double>> rows;
    QString problem; // empty if the file read cleanly

    double at(std::size_t row, const QString& column) const
    {
        return rows[row][static_cast<std::size_t>(header.indexOf(column))];
    }
    Eigen::Quaterniond quaternion(std::size_t row) const
    {
        return {at(row, "qw"), at(row, "qx"), at(row, "qy"), at(row, "qz")};
    }
    Eigen::Vector3d vector(std::size_t row, const char* a, const char* b, const char* c) const
    {
        return {at(row, a), at(row, b), at(row, c)};
    }
    Eigen::Vector3d position(std::size_t row) const { return vector(row, "x", "y", "z"); }
    std::vector<double> times() const
    {
        std::vector<double> result;
        for (std::size_t row = 0; row < rows.size(); ++row)
            result.push_back(at(row, "time"));
        return result;
    }
};

inline Csv readCsv(const QString& path)
{
    Csv csv;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        csv.problem = "cannot open " + path;
        return csv;
    }
    const QStringList lines = QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts);
    if (lines.isEmpty()) {
        csv.problem = path + " is empty";
        return csv;
    }
    csv.header = lines.front().split(',');
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QStringList fields = lines[i].split(',');
        if (fields.size() != csv.header.size())
            csv.problem = QStringLiteral("%1:%2: wrong field count").arg(path).arg(i + 1);
        std::vector<double> row;
        for (const QString& field : fields) {
            bool ok = false;
            row.push_back(field.toDouble(&ok));
            if (!ok)
                csv.problem = QStringLiteral("%1:%2: '%3' is not a number").arg(path).arg(i + 1).arg(field);
        }
        csv.rows.push_back(row);
    }
    return csv;
}

// `contents` written to the file `name` in `folder`; its path.
inline QString writeFileIn(const QTemporaryDir& folder, const QString& name, const QByteArray& contents)
{
    QFile file(folder.filePath(name));
    if (!file.open(QIODevice::WriteOnly) || file.write(contents) != contents.size())
        qFatal("cannot write %s", qPrintable(name));
    return file.fileName();
}

inline QString number(double value) { return QString::number(value, 'g', 17); }

// What gyre-cli may print on standard error when it succeeds.
enum class Warnings { Allowed, Refused };

// The base of a gyre-cli test: a temporary folder for its fixtures and outputs, and a check that a
// run succeeded.
class CliTestCase : public QObject {
protected:
    QString path(const QString& name) const { return dir_.filePath(name); }

    QString writeFile(const QString& name, const QByteArray& contents) const
    {
        const QString filePath = path(name);
        QFile file(filePath);
        if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(contents) != contents.size())
            qFatal("cannot write the fixture %s", qPrintable(filePath));
        return filePath;
    }

    // Runs gyre-cli and checks that it exited normally with status 0 (and, if warnings are refused,
    // printed nothing on standard error); says what went wrong otherwise.
    static bool succeeds(const QStringList& arguments, Warnings warnings = Warnings::Allowed)
    {
        const CliRun run = runCli(arguments);
        if (run.exitedNormally && run.exitCode == 0 && (warnings == Warnings::Allowed || run.err.isEmpty()))
            return true;
        qWarning("gyre-cli %s: exit %d: %s", qPrintable(arguments.join(' ')), run.exitCode, qPrintable(run.err));
        return false;
    }

    QTemporaryDir dir_;
};

} // namespace gyre::test
