// The batch screw (screw_batch.h) against the single screw (screw.h), to the bit as it promises, and
// against the SE(3) geodesic La·exp(t·log(La⁻¹Lb)) written in the test with 4×4 matrices, within a
// tolerance; in every version this processor has: the lanes screwsAt chooses (the widest), and each of
// SSE2's, AVX2's and AVX-512's on its own. The pairs mix random poses with the cases the lanes hand to
// the single screw or meet at the edge of their formulas (identical poses, pure translations, rotations
// tending to zero, rotations near a half turn, large translations, t·a beyond the fast sine's range),
// so that one block holds lanes of every kind; and every batch length up to past two blocks. And the
// PoseBuffers the batch reads fastest start on cache lines.

#include "core/screw.h"
#include "core/screw_batch.h"

#include "core_test_support.h"

#include <QObject>
#include <QTest>

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <vector>

using namespace gyre;
using namespace gyre::test;

namespace {

const std::vector<double> kTimes = {-0.5, -1.0 / 16, 0.0, 0.25, 0.5, 0.75, 1.0, 9.0 / 8, 2.0};

using ScrewsAt = void (*)(std::span<const Pose>, std::span<const Pose>, std::span<const double>, std::span<Pose>);
using Midpoints = void (*)(std::span<const Pose>, std::span<const Pose>, std::span<Pose>);

struct Pairs {
    std::vector<Pose> from;
    std::vector<Pose> to;
};

// b's pose relative to a: a's orientation turned by `rotation` in its own frame, moved by `translation`.
Pose compose(const Pose& a, const Eigen::Quaterniond& rotation, const Eigen::Vector3d& translation)
{
    return {a.orientation * rotation, a.orientation * translation + a.position};
}

Pairs mixedPairs()
{
    Random random(2111);
    Pairs pairs;
    const auto add = [&](const Pose& a, const Pose& b) {
        pairs.from.push_back(a);
        pairs.to.push_back(b);
        // A random pair after each, so that the special lanes share blocks with ordinary ones.
        pairs.from.push_back(random.pose(5.0));
        pairs.to.push_back(random.pose(5.0));
    };
    for (int i = 0; i < 100; ++i)
        add(random.pose(5.0), random.pose(5.0));
    for (int i = 0; i < 6; ++i) {
        const Pose a = random.pose(5.0);
        add(a, a);
        add(a, {negated(a.orientation), a.position});
        add(a, {a.orientation, a.position + random.vector(3.0)});
        add(a, {negated(a.orientation), a.position + random.vector(3.0)});
    }
    for (double angle : {1e-3, 1e-7, 1e-10, 1e-14, 1e-150, 1e-200}) // the last two below kNoRotation
        for (int i = 0; i < 4; ++i) {
            const Pose a = random.pose(5.0);
            add(a, compose(a, axisAngleQuaternion(random.unitVector(), angle), i % 2 ? random.vector(3.0) : Eigen::Vector3d::Zero()));
        }
    for (double delta : {1e-3, 1e-6, 1e-8, 0.0})
        for (int i = 0; i < 4; ++i) {
            const Pose a = random.pose(5.0);
            add(a, compose(a, axisAngleQuaternion(random.unitVector(), kPi - delta), i % 2 ? random.vector(3.0) : Eigen::Vector3d::Zero()));
        }
    for (double scale : {1e3, 1e6})
        for (int i = 0; i < 4; ++i)
            add(random.pose(scale), random.pose(scale));
    return pairs;
}

// A pose's seven coefficients: the quaternion's x, y, z, w as Eigen stores them, then the position.
std::array<double, 7> coefficients(const Pose& pose)
{
    const Eigen::Vector4d& q = pose.orientation.coeffs();
    return {q.x(), q.y(), q.z(), q.w(), pose.position.x(), pose.position.y(), pose.position.z()};
}

// Empty when `got` is `expected` to the bit (screw_batch.h's promise: a sign of zero counts too);
// otherwise names the first coefficient that differs and both poses.
QString bitwiseDifference(const Pose& got, const Pose& expected)
{
    static constexpr std::array<const char*, 7> names = {"x", "y", "z", "w", "position x", "position y", "position z"};
    const std::array<double, 7> a = coefficients(got);
    const std::array<double, 7> b = coefficients(expected);
    for (std::size_t c = 0; c < a.size(); ++c)
        if (std::bit_cast<std::uint64_t>(a[c]) != std::bit_cast<std::uint64_t>(b[c]))
            return QStringLiteral("%1 is %2, the single screw's %3 (%4 apart)\n   got      %5\n   expected %6")
                .arg(QLatin1String(names[c]), str(a[c]), str(b[c]), str(a[c] - b[c]), str(got), str(expected));
    return {};
}

template <screw_batch_detail::InstructionSet set>
void screwsWith(std::span<const Pose> from, std::span<const Pose> to, std::span<const double> times, std::span<Pose> out)
{
    screw_batch_detail::screwsAtWith(set, from, to, times, out);
}

template <screw_batch_detail::InstructionSet set>
void midpointsWith(std::span<const Pose> from, std::span<const Pose> to, std::span<Pose> out)
{
    screw_batch_detail::screwMidpointsWith(set, from, to, out);
}

template <screw_batch_detail::InstructionSet set>
void addVersion(const char* name)
{
    if (screw_batch_detail::processorHas(set))
        QTest::newRow(name) << ScrewsAt(screwsWith<set>) << Midpoints(midpointsWith<set>);
}

void addVersions()
{
    using screw_batch_detail::InstructionSet;
    QTest::addColumn<ScrewsAt>("screws");
    QTest::addColumn<Midpoints>("midpoints");
    QTest::newRow("this processor's") << ScrewsAt(screwsAt) << Midpoints(screwMidpoints);
    addVersion<InstructionSet::Sse2>("SSE2");
    addVersion<InstructionSet::Avx2>("AVX2");
    addVersion<InstructionSet::Avx512>("AVX-512");
}

} // namespace

Q_DECLARE_METATYPE(ScrewsAt)
Q_DECLARE_METATYPE(Midpoints)

class TestScrewBatch : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void matchesTheSingleScrew_data() { addVersions(); }
    void matchesTheSingleScrew();
    void midpointsMatchTheSingleScrew_data() { addVersions(); }
    void midpointsMatchTheSingleScrew();
    void followsTheGeodesic_data() { addVersions(); }
    void followsTheGeodesic();
    void everyLength_data() { addVersions(); }
    void everyLength();
    void beyondTheFastSineRange_data() { addVersions(); }
    void beyondTheFastSineRange();
    void refusesSpansOfDifferentLengths();
    void refusesValuesThatAreNoInstructionSet();
    void poseBuffersStartOnCacheLines();
};

void TestScrewBatch::initTestCase()
{
    // The rows name the versions tested; say which this processor lacks, which no row tests.
    using screw_batch_detail::InstructionSet;
    for (InstructionSet set : {InstructionSet::Sse2, InstructionSet::Avx2, InstructionSet::Avx512})
        if (!screw_batch_detail::processorHas(set))
            qInfo("This processor lacks %s: its lanes are not tested here.", screw_batch_detail::instructionSetName(set).c_str());
}

void TestScrewBatch::matchesTheSingleScrew()
{
    QFETCH(ScrewsAt, screws);
    const Pairs pairs = mixedPairs();
    const std::size_t n = pairs.from.size();
    std::vector<Pose> out(n * kTimes.size());
    screws(pairs.from, pairs.to, kTimes, out);
    for (std::size_t k = 0; k < kTimes.size(); ++k)
        for (std::size_t i = 0; i < n; ++i) {
            const QString difference = bitwiseDifference(out[k * n + i], Screw(pairs.from[i], pairs.to[i]).at(kTimes[k]));
            GYRE_CHECK(difference.isEmpty(), QStringLiteral("pair %1, t %2: %3").arg(i).arg(str(kTimes[k]), difference));
        }
}

void TestScrewBatch::midpointsMatchTheSingleScrew()
{
    QFETCH(Midpoints, midpoints);
    const Pairs pairs = mixedPairs();
    std::vector<Pose> out(pairs.from.size());
    midpoints(pairs.from, pairs.to, out);
    for (std::size_t i = 0; i < out.size(); ++i) {
        const QString difference = bitwiseDifference(out[i], Screw::midpoint(pairs.from[i], pairs.to[i]));
        GYRE_CHECK(difference.isEmpty(), QStringLiteral("pair %1: %2").arg(i).arg(difference));
    }
}

void TestScrewBatch::followsTheGeodesic()
{
    QFETCH(ScrewsAt, screws);
    QFETCH(Midpoints, midpoints);
    const Pairs pairs = mixedPairs();
    const std::size_t n = pairs.from.size();
    std::vector<Pose> out(n * kTimes.size());
    screws(pairs.from, pairs.to, kTimes, out);
    std::vector<Pose> middles(n);
    midpoints(pairs.from, pairs.to, middles);
    for (std::size_t i = 0; i < n; ++i) {
        // A half turn exactly has two geodesics, one each way round; the screw takes either.
        if (kPi - angleBetween(pairs.from[i].orientation, pairs.to[i].orientation) < 1e-12)
            continue;
        for (std::size_t k = 0; k < kTimes.size(); ++k) {
            const double error = poseMatrixDistance(out[k * n + i], geodesic(pairs.from[i], pairs.to[i], kTimes[k]));
            GYRE_CHECK(error < 1e-9, QStringLiteral("pair %1, t %2: %3 from the geodesic").arg(i).arg(str(kTimes[k]), str(error)));
        }
        const double error = poseMatrixDistance(middles[i], geodesic(pairs.from[i], pairs.to[i], 0.5));
        GYRE_CHECK(error < 1e-9, QStringLiteral("pair %1: midpoint %2 from the geodesic").arg(i).arg(str(error)));
    }
}

void TestScrewBatch::everyLength()
{
    QFETCH(ScrewsAt, screws);
    QFETCH(Midpoints, midpoints);
    Random random(2112);
    // Past two blocks of the widest lanes (32 pairs with AVX2 or AVX-512, 16 with SSE2), so that full
    // blocks, each written in place, and partial ones, written through copies, both meet the guard.
    for (std::size_t n = 0; n <= 66; ++n) {
        Pairs pairs;
        for (std::size_t i = 0; i < n; ++i) {
            pairs.from.push_back(random.pose(5.0));
            pairs.to.push_back(random.pose(5.0));
        }
        // Guards past the end of each output: the batch writes no pose beyond its span.
        const Pose guard{Eigen::Quaterniond(0.5, 0.5, 0.5, 0.5), Eigen::Vector3d(7.0, 8.0, 9.0)};
        std::vector<Pose> out(2 * n + 1, guard);
        screws(pairs.from, pairs.to, std::span(kTimes).first(2), std::span(out).first(2 * n));
        std::vector<Pose> middles(n + 1, guard);
        midpoints(pairs.from, pairs.to, std::span(middles).first(n));
        GYRE_CHECK(bitwiseDifference(out.back(), guard).isEmpty() && bitwiseDifference(middles.back(), guard).isEmpty(),
                   QStringLiteral("%1 pairs: a pose written past the end").arg(n));
        for (std::size_t i = 0; i < n; ++i) {
            const Screw screw(pairs.from[i], pairs.to[i]);
            for (std::size_t k = 0; k < 2; ++k) {
                const QString difference = bitwiseDifference(out[k * n + i], screw.at(kTimes[k]));
                GYRE_CHECK(difference.isEmpty(), QStringLiteral("%1 pairs: pair %2 at t %3: %4").arg(n).arg(i).arg(str(kTimes[k]), difference));
            }
            const QString difference = bitwiseDifference(middles[i], Screw::midpoint(pairs.from[i], pairs.to[i]));
            GYRE_CHECK(difference.isEmpty(), QStringLiteral("%1 pairs: midpoint %2: %3").arg(n).arg(i).arg(difference));
        }
    }
}

void TestScrewBatch::beyondTheFastSineRange()
{
    QFETCH(ScrewsAt, screws);
    // Half-angles near π/2 at t = 2000 put t·a past 1024 in most lanes, but not in the slow ones.
    const Pairs pairs = mixedPairs();
    const std::size_t n = pairs.from.size();
    const std::vector<double> times = {2000.0, -3000.0};
    std::vector<Pose> out(n * times.size());
    screws(pairs.from, pairs.to, times, out);
    for (std::size_t k = 0; k < times.size(); ++k)
        for (std::size_t i = 0; i < n; ++i) {
            const QString difference = bitwiseDifference(out[k * n + i], Screw(pairs.from[i], pairs.to[i]).at(times[k]));
            GYRE_CHECK(difference.isEmpty(), QStringLiteral("pair %1, t %2: %3").arg(i).arg(str(times[k]), difference));
        }
}

void TestScrewBatch::refusesSpansOfDifferentLengths()
{
    const std::vector<Pose> three(3);
    const std::vector<Pose> two(2);
    std::vector<Pose> out(3);
    const std::vector<double> times = {0.5};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, screwsAt(three, two, times, out));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, screwsAt(three, three, times, std::span(out).first(2)));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, screwMidpoints(three, two, out));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, screwMidpoints(three, three, std::span(out).first(2)));
}

void TestScrewBatch::refusesValuesThatAreNoInstructionSet()
{
    using screw_batch_detail::InstructionSet;
    const std::vector<Pose> one(1);
    std::vector<Pose> out(1);
    const std::vector<double> times = {0.5};
    for (int value : {-1, 3}) {
        const auto set = static_cast<InstructionSet>(value);
        QVERIFY(!screw_batch_detail::processorHas(set));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, screw_batch_detail::screwsAtWith(set, one, one, times, out));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, screw_batch_detail::screwMidpointsWith(set, one, one, out));
    }
}

void TestScrewBatch::poseBuffersStartOnCacheLines()
{
    // Several buffers alive at once, of sizes whose ordinary allocations land at different offsets.
    std::vector<PoseBuffer> buffers;
    for (std::size_t n : {1, 2, 3, 5, 17, 100, 1000, 5000})
        buffers.emplace_back(n);
    for (const PoseBuffer& buffer : buffers)
        QCOMPARE(reinterpret_cast<std::uintptr_t>(buffer.data()) % 64, std::uintptr_t{0});
    PoseBuffer grown;
    for (int i = 0; i < 300; ++i) {
        grown.push_back(Pose{});
        QCOMPARE(reinterpret_cast<std::uintptr_t>(grown.data()) % 64, std::uintptr_t{0});
    }
    CacheLineAllocator<Pose> allocator;
    QVERIFY_THROWS_EXCEPTION(std::bad_array_new_length, (void)allocator.allocate(std::numeric_limits<std::size_t>::max() / 2));
}

QTEST_APPLESS_MAIN(TestScrewBatch)
#include "tst_screw_batch.moc"
