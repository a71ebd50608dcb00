#include "app/viewport/drawn_motion.h"

#include "app/viewport/default_shape.h"
#include "app/viewport/pose_matrix.h"
#include "app/viewport/skeleton.h"
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
                       {.finished = [this](const std::vector<Pose>& poses) { receiveTrail(poses, false); },
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
                receiveTrail(poses, true);
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
    trailObject_ = selection_.object();
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
        // The trail in hand is another object's, or the old scene's: show none until this one's arrives.
        trailObject_ = selectedTrack_.object();
        trailPoseCount_ = 0;
        trajectoryStale_ = true;
    }
    // The trail subdivides the keys with the track's settings.
    if (changes & (SelectedTrack::kAnotherObject | Change::Scene | Change::Keyframes | Change::TrackSettings))
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
    trailPoseCount_ = 0;
    trailMatrices_.clear();
    trailChanged_ = true;
}

void DrawnMotion::setTrailSpacing(const TrailSpacing& spacing)
{
    trailSpacing_ = spacing.clamped();
    requestSampledTrail();
}

void DrawnMotion::requestTrail()
{
    const model::SceneObject* object = selection_.selectedObject();
    if (!isScrewBenderTrack(object)) {
        subdivision_.cancel();
        requestSampledTrail();
        return;
    }
    sampledTrailJob_.cancel();
    std::vector<Pose> controlPoses;
    controlPoses.reserve(object->track.keys.size());
    for (const model::Keyframe& key : object->track.keys)
        controlPoses.push_back(key.pose);
    sinceTrailRequest_.start();
    subdivision_.request(std::move(controlPoses), object->track.subdivision);
}

void DrawnMotion::requestSampledTrail()
{
    const model::SceneObject* object = selection_.selectedObject();
    if (isScrewBenderTrack(object))
        return; // the screw trail is ScrewBender's subdivision (requestTrail)
    const model::Scene& scene = document_.scene();
    // A joint is drawn as its bones and an empty as its axes: their paths say where they go.
    if (object == nullptr || object->empty || model::findJoints(scene)[static_cast<std::size_t>(object - scene.objects.data())]) {
        sampledTrailJob_.cancel();
        dropTrail();
        return;
    }
    sampledTrailJob_.post([motion = motion_, id = object->id, times = trailTimes(scene, trailSpacing_)](
                              const jobs::JobRun<jobs::NoProgress>& run) {
        run.throwIfStopped(); // superseded before it started
        return trailPoses(*motion, id, times);
    });
}

void DrawnMotion::receiveTrail(const std::vector<Pose>& poses, bool inParentFrame)
{
    trailMatrices_.clear();
    for (const Pose& pose : poses)
        appendPoseMatrix(trailMatrices_, pose);
    trailPoseCount_ = poses.size();
    trailInParentFrame_ = inParentFrame;
    trailChanged_ = true;
    emit changed();
}

const std::vector<Eigen::Vector3f>& DrawnMotion::trajectory()
{
    if (trajectoryStale_)
        rebuildTrajectory();
    return trajectory_;
}

void DrawnMotion::rebuildTrajectory()
{
    trajectory_.clear();
    trajectoryStale_ = false;
    const model::SceneObject* object = selection_.selectedObject();
    const model::Scene& scene = document_.scene();
    if (object == nullptr || !(scene.endTime > scene.startTime))
        return;
    // A joint's path is its origin's, where its bones meet.
    const bool joint = model::findJoints(scene)[static_cast<std::size_t>(object - scene.objects.data())];
    const Eigen::Vector3d centre = joint ? Eigen::Vector3d::Zero() : meshCentre(displayMesh(*object));
    // One sample per frame of the scene, fewer for very long scenes.
    const double frames = std::ceil((scene.endTime - scene.startTime) * scene.fps);
    const int samples = static_cast<int>(std::clamp(frames, 1.0, double(kMaxTrajectorySamples))) + 1;
    for (int i = 0; i < samples; ++i) {
        const double time = scene.startTime + (scene.endTime - scene.startTime) * i / (samples - 1);
        trajectory_.push_back(motion_->worldPose(object->id, time).apply(centre).cast<float>());
    }
}

} // namespace gyre::app
