// Mutation fuzzing of Gyre's readers: every seed file of fuzz_inputs.h is mutated a fixed number of
// times from a fixed seed, and each mutant goes through its reader (and, for an accepted project or
// scene, through the evaluation of every track). Each input must end in acceptance or an InputError
// whose message names the file and the line or field; nothing else may be thrown, evaluation must stay
// finite, and no input may take longer than kInputBound. Under the sanitizer build any memory error or
// undefined behaviour aborts the test.
//
// Scene files are read by Assimp in gyre-scene-worker, as the app and gyre-cli read them: Assimp
// 5.2.5 crashes, aborts or loops on some of these mutants, and each of those must come back as a
// refusal naming the file while this process carries on. A worker process per input costs far more
// than a parse in process, hence fewer mutants.
//
//   GYRE_FUZZ_SEED              the generator's seed (default kDefaultSeed); a failure replays from it
//   GYRE_FUZZ_ITERATIONS        mutants per seed file (default kDefaultIterations)
//   GYRE_FUZZ_SCENE_ITERATIONS  mutants per scene seed file (default kDefaultSceneIterations)

#include "built_scene_worker.h"
#include "fuzz_inputs.h"
#include "mutator.h"
#include "model/project_file.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <exception>
#include <typeinfo>

using namespace gyre::fuzz;

namespace {

constexpr unsigned kDefaultSeed = 20261125;
constexpr int kDefaultIterations = 100;
constexpr int kDefaultSceneIterations = 40;
// Far above what any input takes (milliseconds) even under the sanitizers: a reader that loops or
// does work out of proportion to its input shows as a failure here, not as a hung test. A scene file
// adds a worker's start, and the worker's own time limit (fuzz_inputs.cpp) stops a reader that loops.
constexpr qint64 kInputBoundMs = 5000;
constexpr qint64 kSceneInputBoundMs = 15000;

unsigned environmentNumber(const char* name, unsigned fallback)
{
    if (!qEnvironmentVariableIsSet(name))
        return fallback;
    bool ok = false;
    const unsigned value = qEnvironmentVariable(name).toUInt(&ok);
    if (!ok)
        qFatal("%s must be a non-negative whole number", name);
    return value;
}

} // namespace

class TestFuzzReaders : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void seedsAreAccepted_data() { seedRows(); }
    void seedsAreAccepted();
    void mutantsAreAcceptedOrRefusedWithTheirFile_data() { seedRows(); }
    void mutantsAreAcceptedOrRefusedWithTheirFile();
    void sceneSeedsAreAccepted_data() { sceneSeedRows(); }
    void sceneSeedsAreAccepted();
    void sceneMutantsAreAcceptedOrRefusedWithTheirFile_data() { sceneSeedRows(); }
    void sceneMutantsAreAcceptedOrRefusedWithTheirFile();
    void hugeKeyPositionsEvaluateFinite();

private:
    static void rows(const std::vector<Seed>& seeds);
    void seedRows() { rows(seeds_); }
    void sceneSeedRows() { rows(sceneSeeds_); }
    const Seed& seedNamed(const QString& name) const;
    void checkSeedIsAccepted(const Seed& seed);
    // Runs `iterations` mutants of `seed`, the `index`th of its list, through its reader.
    void checkMutants(const Seed& seed, int index, int iterations, qint64 inputBoundMs);
    // Fails with the input saved for replay if `problem` is set.
    void check(const std::optional<std::string>& problem, const QString& seedName, const QByteArray& input, int mutant);

    QTemporaryDir dir_;
    std::vector<Seed> seeds_;
    std::vector<Seed> sceneSeeds_;
    unsigned seed_ = kDefaultSeed;
    int iterations_ = kDefaultIterations;
    int sceneIterations_ = kDefaultSceneIterations;
};

void TestFuzzReaders::initTestCase()
{
    QVERIFY(dir_.isValid());
    seed_ = environmentNumber("GYRE_FUZZ_SEED", kDefaultSeed);
    iterations_ = static_cast<int>(environmentNumber("GYRE_FUZZ_ITERATIONS", kDefaultIterations));
    sceneIterations_ = static_cast<int>(environmentNumber("GYRE_FUZZ_SCENE_ITERATIONS", kDefaultSceneIterations));
    qInfo("GYRE_FUZZ_SEED=%u GYRE_FUZZ_ITERATIONS=%d GYRE_FUZZ_SCENE_ITERATIONS=%d", seed_, iterations_,
          sceneIterations_);
    gyre::test::useBuiltSceneWorker();
    QVERIFY(QDir(dir_.path()).mkpath(QStringLiteral("seeds")));
    seeds_ = makeSeeds(dir_.filePath(QStringLiteral("seeds")));
    sceneSeeds_ = makeSceneSeeds(dir_.filePath(QStringLiteral("seeds")));
}

void TestFuzzReaders::rows(const std::vector<Seed>& seeds)
{
    QTest::addColumn<int>("index");
    for (std::size_t i = 0; i < seeds.size(); ++i)
        QTest::newRow(qPrintable(seeds[i].name)) << static_cast<int>(i);
}

void TestFuzzReaders::check(const std::optional<std::string>& problem, const QString& seedName,
                            const QByteArray& input, int mutant)
{
    if (!problem)
        return;
    const QString saved = QDir::temp().filePath(QStringLiteral("gyre-fuzz-%1-%2").arg(mutant).arg(seedName));
    QFile file(saved);
    if (file.open(QIODevice::WriteOnly))
        file.write(input);
    QFAIL(qPrintable(QStringLiteral("mutant %1 of %2 (GYRE_FUZZ_SEED=%3, saved as %4): %5")
                         .arg(mutant)
                         .arg(seedName)
                         .arg(seed_)
                         .arg(saved, QString::fromStdString(*problem))));
}

// The seeds themselves are valid files: otherwise their mutants would test little beyond refusal.
void TestFuzzReaders::seedsAreAccepted()
{
    QFETCH(int, index);
    checkSeedIsAccepted(seeds_[static_cast<std::size_t>(index)]);
}

void TestFuzzReaders::sceneSeedsAreAccepted()
{
    QFETCH(int, index);
    checkSeedIsAccepted(sceneSeeds_[static_cast<std::size_t>(index)]);
}

void TestFuzzReaders::checkSeedIsAccepted(const Seed& seed)
{
    const Outcome outcome = readInput(seed.reader, seed.bytes, dir_.filePath(seed.name));
    QVERIFY2(outcome.accepted, outcome.refusal.c_str());
    QVERIFY2(!outcome.evaluationProblem, outcome.evaluationProblem.value_or("").c_str());
    if (seed.reader == Reader::Project || seed.reader == Reader::Scene) {
        QCOMPARE_GT(outcome.tracksEvaluated, 0);
        QCOMPARE(outcome.tracksRefusedByEvaluation, 0);
    }
}

void TestFuzzReaders::mutantsAreAcceptedOrRefusedWithTheirFile()
{
    QFETCH(int, index);
    checkMutants(seeds_[static_cast<std::size_t>(index)], index, iterations_, kInputBoundMs);
}

void TestFuzzReaders::sceneMutantsAreAcceptedOrRefusedWithTheirFile()
{
    QFETCH(int, index);
    // Generators apart from those of the other seeds, so that each row replays on its own.
    checkMutants(sceneSeeds_[static_cast<std::size_t>(index)], static_cast<int>(seeds_.size()) + index,
                 sceneIterations_, kSceneInputBoundMs);
}

void TestFuzzReaders::checkMutants(const Seed& seed, int index, int iterations, qint64 inputBoundMs)
{
    // One generator per seed file, so that each row replays on its own.
    Mutator mutator(seed_ + static_cast<unsigned>(index));
    const QString path = dir_.filePath(seed.name);
    int accepted = 0;
    int refused = 0;
    qint64 slowestMs = 0;
    for (int mutant = 0; mutant < iterations; ++mutant) {
        const QByteArray input = mutator.mutate(seed.bytes, seed.reader == Reader::Project);
        QElapsedTimer timer;
        timer.start();
        Outcome outcome;
        try {
            outcome = readInput(seed.reader, input, path);
        } catch (const std::exception& error) {
            check(std::string("threw ") + typeid(error).name() + ": " + error.what(), seed.name, input, mutant);
            return;
        }
        const qint64 elapsedMs = timer.elapsed();
        slowestMs = std::max(slowestMs, elapsedMs);
        if (elapsedMs > inputBoundMs)
            check("took " + std::to_string(elapsedMs) + " ms", seed.name, input, mutant);
        if (outcome.accepted) {
            ++accepted;
            check(outcome.evaluationProblem, seed.name, input, mutant);
        } else {
            ++refused;
            if (const auto problem = refusalProblem(seed.reader, outcome.refusal, path))
                check("message \"" + outcome.refusal + "\" " + *problem, seed.name, input, mutant);
        }
        if (QTest::currentTestFailed())
            return;
    }
    qInfo("%s: %d mutants accepted, %d refused, slowest %lld ms", qPrintable(seed.name), accepted, refused,
          static_cast<long long>(slowestMs));
    // The mutations do break the files: a mutator that changed nothing would pass every check above.
    // Assimp's readers forgive more than Gyre's (a flipped digit in a vertex is still a mesh), so
    // among the scene files only some mutants need be refused.
    const int leastRefused = seed.reader == Reader::Scene ? iterations / 8 : iterations / 4;
    if (iterations >= 10)
        QCOMPARE_GT(refused, leastRefused);
}

// Found by this test: a key position of 1e308 was accepted, and squad's cubic positions and the screw
// between such keys overflowed to inf and nan. The reader now refuses it, naming the field.
void TestFuzzReaders::hugeKeyPositionsEvaluateFinite()
{
    const QString path = dir_.filePath(QStringLiteral("huge-position.gyre"));
    for (const gyre::InterpolationMethod method : {gyre::InterpolationMethod::Squad, gyre::InterpolationMethod::Screw}) {
        gyre::model::Scene scene = gyre::model::parseProject(seedNamed(QStringLiteral("mesh.gyre")).bytes, path);
        gyre::model::MotionTrack& track = scene.objects[0].track;
        track.interpolation = method;
        track.keys[1].pose.position = {1.0, 0.0, -1e308};
        // projectBytes writes what it is given, unchecked, as a damaged or hostile file would hold it.
        const Outcome outcome = readInput(Reader::Project, gyre::model::projectBytes(scene), path);
        QVERIFY(!outcome.accepted);
        QVERIFY2(!refusalProblem(Reader::Project, outcome.refusal, path), outcome.refusal.c_str());
        QVERIFY2(outcome.refusal.find("keyframes[1].position") != std::string::npos, outcome.refusal.c_str());
    }
}

const Seed& TestFuzzReaders::seedNamed(const QString& name) const
{
    const auto found = std::ranges::find(seeds_, name, &Seed::name);
    if (found == seeds_.end())
        qFatal("no seed %s", qPrintable(name));
    return *found;
}

QTEST_GUILESS_MAIN(TestFuzzReaders)
#include "tst_fuzz_readers.moc"
