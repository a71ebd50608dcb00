// The viewport's drawn motion (drawn_motion.h) without OpenGL: every selected screw track's trail is its own
// polyscrew subdivided, as core's subdivision makes it, within the trails' budget, and follows its keys; the
// selected objects' centre paths are sampled off the UI thread, arrive, and follow an edit, while the trails about
// the current time follow it without waiting for them; the trails are composed only when one changed. Tests print
// what the paths' whole budget costs the worker, and what a drag and playback cost in composes and answers
// (tests never assert on time).

#include "app/playback.h"
#include "app/selection.h"
#include "app/viewport/centre_path.h"
#include "app/viewport/drawn_motion.h"
#include "app/viewport/pose_matrix.h"
#include "core/subdivision.h"
#include "model/commands/import_objects_command.h"
#include "model/commands/set_keyframe_position_command.h"
#include "model/commands/set_subdivision_command.h"
#include "model/commands/set_time_range_command.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

using namespace gyre;

namespace {

// Six keys a second apart, each turned and moved its own way, `shift` along x.
model::SceneObject keyed(model::ObjectId id, InterpolationMethod interpolation, int levels, double shift)
{
    model::SceneObject object;
    object.id = id;
    object.name = QStringLiteral("object %1").arg(id);
    object.track.interpolation = interpolation;
    object.track.subdivision.levels = levels;
    for (int key = 0; key < 6; ++key) {
        const Eigen::Quaterniond turn(Eigen::AngleAxisd(0.4 * key, Eigen::Vector3d(1.0, 0.5 * key, double(id)).normalized()));
        object.track.keys.push_back({double(key), Pose{turn, Eigen::Vector3d(shift + key % 3, 0.5 * key, 0.2 * key * key)}, true});
    }
    return object;
}

std::vector<Pose> controlPoses(const model::SceneObject& object)
{
    std::vector<Pose> poses;
    for (const model::Keyframe& key : object.track.keys)
        poses.push_back(key.pose);
    return poses;
}

// Whether the drawn trail of `object` is its polyscrew subdivided at `levels`, as core makes it.
bool drawsSubdivision(const app::DrawnMotion& drawn, const model::SceneObject& object, int levels)
{
    const auto trail = std::find_if(drawn.trails().begin(), drawn.trails().end(),
                                    [&](const app::DrawnMotion::DrawnTrail& each) { return each.object == object.id; });
    if (trail == drawn.trails().end() || !trail->inParentFrame)
        return false;
    SubdivisionSettings settings = object.track.subdivision;
    settings.levels = levels;
    const std::vector<Pose> poses = subdividePolyscrew(controlPoses(object), settings);
    if (trail->count != poses.size())
        return false;
    std::vector<float> expected;
    for (const Pose& pose : poses)
        app::appendPoseMatrix(expected, pose);
    const auto first = drawn.trailMatrices().begin() + std::ptrdiff_t(trail->first * app::kFloatsPerMatrix);
    return std::equal(expected.begin(), expected.end(), first, [](float a, float b) { return std::abs(a - b) < 1e-6F; });
}

// A box from (1, 1, 1) to (3, 3, 3): its centre is (2, 2, 2).
std::shared_ptr<const model::Mesh> offsetBox()
{
    auto mesh = std::make_shared<model::Mesh>();
    for (int corner = 0; corner < 8; ++corner)
        mesh->positions.emplace_back(corner & 1 ? 3.0F : 1.0F, corner & 2 ? 3.0F : 1.0F, corner & 4 ? 3.0F : 1.0F);
    mesh->indices = {0, 1, 2, 1, 3, 2};
    return mesh;
}

// `count` objects keyed 40 s apart over a scene of 5000 frames at 24 fps, in chains of `chain` (each the child of
// the one before; 1: none): their paths take the worker a while. Without a mesh they are joints, which have no trail.
// Returns their ids.
std::vector<model::ObjectId> importChains(model::Document& document, model::ObjectId count, model::ObjectId chain,
                                          const std::shared_ptr<const model::Mesh>& mesh = nullptr)
{
    std::vector<model::SceneObject> objects;
    for (model::ObjectId id = 1; id <= count; ++id) {
        model::SceneObject object = keyed(id, InterpolationMethod::Hermite, 4, 0.0);
        object.parent = (id - 1) % chain == 0 ? model::kNoObject : id - 1;
        object.mesh = mesh;
        for (model::Keyframe& key : object.track.keys)
            key.time *= 40.0;
        objects.push_back(object);
    }
    auto* import = new model::ImportObjectsCommand(document, objects);
    document.push(import);
    document.push(new model::SetTimeRangeCommand(document, {24, 0, 5000.0 / 24.0}));
    return import->ids();
}

// Whether the drawn trail of each of `objects` is its world poses, in the motion drawn, at the trail's times now.
bool drawsSampledTrails(const app::DrawnMotion& drawn, const model::Document& document,
                        const std::vector<model::ObjectId>& objects)
{
    const std::vector<double> times = app::trailTimes(document.scene(), drawn.trailSpacing());
    for (const model::ObjectId id : objects) {
        const auto trail = std::find_if(drawn.trails().begin(), drawn.trails().end(),
                                        [&](const app::DrawnMotion::DrawnTrail& each) { return each.object == id; });
        if (trail == drawn.trails().end() || trail->inParentFrame || trail->count != times.size())
            return false;
        std::vector<float> expected;
        for (const double time : times)
            app::appendPoseMatrix(expected, drawn.motion().worldPose(id, time));
        const auto first = drawn.trailMatrices().begin() + std::ptrdiff_t(trail->first * app::kFloatsPerMatrix);
        const auto near = [](float a, float b) { return std::abs(a - b) < 1e-5F; };
        if (!std::equal(expected.begin(), expected.end(), first, near))
            return false;
    }
    return true;
}

} // namespace

class TestDrawnMotion : public QObject {
    Q_OBJECT

private slots:
    void everySelectedScrewTrackDrawsItsSubdivision()
    {
        model::Document document;
        auto* import = new model::ImportObjectsCommand(
            document, {keyed(1, InterpolationMethod::Screw, 3, 0.0), keyed(2, InterpolationMethod::Screw, 2, 10.0),
                       keyed(3, InterpolationMethod::Hermite, 4, 20.0)});
        document.push(import);
        const std::vector<model::ObjectId> ids = import->ids();
        app::Selection selection(document);
        app::DrawnMotion drawn(document, selection);
        drawn.setTrailSpacing({16, 0});
        selection.selectObjects(ids, ids[0]);
        const auto object = [&](std::size_t i) { return *document.object(ids[i]); };
        // Each screw track's own subdivision (6 keys, a cycle: 6·2^L poses), the hermite track's 16 sampled copies.
        QTRY_COMPARE(drawn.trailPoseCount(), std::size_t{48 + 24 + 16});
        QCOMPARE(drawn.trails().size(), std::size_t{3});
        QVERIFY(drawsSubdivision(drawn, object(0), 3));
        QVERIFY(drawsSubdivision(drawn, object(1), 2));
        QCOMPARE(drawn.trails().back().object, ids[2]);
        QVERIFY(!drawn.trails().back().inParentFrame);

        // A key of the other screw track moved: its trail follows, the active one's stays.
        document.push(new model::SetKeyframePositionCommand(document, ids[1], 2, Eigen::Vector3d(12.0, 4.0, -3.0)));
        QTRY_VERIFY(drawsSubdivision(drawn, object(1), 2));
        QVERIFY(drawsSubdivision(drawn, object(0), 3));

        // At 8 levels it would be 1536 poses, past the budget the others share: it is drawn at 7 (768), and the
        // hermite track's copies still fit what is left.
        SubdivisionSettings finer = object(1).track.subdivision;
        finer.levels = 8;
        document.push(new model::SetSubdivisionCommand(document, ids[1], finer));
        QTRY_COMPARE(drawn.trailPoseCount(), std::size_t{48 + 768 + 16});
        QVERIFY(drawsSubdivision(drawn, object(1), 7));
        QVERIFY(drawsSubdivision(drawn, object(0), 3));

        // Made active, it is the one ScrewBender edits: its whole subdivision, outside the budget.
        selection.selectObjects(ids, ids[1]);
        QTRY_COMPARE(drawn.trailPoseCount(), std::size_t{48 + 1536 + 16});
        QVERIFY(drawsSubdivision(drawn, object(1), 8));
    }

    void theCentrePathsArriveAndFollowAnEdit()
    {
        model::Document document;
        model::SceneObject boxed = keyed(1, InterpolationMethod::Hermite, 4, 0.0);
        boxed.mesh = offsetBox();
        auto* import = new model::ImportObjectsCommand(document, {boxed, keyed(2, InterpolationMethod::Screw, 2, 5.0)});
        document.push(import);
        const std::vector<model::ObjectId> ids = import->ids();
        app::Selection selection(document);
        app::DrawnMotion drawn(document, selection);
        QSignalSpy changed(&drawn, &app::DrawnMotion::changed);
        selection.selectObjects(ids, ids[1]);
        QVERIFY(drawn.trajectoriesPending());
        QTRY_VERIFY(!drawn.trajectoriesPending());
        QVERIFY(changed.count() > 0);
        // The active object's first; one point a frame over the 10 s range at 24 fps.
        const std::vector<std::vector<Eigen::Vector3f>>& paths = drawn.trajectories();
        QCOMPARE(paths.size(), std::size_t{2});
        const std::vector<double> times = app::pathTimes(document.scene());
        QCOMPARE(times.size(), std::size_t{241});
        const auto centreAt = [&](model::ObjectId id, const Eigen::Vector3d& centre, double time) {
            return document.motion(id)->motion().at(time).apply(centre).cast<float>().eval();
        };
        for (std::size_t i = 0; i < times.size(); ++i) {
            QVERIFY((paths[1][i] - centreAt(ids[0], Eigen::Vector3d(2, 2, 2), times[i])).norm() < 1e-5F);
            QVERIFY(paths[0][i].allFinite());
        }
        // The viewport uploads paths when they change, and only then.
        QVERIFY(drawn.takeTrajectoriesChange());
        QVERIFY(!drawn.takeTrajectoriesChange());

        // Key 1 (1 s, the path's point 24) moved: the path follows once sampled anew, a moment behind.
        const Eigen::Vector3d moved(-4.0, 7.0, 2.5);
        document.push(new model::SetKeyframePositionCommand(document, ids[0], 1, moved));
        const Eigen::Vector3f expected =
            (moved + document.object(ids[0])->track.keys[1].pose.orientation * Eigen::Vector3d(2, 2, 2)).cast<float>();
        QTRY_VERIFY(drawn.trajectories().size() == 2 && (drawn.trajectories()[1][24] - expected).norm() < 1e-5F);
        QVERIFY(!drawn.trajectoriesPending());
        QVERIFY(drawn.takeTrajectoriesChange());

        // Nothing selected: no path.
        selection.clear();
        QVERIFY(drawn.trajectories().empty());
        QVERIFY(!drawn.trajectoriesPending());
        QVERIFY(drawn.takeTrajectoriesChange());
    }

    // The paths' budget in full: 64 selected objects, two chains of 32 (a motion capture's depth), 4097 points
    // each over a scene of 5000 frames. Prints the time from the selection to the paths' arrival. Under the
    // sanitizers, two hundred times slower, one chain of 16 (a quarter of the budget, at half the depth), so that
    // the function stays well under its minute.
    void measuresThePathsWholeBudget()
    {
        model::Document document;
#if defined(__SANITIZE_ADDRESS__)
        constexpr model::ObjectId kObjects = 16;
        constexpr model::ObjectId kChain = 16;
#else
        constexpr model::ObjectId kObjects = app::kMaxPathObjects;
        constexpr model::ObjectId kChain = 32;
#endif
        const std::vector<model::ObjectId> ids = importChains(document, kObjects, kChain);
        app::Selection selection(document);
        app::DrawnMotion drawn(document, selection);
        QTRY_VERIFY(drawn.motion().contains(ids.back()));
        QElapsedTimer clock;
        clock.start();
        selection.selectObjects(ids, ids.front());
        QTRY_VERIFY_WITH_TIMEOUT(!drawn.trajectoriesPending(), 50000);
        const double milliseconds = double(clock.nsecsElapsed()) / 1e6;
        QCOMPARE(drawn.trajectories().size(), std::size_t(kObjects));
        std::size_t points = 0;
        for (const std::vector<Eigen::Vector3f>& path : drawn.trajectories()) {
            QCOMPARE(path.size(), std::size_t(app::kMaxPathSamples + 1));
            points += path.size();
        }
        qInfo("%zu paths of %d points (%zu points), chains of %zu: %.1f ms from the selection to their arrival",
              drawn.trajectories().size(), app::kMaxPathSamples + 1, points, std::size_t(kChain), milliseconds);
    }

    // With copies every frame about the current one, each step of the current time asks for the trails anew;
    // the paths, stale after the selection and taking far longer than a step, are not asked for again, and the
    // trails do not wait for them.
    void theTrailsFollowTheCurrentTimeWhileThePathsAreSampled()
    {
        model::Document document;
        const std::vector<model::ObjectId> ids = importChains(document, 8, 8, offsetBox());
        app::Selection selection(document);
        app::DrawnMotion drawn(document, selection);
        drawn.setTrailSpacing({4, 1});
        QTRY_VERIFY(drawn.motion().contains(ids.back()));
        selection.selectObjects(ids, ids.front());
        QVERIFY(drawn.trajectoriesPending());
        for (int step = 1; step <= 3; ++step) {
            document.setCurrentTime(10.0 + step / 24.0);
            QTRY_VERIFY(drawsSampledTrails(drawn, document, ids));
            QVERIFY(drawn.trajectoriesPending());
        }
        QTRY_VERIFY_WITH_TIMEOUT(!drawn.trajectoriesPending(), 50000);
        QCOMPARE(drawn.trajectories().size(), ids.size());
        QCOMPARE(drawn.trailWork().pathAnswers, std::uint64_t{1});
    }

    // One screw track selected alone, a key moved again and again (a drag, each move's answers awaited): the
    // trail is composed (and so uploaded) once a move, when its subdivision arrives; the paths, sampled anew
    // after each move's motion, and the empty sampled trails leave it alone. Prints the counts.
    void aDraggedScrewTrackAloneIsComposedOnceAMove()
    {
        model::Document document;
        auto* import = new model::ImportObjectsCommand(document, {keyed(1, InterpolationMethod::Screw, 6, 0.0)});
        document.push(import);
        const model::ObjectId id = import->ids().front();
        app::Selection selection(document);
        app::DrawnMotion drawn(document, selection);
        selection.selectObject(id);
        QTRY_VERIFY(drawsSubdivision(drawn, *document.object(id), 6) && !drawn.trajectoriesPending());
        const app::DrawnMotion::TrailWork before = drawn.trailWork();
        constexpr int kMoves = 10;
        for (int move = 1; move <= kMoves; ++move) {
            const Eigen::Vector3d position(0.1 * move, 2.0, -1.0);
            document.push(new model::SetKeyframePositionCommand(document, id, 2, position));
            // Key 2 stands at 2 s: the motion drawn passes through it once rebuilt.
            QTRY_VERIFY(drawsSubdivision(drawn, *document.object(id), 6) &&
                        (drawn.motion().worldPose(id, 2.0).position - position).norm() < 1e-9 &&
                        !drawn.trajectoriesPending());
        }
        const app::DrawnMotion::TrailWork& after = drawn.trailWork();
        qInfo("%d drag moves of a screw track of %zu poses, selected alone: %llu composes, %llu subdivisions, %llu "
              "sampled answers, %llu path answers",
              kMoves, drawn.trailPoseCount(), static_cast<unsigned long long>(after.composes - before.composes),
              static_cast<unsigned long long>(after.screwAnswers - before.screwAnswers),
              static_cast<unsigned long long>(after.sampledAnswers - before.sampledAnswers),
              static_cast<unsigned long long>(after.pathAnswers - before.pathAnswers));
        QCOMPARE(after.composes - before.composes, std::uint64_t{kMoves});
        QCOMPARE(after.sampledAnswers, before.sampledAnswers);
    }

    // A key of a selected object that is no screw track moved: its sampled trail follows, and the screw trail,
    // whose subdivision is the same, is not composed again for it.
    void aKeyOfAnotherTrackLeavesTheScrewTrailAlone()
    {
        model::Document document;
        auto* import = new model::ImportObjectsCommand(
            document, {keyed(1, InterpolationMethod::Screw, 5, 0.0), keyed(2, InterpolationMethod::Hermite, 4, 10.0)});
        document.push(import);
        const std::vector<model::ObjectId> ids = import->ids();
        app::Selection selection(document);
        app::DrawnMotion drawn(document, selection);
        selection.selectObjects(ids, ids[0]);
        QTRY_VERIFY(drawsSubdivision(drawn, *document.object(ids[0]), 5) &&
                    drawsSampledTrails(drawn, document, {ids[1]}) && !drawn.trajectoriesPending());
        const app::DrawnMotion::TrailWork before = drawn.trailWork();
        const Eigen::Vector3d position(14.0, -3.0, 1.0);
        document.push(new model::SetKeyframePositionCommand(document, ids[1], 3, position));
        // The subdivision is asked for again (a selected object's keys changed) and answers, every polyscrew the same.
        QTRY_VERIFY((drawn.motion().worldPose(ids[1], 3.0).position - position).norm() < 1e-9 &&
                    drawsSampledTrails(drawn, document, {ids[1]}) &&
                    drawn.trailWork().screwAnswers > before.screwAnswers);
        QVERIFY(drawsSubdivision(drawn, *document.object(ids[0]), 5));
        // The sampled trail's, once.
        QCOMPARE(drawn.trailWork().composes, before.composes + 1);
    }

    // Playback with copies every frame about the current one and stale paths (the selection's, taking longer than
    // a frame): prints how many sampled answers arrive and how many composes they cost over two seconds of
    // playback, with the paths' answers. The paths' whole budget, 64 objects in chains of 32 with 16 copies each;
    // under the sanitizers, 16 objects each on its own with 4 copies, whose trails still take less than a frame.
    void measuresTheTrailsDuringPlaybackWhileThePathsAreSampled()
    {
        model::Document document;
#if defined(__SANITIZE_ADDRESS__)
        const std::vector<model::ObjectId> ids = importChains(document, 16, 1, offsetBox());
        constexpr int kCopies = 4;
#else
        const std::vector<model::ObjectId> ids = importChains(document, app::kMaxPathObjects, 32, offsetBox());
        constexpr int kCopies = 16;
#endif
        app::Selection selection(document);
        app::DrawnMotion drawn(document, selection);
        drawn.setTrailSpacing({kCopies, 1});
        app::Playback playback(document);
        QTRY_VERIFY(drawn.motion().contains(ids.back()));
        selection.selectObjects(ids, ids.front());
        const app::DrawnMotion::TrailWork before = drawn.trailWork();
        std::uint64_t steps = 0;
        connect(&document, &model::Document::currentTimeChanged, this, [&] { ++steps; });
        playback.play();
        QTRY_VERIFY_WITH_TIMEOUT(document.scene().currentTime >= 2.0, 10000);
        playback.pause();
        const app::DrawnMotion::TrailWork during = drawn.trailWork();
        const bool pathsPending = drawn.trajectoriesPending();
        QTRY_VERIFY_WITH_TIMEOUT(!drawn.trajectoriesPending(), 50000);
        const app::TrailPlan plan = app::planTrails(document.scene(), ids, ids.front(), drawn.trailSpacing());
        QCOMPARE(plan.sampled.size(), ids.size());
        QTRY_VERIFY(drawsSampledTrails(drawn, document, plan.sampled));
        qInfo("%zu objects, %d copies every frame, 2 s of playback (%llu steps of the current time): %llu sampled "
              "answers, %llu composes, %llu path answers arrived while playing (the paths %s when it paused)",
              ids.size(), kCopies, static_cast<unsigned long long>(steps),
              static_cast<unsigned long long>(during.sampledAnswers - before.sampledAnswers),
              static_cast<unsigned long long>(during.composes - before.composes),
              static_cast<unsigned long long>(during.pathAnswers - before.pathAnswers),
              pathsPending ? "still pending" : "in hand");
    }
};

QTEST_GUILESS_MAIN(TestDrawnMotion)
#include "tst_drawn_motion.moc"
