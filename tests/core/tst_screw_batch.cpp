// ScrewBatch and screwMidpoints against the single Screw they batch: random pose pairs, near-zero and
// near-π angles, pure translations, identical poses, batch sizes around the lane count, and a t far
// enough out that the trigonometry leaves its reduced range.

#include "core/screw.h"
#include "core/screw_batch.h"

#include "core_test_support.h"

#include <QObject>
#include <QTest>

#include <vector>

using namespace gyre;
using namespace gyre::test;

namespace {

// The tolerance of the core's tests: the batch runs the single screw's operations, so in practice
// the results agree to the bit.
constexpr double kTolerance = 1e-15;

double largestDifference(const Pose& a, const Pose& b)
{
    return std::max((a.orientation.coeffs() - b.orientation.coeffs()).cwiseAbs().maxCoeff(),
                    (a.position - b.position).cwiseAbs().maxCoeff());
}

// Pairs of every kind the screw treats apart, then random ones, `count` in all.
void posePairs(Random& random, std::size_t count, std::vector<Pose>& from, std::vector<Pose>& to)
{
    from.clear();
    to.clear();
    const auto add = [&](const Pose& a, const Pose& b) {
        from.push_back(a);
        to.push_back(b);
    };
    while (from.size() < count) {
        const Pose a{random.rotation(), random.vector(5.0)};
        switch (from.size() % 8) {
        case 0: // near-zero angles, down to none at all
            add(a, {a.orientation * random.rotationWithAngle(1e-12, 1e-6), random.vector(5.0)});
            break;
        case 1: // near π, on either side of the short arc
            add(a, {a.orientation * random.rotationWithAngle(kPi - 1e-7, kPi), random.vector(5.0)});
            break;
        case 2: // a pure translation
            add(a, {a.orientation, random.vector(5.0)});
            break;
        case 3: // identical poses
            add(a, a);
            break;
        case 4: // the other sign of the same end orientation
            add(a, {negated(random.rotation()), random.vector(5.0)});
            break;
        case 5: // exactly π about an axis
            add(a, {a.orientation * axisAngleQuaternion(random.unitVector(), kPi), random.vector(5.0)});
            break;
        default:
            add(a, {random.rotation(), random.vector(5.0)});
            break;
        }
    }
}

} // namespace

class TestScrewBatch : public QObject {
    Q_OBJECT

private slots:
    void batchMatchesSingleScrews();
    void midpointsMatchSingleMidpoints();
    void mismatchedSizesAreRefused();
};

void TestScrewBatch::batchMatchesSingleScrews()
{
    Random random(31);
    std::vector<Pose> from;
    std::vector<Pose> to;
    ScrewBatch batch;
    double largest = 0.0;
    for (const std::size_t count : {std::size_t{0}, std::size_t{1}, kScrewLanes - 1, kScrewLanes, kScrewLanes + 1,
                                    std::size_t{203}}) {
        posePairs(random, count, from, to);
        batch.assign(from, to);
        QCOMPARE(batch.size(), count);
        std::vector<Pose> out(count);
        // 3000 turns the larger angles past the reduced range of fastSinCos.
        for (const double t : {-0.25, 0.0, 1.0 / 16.0, 0.5, 1.0, 9.0 / 8.0, 2.0, 3000.0}) {
            batch.evaluate(t, out);
            for (std::size_t i = 0; i < count; ++i) {
                const Pose single = Screw(from[i], to[i]).at(t);
                const double difference = largestDifference(out[i], single);
                largest = std::max(largest, difference);
                GYRE_CHECK(difference <= kTolerance, QStringLiteral("pair %1 of %2 at t = %3: %4 against %5")
                                                         .arg(i).arg(count).arg(t).arg(str(out[i]), str(single)));
            }
        }
    }
    qInfo("largest difference from the single screw: %g", largest);
}

void TestScrewBatch::midpointsMatchSingleMidpoints()
{
    Random random(37);
    std::vector<Pose> from;
    std::vector<Pose> to;
    for (const std::size_t count : {std::size_t{1}, kScrewLanes, std::size_t{203}}) {
        posePairs(random, count, from, to);
        std::vector<Pose> out(count);
        screwMidpoints(from, to, out);
        for (std::size_t i = 0; i < count; ++i) {
            const Pose single = Screw::midpoint(from[i], to[i]);
            GYRE_CHECK(largestDifference(out[i], single) <= kTolerance,
                       QStringLiteral("pair %1 of %2: %3 against %4").arg(i).arg(count).arg(str(out[i]), str(single)));
        }
    }
}

void TestScrewBatch::mismatchedSizesAreRefused()
{
    const std::vector<Pose> two(2);
    const std::vector<Pose> three(3);
    std::vector<Pose> out(2);
    ScrewBatch batch;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, batch.assign(two, three));
    batch.assign(two, two);
    std::vector<Pose> wrong(3);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, batch.evaluate(0.5, wrong));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, screwMidpoints(two, two, wrong));
}

QTEST_GUILESS_MAIN(TestScrewBatch)
#include "tst_screw_batch.moc"
