// The viewport's drawn motion (drawn_motion.h) without OpenGL: every selected screw track's trail is its own
// polyscrew subdivided, as core's subdivision makes it, within the trails' budget, and follows its keys; the
// selected objects' centre paths are sampled off the UI thread, arrive, and follow an edit. One test prints what
// the paths' whole budget costs the worker (tests never assert on time).

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

        // Key 1 (1 s, the path's point 24) moved: the path follows once sampled anew, a moment behind.
        const Eigen::Vector3d moved(-4.0, 7.0, 2.5);
        document.push(new model::SetKeyframePositionCommand(document, ids[0], 1, moved));
        const Eigen::Vector3f expected =
            (moved + document.object(ids[0])->track.keys[1].pose.orientation * Eigen::Vector3d(2, 2, 2)).cast<float>();
        QTRY_VERIFY(drawn.trajectories().size() == 2 && (drawn.trajectories()[1][24] - expected).norm() < 1e-5F);
        QVERIFY(!drawn.trajectoriesPending());

        // Nothing selected: no path.
        selection.clear();
        QVERIFY(drawn.trajectories().empty());
        QVERIFY(!drawn.trajectoriesPending());
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
        std::vector<model::SceneObject> objects;
        for (model::ObjectId id = 1; id <= kObjects; ++id) {
            model::SceneObject object = keyed(id, InterpolationMethod::Hermite, 4, 0.0);
            object.parent = id % kChain == 1 ? model::kNoObject : id - 1;
            for (model::Keyframe& key : object.track.keys)
                key.time *= 40.0;
            objects.push_back(object);
        }
        auto* import = new model::ImportObjectsCommand(document, objects);
        document.push(import);
        document.push(new model::SetTimeRangeCommand(document, {24, 0, 5000.0 / 24.0}));
        app::Selection selection(document);
        app::DrawnMotion drawn(document, selection);
        QTRY_VERIFY(drawn.motion().contains(import->ids().back()));
        QElapsedTimer clock;
        clock.start();
        selection.selectObjects(import->ids(), import->ids().front());
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
};

QTEST_GUILESS_MAIN(TestDrawnMotion)
#include "tst_drawn_motion.moc"
