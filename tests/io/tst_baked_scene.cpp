// prepareGltfTimes (io/baked_scene.h): which baked sample survives where times collide in float32,
// that every float32 time is then there exactly once, increasing, and that times start at 0 or later;
// and jointInfluences, each skin joint's positions and weights.

#include "io/baked_scene.h"

#include <QTest>

#include <cstdint>
#include <set>
#include <utility>

using namespace gyre;
using namespace gyre::io;

namespace {

// A sample whose pose says which it was: its position's x is its index in the input.
model::TimedPose sample(double time, int index)
{
    return {time, Pose{Eigen::Quaterniond::Identity(), Eigen::Vector3d(index, 0, 0)}};
}

int indexOf(const model::TimedPose& sample) { return static_cast<int>(sample.pose.position.x()); }

model::SceneObject objectWithKeys(const std::vector<double>& times)
{
    model::SceneObject object;
    std::vector<model::Keyframe> keys;
    for (const double time : times)
        keys.push_back({time, Pose{}});
    object.track.keys = std::move(keys);
    return object;
}

// The input's surviving samples, by index, after merging one object's samples against its keys.
std::vector<int> survivors(const std::vector<double>& sampleTimes, const std::vector<double>& keyTimes)
{
    BakedScene baked;
    baked.objects.resize(1);
    for (std::size_t i = 0; i < sampleTimes.size(); ++i)
        baked.objects[0].samples.push_back(sample(sampleTimes[i], static_cast<int>(i)));
    model::Scene scene;
    scene.objects.push_back(objectWithKeys(keyTimes));
    prepareGltfTimes(baked, scene);
    std::vector<int> result;
    for (const model::TimedPose& kept : baked.objects[0].samples)
        result.push_back(indexOf(kept));
    return result;
}

} // namespace

class TestBakedScene : public QObject {
    Q_OBJECT

private slots:
    void distinctTimesAreKept()
    {
        QCOMPARE(survivors({0.0, 1.0 / 24, 2.0 / 24, 0.1, 3.0 / 24}, {0.0, 0.1}), (std::vector<int>{0, 1, 2, 3, 4}));
    }

    void theLastKeyOfACollisionSurvives()
    {
        // A frame 1e-8 s before three keys 1e-9 s apart: at 0.5 s a float32 step is 6e-8 s.
        QCOMPARE(survivors({0.0, 0.5 - 1e-8, 0.5, 0.5 + 1e-9, 0.5 + 2e-9, 1.0}, {0.0, 0.5, 0.5 + 1e-9, 0.5 + 2e-9, 1.0}),
                 (std::vector<int>{0, 4, 5}));
    }

    void aKeyWinsOverALaterFrame()
    {
        QCOMPARE(survivors({0.0, 0.5, 0.5 + 1e-8, 1.0}, {0.0, 0.5, 1.0}), (std::vector<int>{0, 1, 3}));
    }

    // Near 1e6 s a float32 step is 1/16 s, so frames at 120 fps collide by twos and threes, and Assimp's
    // reader, which multiplies float32 seconds by 1000 in float32, joins some seconds one step apart:
    // the last of each run survives, and the survivors hold every time as read back once, increasing
    // as float32 seconds too.
    void framesNearAMillionSeconds()
    {
        const auto readBack = [](double time) { return static_cast<float>(static_cast<float>(time) * 1000.0f); };
        std::vector<double> times;
        for (int k = 0; k <= 240; ++k)
            times.push_back(1e6 + k / 120.0);
        const std::vector<int> kept = survivors(times, {});
        std::set<float> expected;
        for (const double time : times)
            expected.insert(readBack(time));
        QCOMPARE(kept.size(), expected.size());
        QVERIFY(kept.size() < times.size());
        auto wanted = expected.begin();
        for (std::size_t i = 0; i < kept.size(); ++i, ++wanted) {
            const auto index = static_cast<std::size_t>(kept[i]);
            QCOMPARE(readBack(times[index]), *wanted);
            QVERIFY(i == 0 || static_cast<float>(times[index]) > static_cast<float>(times[static_cast<std::size_t>(kept[i - 1])]));
            const bool lastOfItsRun = index + 1 == times.size() || readBack(times[index + 1]) != readBack(times[index]);
            QVERIFY2(lastOfItsRun, qPrintable(QString::number(index)));
        }
    }

    // Each object is merged against its own keys; an object without samples stays without.
    void eachObjectAgainstItsOwnKeys()
    {
        BakedScene baked;
        baked.objects.resize(3);
        baked.objects[0].samples = {sample(0.5, 0), sample(0.5 + 1e-8, 1)};
        baked.objects[2].samples = {sample(0.5, 0), sample(0.5 + 1e-8, 1)};
        model::Scene scene;
        scene.objects = {objectWithKeys({0.5}), objectWithKeys({0.0}), objectWithKeys({0.5 + 1e-8})};
        QCOMPARE(prepareGltfTimes(baked, scene).size(), 2); // one for each object that lost a sample
        QCOMPARE(baked.objects[0].samples.size(), std::size_t{1});
        QCOMPARE(indexOf(baked.objects[0].samples[0]), 0);
        QVERIFY(baked.objects[1].samples.empty());
        QCOMPARE(baked.objects[2].samples.size(), std::size_t{1});
        QCOMPARE(indexOf(baked.objects[2].samples[0]), 1);
    }

    // A scene from -0.25 s is written from 0 s: every time 0.25 s later, and a key still wins over a
    // frame after it within a float32 step (the step at 0.25 s is 3e-8 s).
    void negativeTimesMoveLater()
    {
        BakedScene baked;
        baked.range = {-0.25, 0.5, 4.0};
        baked.objects.resize(1);
        baked.objects[0].samples = {sample(-0.25, 0), sample(0.0, 1), sample(1e-8, 2), sample(0.25, 3), sample(0.5, 4)};
        model::Scene scene;
        scene.objects = {objectWithKeys({0.0, 0.5})};
        const QStringList warnings = prepareGltfTimes(baked, scene);
        QCOMPARE(baked.range.start, 0.0);
        QCOMPARE(baked.range.end, 0.75);
        std::vector<int> kept;
        std::vector<double> times;
        for (const model::TimedPose& s : baked.objects[0].samples) {
            kept.push_back(indexOf(s));
            times.push_back(s.time);
        }
        QCOMPARE(kept, (std::vector<int>{0, 1, 3, 4}));
        QCOMPARE(times, (std::vector<double>{0.0, 0.25, 0.5, 0.75}));
        QCOMPARE(warnings.size(), 2);
        QVERIFY2(warnings[0].contains("0.25 s later"), qPrintable(warnings[0]));
    }

    // Each joint's nonzero weights by increasing position, whichever of a position's four slots holds
    // it; a joint no position leans on has none.
    void jointInfluencesByJoint()
    {
        model::Skin skin;
        skin.joints = {1, 2, 3, 4};
        skin.vertexJoints = {{2, 0, 1, 0}, {0, 0, 0, 0}, {1, 2, 0, 0}, {3, 0, 2, 1}};
        skin.vertexWeights = {Eigen::Vector4f(0.5F, 0.25F, 0.25F, 0.0F), Eigen::Vector4f::Zero(),
                              Eigen::Vector4f(0.75F, 0.125F, 0.0F, 0.0F), Eigen::Vector4f(0.0F, 0.0F, 0.5F, 0.5F)};
        const std::vector<std::vector<JointInfluence>> influences = jointInfluences(skin);
        const auto listOf = [&influences](std::size_t joint) {
            std::vector<std::pair<std::uint32_t, float>> result;
            for (const JointInfluence& influence : influences.at(joint))
                result.emplace_back(influence.vertex, influence.weight);
            return result;
        };
        using List = std::vector<std::pair<std::uint32_t, float>>;
        QCOMPARE(influences.size(), std::size_t{4});
        QCOMPARE(listOf(0), (List{{0, 0.25F}}));
        QCOMPARE(listOf(1), (List{{0, 0.25F}, {2, 0.75F}, {3, 0.5F}}));
        QCOMPARE(listOf(2), (List{{0, 0.5F}, {2, 0.125F}, {3, 0.5F}}));
        QVERIFY(listOf(3).empty());
    }
};

QTEST_APPLESS_MAIN(TestBakedScene)
#include "tst_baked_scene.moc"
