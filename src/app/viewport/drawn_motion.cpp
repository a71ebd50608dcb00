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
                  {.finished = [this](Sampled sampled) { receiveSampled(std::move(sampled)); },
                   .failed = [this](const QString& message) {
                       dropTrail();
                       // Not asked for again until the motion, the selection or the range changes.
                       setTrajectories({});
                       trajectoriesStale_ = false;
                       emit changed();
                       emit failed(tr("The trail could not be built: %1").arg(message));
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
                receiveScrewTrails(poses);
            });
    connect(&subdivision_, &jobs::SubdivisionJob::failed, this, [this](std::uint64_t, const QString& reason) {
        dropTrail();
        emit changed();
        emit failed(tr("The trail could not be built: %1").arg(reason));
    });
    // Copies about the current frame follow it.
    connect(&document_, &model::Document::currentTimeChanged, this, [this] {
        if (trailSpacing_.everyFrames > 0)
            requestSampledTrail();
    });
    connect(&selection_, &Selection::changed, this, &DrawnMotion::onSelectionChanged);
    selectedObjects_ = selection_.objects();
    activeObject_ = selection_.object();
    motion_ = std::make_shared<model::SceneMotion>(document_.scene(), motionOf());
    snapshotOriginalMotion();
    requestTrail();
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
        trajectoriesStale_ = true;
        requestTrail();
        emit sceneReset();
        return;
    }
    // A parent's change moves its children too: the scene's motion is made anew, sharing the
    // document's motions of the tracks that did not change.
    if (changes & (model::kMotionChanges | Change::Object))
        rebuildMotionInBackground();
    // A selected screw track's keys or settings: its subdivision. Another interpolation or another budget share
    // moves a track between the subdivided and the sampled trails.
    if (selection_.isObjectSelected(object) && (changes & (Change::Keyframes | Change::TrackSettings)))
        requestScrewTrails();
    if (changes.testFlag(Change::SceneSettings)) {
        // The copies are spread over the scene's range, at its frames, and so are the paths' points.
        trajectoriesStale_ = true;
        requestSampledTrail();
    } else if (selection_.isObjectSelected(object) && changes.testFlag(Change::TrackSettings)) {
        requestSampledTrail();
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
    trajectoriesStale_ = true;
    requestTrail();
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
    trajectoriesStale_ = true;
    requestSampledTrail();
    emit changed();
}

bool DrawnMotion::isScrewBenderTrack(const model::SceneObject* object)
{
    return object != nullptr && !object->track.keys.empty() && object->track.interpolation == InterpolationMethod::Screw;
}

void DrawnMotion::setTrajectories(std::vector<std::vector<Eigen::Vector3f>> paths)
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
    requestTrail();
}

TrailPlan DrawnMotion::currentTrailPlan() const
{
    return planTrails(document_.scene(), selection_.objects(), selection_.object(), trailSpacing_);
}

void DrawnMotion::requestTrail()
{
    requestScrewTrails();
    // The others' trails, which leave the screw tracks out; newest wins, so none sampled before it became one lands.
    requestSampledTrail();
}

void DrawnMotion::requestScrewTrails()
{
    const TrailPlan plan = currentTrailPlan();
    if (plan.subdivided.empty()) {
        subdivision_.cancel();
        screwTrailObjects_.clear();
        if (!screwTrails_.empty()) {
            screwTrails_.clear();
            composeTrails();
        }
        return;
    }
    const model::Scene& scene = document_.scene();
    std::vector<jobs::SubdivisionJob::Polyscrew> polyscrews;
    screwTrailObjects_.clear();
    for (const TrailPlan::Subdivided& subdivided : plan.subdivided) {
        const model::SceneObject* object = model::findObject(scene, subdivided.object);
        jobs::SubdivisionJob::Polyscrew& polyscrew = polyscrews.emplace_back();
        polyscrew.controlPoses.reserve(object->track.keys.size());
        for (const model::Keyframe& key : object->track.keys)
            polyscrew.controlPoses.push_back(key.pose);
        polyscrew.settings = object->track.subdivision;
        polyscrew.settings.levels = subdivided.levels;
        screwTrailObjects_.push_back(subdivided.object);
    }
    sinceTrailRequest_.start();
    subdivision_.request(std::move(polyscrews));
}

void DrawnMotion::requestSampledTrail()
{
    const model::Scene& scene = document_.scene();
    std::vector<model::ObjectId> trailed = currentTrailPlan().sampled;
    std::vector<PathObject> pathed;
    if (trajectoriesStale_)
        pathed = pathObjects(scene, selection_.objects(), selection_.object());
    if (trailed.empty() && pathed.empty()) {
        sampledJob_.cancel();
        // No request in flight has paths wanted now: were they stale, there is no path to draw.
        if (trajectoriesStale_) {
            setTrajectories({});
            trajectoriesStale_ = false;
        }
        // Composed again only when some went: a screw trail alone is not uploaded anew at every drag move.
        if (!sampledTrails_.empty()) {
            sampledTrails_.clear();
            composeTrails();
        }
        return;
    }
    const bool withPaths = trajectoriesStale_;
    sampledJob_.post([motion = motion_, objects = std::move(trailed), times = trailTimes(scene, trailSpacing_),
                      pathed = std::move(pathed), pathTimes = pathTimes(scene),
                      withPaths](const jobs::JobRun<jobs::NoProgress>& run) {
        run.throwIfStopped(); // superseded before it started
        Sampled sampled{trailPoses(*motion, objects, times), std::nullopt};
        if (withPaths) {
            sampled.paths = centrePaths(*motion, pathed, pathTimes, run.stopFlag());
            run.throwIfStopped(); // superseded, the paths cut short: a newer request samples them
        }
        return sampled;
    });
}

void DrawnMotion::receiveScrewTrails(const std::vector<jobs::SubdivisionJob::SubdividedPoses>& poses)
{
    screwTrails_.clear();
    for (std::size_t i = 0; i < poses.size() && i < screwTrailObjects_.size(); ++i)
        screwTrails_.push_back({screwTrailObjects_[i], poses[i]});
    composeTrails();
    emit changed();
}

void DrawnMotion::receiveSampled(Sampled sampled)
{
    sampledTrails_ = std::move(sampled.trails);
    if (sampled.paths) {
        setTrajectories(std::move(*sampled.paths));
        trajectoriesStale_ = false;
    }
    composeTrails();
    emit changed();
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
}

} // namespace gyre::app
