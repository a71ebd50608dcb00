// The segment a time falls in, found by segmentAt's binary search and by SegmentCursor's gallop from
// its last answer, against a linear scan written here: the last key at or before the time, clamped to
// the first and last segment.

#include "core/timed_keys.h"

#include <QTest>

#include <random>
#include <vector>

using gyre::SegmentCursor;
using gyre::segmentAt;

namespace {

struct Key {
    double time = 0.0;
};

std::size_t scannedSegment(const std::vector<Key>& keys, double time)
{
    std::size_t segment = 0;
    for (std::size_t i = 0; i + 1 < keys.size(); ++i)
        if (keys[i].time <= time)
            segment = i;
    return segment;
}

} // namespace

class TestTimedKeys : public QObject {
    Q_OBJECT

private slots:
    void cursorFindsTheScannedSegment();
};

void TestTimedKeys::cursorFindsTheScannedSegment()
{
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> gap(0.01, 1.0);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int backward = 0;
    int atKeys = 0;
    for (const std::size_t count : {2u, 3u, 7u, 64u, 1000u}) {
        std::vector<Key> keys{{-0.5}};
        while (keys.size() < count)
            keys.push_back({keys.back().time + gap(rng)});
        const double first = keys.front().time;
        const double last = keys.back().time;
        SegmentCursor cursor;
        double time = first - 1.0;
        for (int query = 0; query < 4000; ++query) {
            // Mostly forward by less than a segment, sometimes by many, sometimes back, sometimes onto a
            // key's own time or outside the keys.
            const double choice = unit(rng);
            if (choice < 0.6) {
                time += 0.05 * gap(rng);
            } else if (choice < 0.75) {
                time += 20.0 * gap(rng);
            } else if (choice < 0.85) {
                time -= 5.0 * gap(rng);
                ++backward;
            } else if (choice < 0.95) {
                time = keys[static_cast<std::size_t>(unit(rng) * static_cast<double>(count - 1))].time;
                ++atKeys;
            } else {
                time = first + (last - first) * (3.0 * unit(rng) - 1.0);
            }
            const std::size_t expected = scannedSegment(keys, time);
            QCOMPARE(segmentAt(keys, time), expected);
            QCOMPARE(cursor.at(keys, time), expected);
        }
    }
    QVERIFY(backward > 100);
    QVERIFY(atKeys > 100);
}

QTEST_GUILESS_MAIN(TestTimedKeys)
#include "tst_timed_keys.moc"
