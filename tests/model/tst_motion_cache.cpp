// The document's one motion per track (motion_cache.h): built once per change of its track, shared by
// every caller until then, rebuilt after an undo, and safe to build from several threads at once. The scene's
// motion finds several objects' world poses together as it finds each one's.

#include "model/commands/import_objects_command.h"
#include "model/commands/rename_object_command.h"
#include "model/commands/set_keyframe_orientation_command.h"
#include "model/commands/set_time_range_command.h"
#include "model/scene_motion.h"
#include "model/track_evaluation.h"

#include <QTest>

#include <Eigen/Geometry>

#include <memory>
#include <thread>
#include <vector>

using namespace gyre;
using namespace gyre::model;

namespace {

Eigen::Quaterniond aboutZ(double angle) { return Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ())); }

SceneObject objectTurning(ObjectId id, double turn, ObjectId parent = kNoObject)
{
    SceneObject object;
    object.id = id;
    object.parent = parent;
    for (double time : {0.0, 1.0, 2.0})
        object.track.keys.push_back({time, {aboutZ(turn * time), {time, 0, 0}}, true});
    return object;
}

// A document holding two objects, the second a child of the first.
struct Fixture {
    Fixture()
    {
        auto* command = new ImportObjectsCommand(document, {objectTurning(1, 0.5), objectTurning(2, 0.25, 1)});
        ids = command->ids();
        document.push(command);
    }

    double angleAt(ObjectId id, double time) const
    {
        return Eigen::AngleAxisd(document.motion(id)->motion().at(time).orientation).angle();
    }

    Document document;
    std::vector<ObjectId> ids;
};

} // namespace

class TstMotionCache : public QObject {
    Q_OBJECT

private slots:
    void builtOnceAndShared()
    {
        Fixture f;
        QCOMPARE(f.document.motionBuilds(), std::size_t(0)); // nothing asked for yet
        const auto first = f.document.motion(f.ids[0]);
        const auto second = f.document.motion(f.ids[0]);
        QCOMPARE(first.get(), second.get());
        QCOMPARE(f.document.motionBuilds(), std::size_t(0)); // handed out, built on first use
        QCOMPARE(Eigen::AngleAxisd(first->motion().at(2.0).orientation).angle(), 1.0);
        second->motion().at(1.0);
        QCOMPARE(f.document.motionBuilds(), std::size_t(1));
        QVERIFY(f.document.motion(kNoObject + 99) == nullptr);
    }

    void rebuiltOnlyForTheTrackThatChanged()
    {
        Fixture f;
        const auto parent = f.document.motion(f.ids[0]);
        const auto child = f.document.motion(f.ids[1]);
        parent->motion();
        child->motion();
        QCOMPARE(f.document.motionBuilds(), std::size_t(2));

        f.document.push(new SetKeyframeOrientationCommand(f.document, f.ids[1], 2, aboutZ(1.5)));
        QCOMPARE(f.document.motion(f.ids[0]).get(), parent.get());
        QVERIFY(f.document.motion(f.ids[1]).get() != child.get());
        QCOMPARE(f.angleAt(f.ids[1], 2.0), 1.5);
        QCOMPARE(f.document.motionBuilds(), std::size_t(3));
        // What was handed out before the change stays as it was: a worker may still be reading it.
        QCOMPARE(Eigen::AngleAxisd(child->motion().at(2.0).orientation).angle(), 0.5);

        // Neither a name nor the time range moves a track.
        f.document.push(new RenameObjectCommand(f.document, f.ids[1], QStringLiteral("renamed")));
        f.document.push(new SetTimeRangeCommand(f.document, {24, 0, 4}));
        f.angleAt(f.ids[1], 2.0);
        QCOMPARE(f.document.motionBuilds(), std::size_t(3));
    }

    void rebuiltAfterUndoAndRedo()
    {
        Fixture f;
        f.document.push(new SetKeyframeOrientationCommand(f.document, f.ids[0], 2, aboutZ(1.5)));
        QCOMPARE(f.angleAt(f.ids[0], 2.0), 1.5);
        f.document.undoStack().undo();
        QCOMPARE(f.angleAt(f.ids[0], 2.0), 1.0);
        f.document.undoStack().redo();
        QCOMPARE(f.angleAt(f.ids[0], 2.0), 1.5);
        QCOMPARE(f.document.motionBuilds(), std::size_t(3));

        // Undoing the import removes both objects; redoing brings motions that are built anew.
        f.document.undoStack().undo();
        f.document.undoStack().undo();
        QVERIFY(f.document.motion(f.ids[0]) == nullptr);
        f.document.undoStack().redo();
        QCOMPARE(f.angleAt(f.ids[0], 2.0), 1.0);
        QCOMPARE(f.document.motionBuilds(), std::size_t(4));
    }

    void aNewSceneForgetsEveryMotion()
    {
        Fixture f;
        const auto before = f.document.motion(f.ids[0]);
        f.document.startNewProject();
        QCOMPARE(f.document.motionBuilds(), std::size_t(0));
        // The new project's block may reuse an id; its motion is its own.
        for (const SceneObject& object : f.document.scene().objects)
            QVERIFY(f.document.motion(object.id) != before);
    }

    void theSceneMotionSharesTheDocumentsMotions()
    {
        Fixture f;
        const auto fromDocument = [&f](const SceneObject& object) { return f.document.motion(object.id); };
        const SceneMotion motion(f.document.scene(), fromDocument);
        motion.build();
        QCOMPARE(f.document.motionBuilds(), std::size_t(2));
        const SceneMotion again(f.document.scene(), fromDocument);
        again.build();
        QCOMPARE(f.document.motionBuilds(), std::size_t(2));
        // The child turns 0.25 rad/s on a parent turning 0.5 rad/s about the same axis.
        QCOMPARE(Eigen::AngleAxisd(again.worldPose(f.ids[1], 2.0).orientation).angle(), 1.5);
    }

    // Only the values: that worldPoses evaluates each shared ancestor's track once per time is not observable
    // here, since MotionOf hands SceneMotion the concrete SharedTrackMotion and TrackMotion::at is not virtual,
    // so a test cannot slip in a track motion that counts its evaluations.
    void worldPosesAreEachObjectsWorldPose()
    {
        // A chain 1 ← 2 ← 3 and 4 beside 2, asked for out of order, one twice, with an object the scene lacks.
        Scene scene;
        scene.objects = {objectTurning(1, 0.5), objectTurning(2, 0.25, 1), objectTurning(3, -0.75, 2),
                         objectTurning(4, 1.5, 1)};
        scene.objects[2].track.keys[1].pose.position = {0.0, 2.0, -1.0};
        const SceneMotion motion(scene, [](const SceneObject& object) {
            return std::make_shared<const SharedTrackMotion>(object.track);
        });
        const std::vector<ObjectId> ids{3, 1, 4, 2, 3, 99};
        for (const double time : {0.0, 0.4, 1.3, 2.0}) {
            const std::vector<Pose> poses = motion.worldPoses(ids, time);
            QCOMPARE(poses.size(), ids.size());
            for (std::size_t i = 0; i < ids.size(); ++i) {
                const Pose one = motion.worldPose(ids[i], time);
                QVERIFY(poses[i].orientation.angularDistance(one.orientation) < 1e-12);
                QVERIFY((poses[i].position - one.position).norm() < 1e-12);
            }
        }
        // The grandchild's turns add up about z: 0.5 + 0.25 − 0.75 rad/s.
        QVERIFY(std::abs(Eigen::AngleAxisd(motion.worldPoses({3}, 2.0).front().orientation).angle()) < 1e-12);
        QVERIFY((motion.worldPoses({99}, 1.0).front().position).norm() == 0.0);
    }

    // Threads asking together wait for one build and share it.
    void threadsShareOneBuild()
    {
        Fixture f;
        const auto motion = f.document.motion(f.ids[0]);
        std::vector<const TrackMotion*> seen(4);
        std::vector<std::thread> threads;
        for (std::size_t i = 0; i < seen.size(); ++i)
            threads.emplace_back([&seen, &motion, i] { seen[i] = &motion->motion(); });
        for (std::thread& thread : threads)
            thread.join();
        QCOMPARE(f.document.motionBuilds(), std::size_t(1));
        for (const TrackMotion* each : seen)
            QCOMPARE(each, seen.front());
    }

    // A track TrackMotion refuses throws at every use, and is built only once.
    void aRefusedTrackThrowsEveryTime()
    {
        MotionTrack track;
        track.keys.push_back({1.0, {}, true});
        track.keys.push_back({0.0, {}, true}); // times must increase
        auto builds = std::make_shared<std::atomic<std::size_t>>(0);
        const SharedTrackMotion motion(track, builds);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, motion.motion());
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, motion.motion());
        QCOMPARE(builds->load(), std::size_t(1));
    }

    // The motion before the fit is the track without its fit: no fitted curve, and the key the fit
    // turned as it was before (sketch.keysBeforeFit); built once, as the motion is.
    void theMotionWithoutFitPutsTheMovedKeysBack()
    {
        MotionTrack track = objectTurning(1, 0.5).track;
        const Keyframe before = track.keys[1];
        track.keys[1].pose.orientation = aboutZ(1.5);
        track.sketch.keysBeforeFit = {before};
        // A fit over [1.5, 2] s: at 1 s both motions play the keys.
        track.sketch.fittedCurve = {{1.5, aboutZ(1.2), Eigen::Quaterniond(0, 0, 0, 0.25)},
                                    {2.0, aboutZ(1.0), Eigen::Quaterniond(0, 0, 0, 0.25)}};
        auto builds = std::make_shared<std::atomic<std::size_t>>(0);
        const SharedTrackMotion motion(track, builds);
        const TrackMotion& withoutFit = motion.motionWithoutFit();
        QVERIFY(withoutFit.at(1.0).orientation.isApprox(before.pose.orientation, 1e-12));
        QVERIFY(motion.motion().at(1.0).orientation.isApprox(aboutZ(1.5), 1e-12));
        QCOMPARE(&motion.motionWithoutFit(), &withoutFit);
        QCOMPARE(builds->load(), std::size_t(2));
    }

    // A ballistic track's motion before its fit falls under the scene's gravity, as its motion does: the views
    // draw the centre's path of both.
    void theMotionWithoutFitFallsUnderTheScenesGravity()
    {
        MotionTrack track;
        track.interpolation = InterpolationMethod::Ballistic;
        track.keys.push_back({0.0, {Eigen::Quaterniond::Identity(), {0, 0, 0}}, true});
        track.keys.push_back({1.0, {aboutZ(0.5), {2, 0, 0}}, true});
        track.sketch.fittedCurve = {{0.25, aboutZ(0.1), Eigen::Quaterniond(0, 0, 0, 0.25)},
                                    {0.75, aboutZ(0.4), Eigen::Quaterniond(0, 0, 0, 0.25)}};
        const Gravity gravity{3.7, UpDirection::PlusY};
        const SharedTrackMotion motion(track, nullptr, MassProperties{}, gravity);
        // x(t) = x0 + v0·t − ½·g·up·t² through both keys: v0 = (x1 − x0)/T + ½·g·T·up; at t = ½ the centre is
        // ½·g·t·(T − t) = 3.7/8 above the chord's middle (1, 0, 0). The default body's centre is its origin.
        const Eigen::Vector3d expected(1.0, 3.7 / 8.0, 0.0);
        QVERIFY((motion.motion().at(0.5).position - expected).norm() < 1e-12);
        QVERIFY((motion.motionWithoutFit().at(0.5).position - expected).norm() < 1e-12);
    }
};

QTEST_GUILESS_MAIN(TstMotionCache)
#include "tst_motion_cache.moc"
