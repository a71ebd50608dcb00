// Writes the fuzz seeds (fuzz_inputs.h) as libFuzzer corpora: <dir>/pose_csv holds the CSV seeds,
// <dir>/project the project seeds.
#include "fuzz_inputs.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <cstdio>

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s CORPUS_DIR\n", argv[0]);
        return 2;
    }
    const QDir corpus(QString::fromLocal8Bit(argv[1]));
    QTemporaryDir scratch;
    for (const gyre::fuzz::Seed& seed : gyre::fuzz::makeSeeds(scratch.path())) {
        const QString folder = seed.reader == gyre::fuzz::Reader::Project ? QStringLiteral("project") : QStringLiteral("pose_csv");
        QFile file(corpus.filePath(folder + QLatin1Char('/') + seed.name));
        if (!corpus.mkpath(folder) || !file.open(QIODevice::WriteOnly) || file.write(seed.bytes) != seed.bytes.size()) {
            std::fprintf(stderr, "cannot write %s\n", qPrintable(file.fileName()));
            return 1;
        }
    }
    return 0;
}
