#include "app/viewport/drawn_motion.h"

#include "model/scene_queries.h"

#include <algorithm>

namespace gyre::app {

DrawnMotion::DrawnMotion(model::Document& document, Selection& selection, QObject* parent)
    : QObject(parent)
    , document_(document)
    , selection_(selection)
    , motionJob_(jobs::JobPolicy::NewestWins,
                 {.finished = [this](std::shared_ptr<const model::SceneMotion> built) { receiveMotion(std::move(built)); },
                  .failed = [this](const QString& message) {
                      emit failed(tr("The motion could not be rebuilt: %1").arg(message));
                  }})
    , sampledJob_(jobs::JobPolicy::NewestWins,
                  {.finished = [this](std::vector<ObjectTrail> trails) {
                       ++trailWork_.sampledAnswers;
                       setSampledTrails(std::move(trails));
                       emit changed();
                   },
                   .failed = [this](const QString& message) {
                       setSampledTrails({});
                       emit changed();
                       emit failed(tr("The trail could not be built: %1").arg(message));
                   }})
    , pathJob_(jobs::JobPolicy::NewestWins,
               {.finished = [this](Paths paths) {
                    ++trailWork_.pathAnswers;
                    setTrajectories(std::move(paths));
                    trajectoriesStale_ = false;
                    emit changed();
                },
                .failed = [this](const QString& message) {
                    // Not asked for again until the motion, the selection or the range changes.
                    setTrajectories({});
                    trajectoriesStale_ = false;
                    emit changed();
                    emit failed(tr("The paths could not be sampled: %1").arg(message));
                }})
{
    connect(&document_, &model::Document::changed, this, &DrawnMotion::onDocumentChanged);
    connect(&document_.undoStack(), &QUndoStack::cleanChanged, this, [this](bool clean) {
        if (clean)
            snapshotOriginalMotion();
    });
    connect(&subdivision_, &jobs::SubdivisionJob::subdivided, this,
            [this](std::uint64_t, const std::vector<jobs::SubdivisionJob::SubdividedPoses>& poses, qint64 nanoseconds) {
                subdivisionMilliseconds_ = double(nanoseconds) / 1e6;
                subdivisionLatencyMilliseconds_ = double(sinceTrailRequest_.nsecsElapsed()) / 1e6;
                ++trailWork_.screwAnswers;
                receiveScrewTrails(poses);
            });
    connect(&subdivision_, &jobs::SubdivisionJob::failed, this, [this](std::uint64_t, const QString& reason) {
        setScrewTrails({});
        emit changed();
        emit failed(tr("The trail could not be built: %1").arg(reason));
    });
    // Copies about the current frame follow it.
    connect(&document_, &model::Document::currentTimeChanged, this, [this] {
        if (trailSpacing_.everyFrames > 0)
            requestSampledTrail(currentTrailPlan());
    });
    connect(&selection_, &Selection::changed, this, &DrawnMotion::onSelectionChanged);
    selectedObjects_ = selection_.objects();
    activeObject_ = selection_.object();
    motion_ = std::make_shared<model::SceneMotion>(document_.scene(), motionOf());
    snapshotOriginalMotion();
    const TrailPlan plan = currentTrailPlan();
    requestTrail(plan);
    requestPaths(plan);
}

std::optional<Pose> DrawnMotion::originalWorldPose(model::ObjectId id, double time) const
{
    if (model::findObject(originalScene_, id) == nullptr)
        return std::nullopt;
    return originalMotion_.worldPose(id, time);
}

void DrawnMotion::setPreviewTrack(model::ObjectId object, std::optional<model::MotionTrack> track)
{
    previewObject_ = object;
    // A ballistic track flies the object's body under the scene's gravity.
    const model::Scene& scene = document_.scene();
    const model::SceneObject* previewed = model::findObject(scene, object);
    previewMotion_ = track ? std::make_shared<const model::SharedTrackMotion>(
                                 std::move(*track), nullptr, previewed ? model::flightBodyOf(*previewed) : MassProperties{},
                                 scene.gravity)
                           : nullptr;
    rebuildMotionInBackground();
}

void DrawnMotion::onDocumentChanged(model::ObjectId object, model::Changes changes)
{
    using model::Change;
    if (changes.testFlag(Change::Scene)) {
        // Opening a project may wait for its motion; only dragging must not. A preview was of the old scene,
        // and so are the trails and paths in hand: none is shown until this scene's arrive.
        previewMotion_.reset();
        motionJob_.cancel();
        motion_ = std::make_shared<model::SceneMotion>(document_.scene(), motionOf());
        snapshotOriginalMotion();
        dropTrail();
        setTrajectories({});
        const TrailPlan plan = currentTrailPlan();
        requestTrail(plan);
        requestPaths(plan);
        emit sceneReset();
        return;
    }
    // A parent's change moves its children too: the scene's motion is made anew, sharing the
    // document's motions of the tracks that did not change.
    if (changes & (model::kMotionChanges | Change::Object))
        rebuildMotionInBackground();
    // A selected screw track's keys or settings: its subdivision. Another interpolation or another budget share
    // moves a track between the subdivided and the sampled trails.
    const bool selectedTrack =
        selection_.isObjectSelected(object) && (changes & (Change::Keyframes | Change::TrackSettings));
    const bool range = changes.testFlag(Change::SceneSettings);
    if (selectedTrack || range) {
        const TrailPlan plan = currentTrailPlan();
        if (selectedTrack)
            requestScrewTrails(plan);
        if (range) {
            // The copies are spread over the scene's range, at its frames, and so are the paths' points.
            requestSampledTrail(plan);
            requestPaths(plan);
        } else if (changes.testFlag(Change::TrackSettings)) {
            requestSampledTrail(plan);
        }
    }
    emit changed();
}

void DrawnMotion::onSelectionChanged()
{
    // Selecting keys changes the selection too, and asks for nothing here.
    std::vector<model::ObjectId> objects = selection_.objects();
    if (objects == selectedObjects_ && selection_.object() == activeObject_)
        return;
    if (selection_.object() != activeObject_) {
        // The trails and paths in hand are of another selection: show none until this one's arrive.
        dropTrail();
        setTrajectories({});
    }
    selectedObjects_ = std::move(objects);
    activeObject_ = selection_.object();
    const TrailPlan plan = currentTrailPlan();
    requestTrail(plan);
    requestPaths(plan);
    emit changed();
}

void DrawnMotion::snapshotOriginalMotion()
{
    originalScene_ = document_.scene();
    originalMotion_ = model::SceneMotion(originalScene_, [this](const model::SceneObject& object) {
        return document_.motion(object.id);
    });
}

model::SceneMotion::MotionOf DrawnMotion::motionOf() const
{
    return [this](const model::SceneObject& object) {
        return object.id == previewObject_ && previewMotion_ ? previewMotion_ : document_.motion(object.id);
    };
}

void DrawnMotion::rebuildMotionInBackground()
{
    // The whole scene each time, so that the newest request, the one that runs, has every change. Made
    // here, it costs a look-up per object; the tracks whose motion is not built yet are built there.
    auto motion = std::make_shared<const model::SceneMotion>(document_.scene(), motionOf());
    motionJob_.post([built = std::move(motion)](const jobs::JobRun<jobs::NoProgress>& run) {
        run.throwIfStopped(); // cancelled before it started
        built->build();
        return built;
    });
}

void DrawnMotion::receiveMotion(std::shared_ptr<const model::SceneMotion> built)
{
    motion_ = std::move(built);
    // A parent's change moves the selected objects' paths and trails as well as their own.
    const TrailPlan plan = currentTrailPlan();
    requestSampledTrail(plan);
    requestPaths(plan);
    emit changed();
}

void DrawnMotion::setTrajectories(Paths paths)
{
    trajectories_ = std::move(paths);
    trajectoriesChanged_ = true;
}

void DrawnMotion::dropTrail()
{
    screwTrails_.clear();
    sampledTrails_.clear();
    composeTrails();
}

void DrawnMotion::setTrailSpacing(const TrailSpacing& spacing)
{
    trailSpacing_ = spacing.clamped();
    requestTrail(currentTrailPlan());
}

TrailPlan DrawnMotion::currentTrailPlan() const
{
    return planTrails(document_.scene(), selection_.objects(), selection_.object(), trailSpacing_);
}

void DrawnMotion::requestTrail(const TrailPlan& plan)
{
    requestScrewTrails(plan);
    // The others' trails, which leave the screw tracks out; newest wins, so none sampled before it became one lands.
    requestSampledTrail(plan);
}

void DrawnMotion::requestScrewTrails(const TrailPlan& plan)
{
    screwTrailObjects_.clear();
    if (plan.subdivided.empty()) {
        subdivision_.cancel();
        setScrewTrails({});
        return;
    }
    const model::Scene& scene = document_.scene();
    std::vector<jobs::SubdivisionJob::Polyscrew> polyscrews;
    // The subdivided tracks come in the plan's objects' order: one walk finds each.
    auto next = plan.subdivided.begin();
    for (const TrailPlan::Object& each : plan.objects) {
        if (next == plan.subdivided.end())
            break;
        if (each.id != next->object)
            continue;
        const model::MotionTrack& track = scene.objects[each.index].track;
        jobs::SubdivisionJob::Polyscrew& polyscrew = polyscrews.emplace_back();
        polyscrew.controlPoses.reserve(track.keys.size());
        for (const model::Keyframe& key : track.keys)
            polyscrew.controlPoses.push_back(key.pose);
        polyscrew.settings = track.subdivision;
        polyscrew.settings.levels = next->levels;
        screwTrailObjects_.push_back(each.id);
        ++next;
    }
    sinceTrailRequest_.start();
    subdivision_.request(std::move(polyscrews));
}

void DrawnMotion::requestSampledTrail(const TrailPlan& plan)
{
    if (plan.sampled.empty()) {
        sampledJob_.cancel();
        setSampledTrails({});
        return;
    }
    sampledJob_.post([motion = motion_, objects = plan.sampled,
                      times = trailTimes(document_.scene(), trailSpacing_)](const jobs::JobRun<jobs::NoProgress>& run) {
        run.throwIfStopped(); // superseded before it started
        return trailPoses(*motion, objects, times);
    });
}

void DrawnMotion::requestPaths(const TrailPlan& plan)
{
    const model::Scene& scene = document_.scene();
    std::vector<PathObject> pathed = pathObjects(scene, plan);
    if (pathed.empty()) {
        pathJob_.cancel();
        if (!trajectories_.empty())
            setTrajectories({});
        trajectoriesStale_ = false;
        return;
    }
    trajectoriesStale_ = true;
    pathJob_.post([motion = motion_, pathed = std::move(pathed),
                   times = pathTimes(scene)](const jobs::JobRun<jobs::NoProgress>& run) {
        run.throwIfStopped(); // superseded before it started
        Paths paths = centrePaths(*motion, pathed, times, run.stopFlag());
        run.throwIfStopped(); // superseded, the paths cut short: a newer request samples them
        return paths;
    });
}

void DrawnMotion::receiveScrewTrails(const std::vector<jobs::SubdivisionJob::SubdividedPoses>& poses)
{
    std::vector<ScrewTrail> trails;
    for (std::size_t i = 0; i < poses.size() && i < screwTrailObjects_.size(); ++i)
        trails.push_back({screwTrailObjects_[i], poses[i]});
    // Every polyscrew as before (another object's keys changed) leaves nothing to draw anew.
    if (setScrewTrails(std::move(trails)))
        emit changed();
}

bool DrawnMotion::setScrewTrails(std::vector<ScrewTrail> trails)
{
    if (trails == screwTrails_)
        return false;
    screwTrails_ = std::move(trails);
    composeTrails();
    return true;
}

void DrawnMotion::setSampledTrails(std::vector<ObjectTrail> trails)
{
    const auto drawsCopies = [](const std::vector<ObjectTrail>& each) {
        return std::any_of(each.begin(), each.end(), [](const ObjectTrail& trail) { return !trail.poses.empty(); });
    };
    // A screw trail alone is not composed and uploaded anew for sampled trails that were and stay empty.
    const bool drawn = drawsCopies(sampledTrails_) || drawsCopies(trails);
    sampledTrails_ = std::move(trails);
    if (drawn)
        composeTrails();
}

void DrawnMotion::composeTrails()
{
    trailMatrices_.clear();
    trails_.clear();
    const auto append = [this](model::ObjectId object, const std::vector<Pose>& poses, bool inParentFrame) {
        trails_.push_back({object, trailMatrices_.size() / kFloatsPerMatrix, poses.size(), inParentFrame});
        for (const Pose& pose : poses)
            appendPoseMatrix(trailMatrices_, pose);
    };
    for (const ScrewTrail& trail : screwTrails_)
        if (!trail.poses->empty())
            append(trail.object, *trail.poses, true);
    for (const ObjectTrail& trail : sampledTrails_)
        if (!trail.poses.empty())
            append(trail.object, trail.poses, false);
    trailChanged_ = true;
    ++trailWork_.composes;
}

} // namespace gyre::app
