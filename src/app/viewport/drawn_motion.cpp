#include "app/viewport/drawn_motion.h"

#include "app/viewport/default_shape.h"
#include "app/viewport/pose_matrix.h"
#include "app/viewport/skeleton.h"
#include "model/scene_joints.h"
#include "model/scene_queries.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace gyre::app {

namespace {

// The centre of the mesh's bounding box, in its own frame.
Eigen::Vector3d meshCentre(const model::Mesh& mesh)
{
    if (mesh.positions.empty())
        return Eigen::Vector3d::Zero();
    Eigen::Vector3f low = mesh.positions.front();
    Eigen::Vector3f high = low;
    for (const Eigen::Vector3f& position : mesh.positions) {
        low = low.cwiseMin(position);
        high = high.cwiseMax(position);
    }
    return (0.5F * (low + high)).cast<double>();
}

} // namespace

DrawnMotion::DrawnMotion(model::Document& document, Selection& selection, QObject* parent)
    : QObject(parent)
    , document_(document)
    , selection_(selection)
    , selectedTrack_(document, selection)
    , motionJob_(jobs::JobPolicy::NewestWins,
                 {.finished = [this](std::shared_ptr<const model::SceneMotion> built) { receiveMotion(std::move(built)); },
                  .failed = [this](const QString& message) {
                      emit failed(tr("The motion could not be rebuilt: %1").arg(message));
                  }})
    , sampledTrailJob_(jobs::JobPolicy::NewestWins,
                       {.finished = [this](const std::vector<ObjectTrail>& trails) { receiveSampledTrails(trails); },
                        .failed = [this](const QString& message) {
                            dropTrail();
                            emit changed();
                            emit failed(tr("The trail could not be built: %1").arg(message));
                        }})
{
    connect(&document_, &model::Document::changed, this, &DrawnMotion::onDocumentChanged);
    connect(&selectedTrack_, &SelectedTrack::changed, this, &DrawnMotion::onSelectedTrackChanged);
    connect(&document_.undoStack(), &QUndoStack::cleanChanged, this, [this](bool clean) {
        if (clean)
            snapshotOriginalMotion();
    });
    connect(&subdivision_, &jobs::SubdivisionJob::subdivided, this,
            [this](std::uint64_t, const std::vector<Pose>& poses, qint64 nanoseconds) {
                subdivisionMilliseconds_ = double(nanoseconds) / 1e6;
                subdivisionLatencyMilliseconds_ = double(sinceTrailRequest_.nsecsElapsed()) / 1e6;
                receiveScrewTrail(poses);
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

void DrawnMotion::onDocumentChanged(model::ObjectId, model::Changes changes)
{
    using model::Change;
    if (changes.testFlag(Change::Scene)) {
        // Opening a project may wait for its motion; only dragging must not. A preview was of the old scene.
        previewMotion_.reset();
        motionJob_.cancel();
        motion_ = std::make_shared<model::SceneMotion>(document_.scene(), motionOf());
        trajectoryStale_ = true;
        snapshotOriginalMotion();
        requestSampledTrail();
        emit sceneReset();
        return;
    }
    // A parent's change moves its children too: the scene's motion is made anew, sharing the
    // document's motions of the tracks that did not change.
    if (changes & (model::kMotionChanges | Change::Object))
        rebuildMotionInBackground();
    if (changes & (Change::Added | Change::Removed | Change::Object | Change::SceneSettings))
        trajectoryStale_ = true;
    // The copies are spread over the scene's range, at its frames.
    if (changes.testFlag(Change::SceneSettings))
        requestSampledTrail();
    emit changed();
}

void DrawnMotion::onSelectedTrackChanged(model::Changes changes)
{
    using model::Change;
    if (changes & (SelectedTrack::kAnotherObject | Change::Scene)) {
        // The trails in hand are of another selection, or the old scene's: show none until this one's arrive.
        dropTrail();
        trajectoryStale_ = true;
    }
    // The trail subdivides the keys with the track's settings.
    if (changes & (SelectedTrack::kAnotherObject | Change::Scene | Change::Keyframes | Change::TrackSettings))
        requestTrail();
    emit changed();
}

void DrawnMotion::onSelectionChanged()
{
    // Selecting keys changes the selection too, and asks for nothing here.
    std::vector<model::ObjectId> objects = selection_.objects();
    if (objects == selectedObjects_)
        return;
    selectedObjects_ = std::move(objects);
    trajectoryStale_ = true;
    requestSampledTrail();
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
    // A parent's change moves the selected object's trajectory and trail as well as its own.
    trajectoryStale_ = true;
    requestSampledTrail();
    emit changed();
}

bool DrawnMotion::isScrewBenderTrack(const model::SceneObject* object)
{
    return object != nullptr && !object->track.keys.empty() && object->track.interpolation == InterpolationMethod::Screw;
}

void DrawnMotion::dropTrail()
{
    screwTrail_.clear();
    sampledTrails_.clear();
    composeTrails();
}

void DrawnMotion::setTrailSpacing(const TrailSpacing& spacing)
{
    trailSpacing_ = spacing.clamped();
    requestSampledTrail();
}

void DrawnMotion::requestTrail()
{
    const model::SceneObject* object = selection_.selectedObject();
    if (isScrewBenderTrack(object)) {
        std::vector<Pose> controlPoses;
        controlPoses.reserve(object->track.keys.size());
        for (const model::Keyframe& key : object->track.keys)
            controlPoses.push_back(key.pose);
        screwTrailObject_ = object->id;
        sinceTrailRequest_.start();
        subdivision_.request(std::move(controlPoses), object->track.subdivision);
    } else {
        subdivision_.cancel();
        screwTrailObject_ = model::kNoObject;
        screwTrail_.clear();
    }
    // The others' trails, which leave the screw track out; newest wins, so none sampled before it became one lands.
    requestSampledTrail();
}

void DrawnMotion::requestSampledTrail()
{
    const model::Scene& scene = document_.scene();
    // Every selected object's but the screw track's, which is ScrewBender's subdivision (requestTrail).
    std::vector<model::ObjectId> trailed =
        sampledTrailObjects(scene, selection_.objects(), selection_.object(), screwTrailObject_, trailSpacing_);
    if (trailed.empty()) {
        sampledTrailJob_.cancel();
        // Composed again only when some went: a screw trail alone is not uploaded anew at every drag move.
        if (!sampledTrails_.empty()) {
            sampledTrails_.clear();
            composeTrails();
        }
        return;
    }
    sampledTrailJob_.post([motion = motion_, objects = std::move(trailed), times = trailTimes(scene, trailSpacing_)](
                              const jobs::JobRun<jobs::NoProgress>& run) {
        run.throwIfStopped(); // superseded before it started
        return trailPoses(*motion, objects, times);
    });
}

void DrawnMotion::receiveScrewTrail(const std::vector<Pose>& poses)
{
    screwTrail_ = poses;
    composeTrails();
    emit changed();
}

void DrawnMotion::receiveSampledTrails(const std::vector<ObjectTrail>& trails)
{
    sampledTrails_ = trails;
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
    if (screwTrailObject_ != model::kNoObject && !screwTrail_.empty())
        append(screwTrailObject_, screwTrail_, true);
    for (const ObjectTrail& trail : sampledTrails_)
        if (!trail.poses.empty())
            append(trail.object, trail.poses, false);
    trailChanged_ = true;
}

const std::vector<std::vector<Eigen::Vector3f>>& DrawnMotion::trajectories()
{
    if (trajectoryStale_)
        rebuildTrajectories();
    return trajectories_;
}

void DrawnMotion::rebuildTrajectories()
{
    trajectories_.clear();
    trajectoryStale_ = false;
    const model::Scene& scene = document_.scene();
    if (!(scene.endTime > scene.startTime))
        return;
    std::vector<model::ObjectId> objects = selection_.objects();
    // The active object's first, so that the budget never leaves it out.
    std::stable_partition(objects.begin(), objects.end(), [this](model::ObjectId id) { return id == selection_.object(); });
    objects.resize(std::min(objects.size(), kMaxTrajectoryObjects));
    const std::vector<bool> joints = model::findJoints(scene);
    // One sample per frame of the scene, fewer for very long scenes and for many objects.
    const double frames = std::ceil((scene.endTime - scene.startTime) * scene.fps);
    const double perPath = std::min<double>(kMaxTrajectorySamples,
                                            kMaxTrajectoryPoints / static_cast<double>(std::max<std::size_t>(objects.size(), 1)));
    const int samples = static_cast<int>(std::clamp(frames, 1.0, std::floor(perPath))) + 1;
    for (const model::ObjectId id : objects) {
        const model::SceneObject* object = model::findObject(scene, id);
        if (object == nullptr)
            continue;
        // A joint's path is its origin's, where its bones meet.
        const bool joint = joints[static_cast<std::size_t>(object - scene.objects.data())];
        const Eigen::Vector3d centre = joint ? Eigen::Vector3d::Zero() : meshCentre(displayMesh(*object));
        std::vector<Eigen::Vector3f>& path = trajectories_.emplace_back();
        for (int i = 0; i < samples; ++i) {
            const double time = scene.startTime + (scene.endTime - scene.startTime) * i / (samples - 1);
            path.push_back(motion_->worldPose(id, time).apply(centre).cast<float>());
        }
    }
}

} // namespace gyre::app
