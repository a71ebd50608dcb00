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
{
    connect(&document_, &model::Document::sceneReset, this, &DrawnMotion::onSceneReset);
    connect(&document_, &model::Document::objectAdded, this, &DrawnMotion::onObjectsChanged);
    connect(&document_, &model::Document::objectRemoved, this, &DrawnMotion::onObjectsChanged);
    connect(&document_, &model::Document::objectChanged, this, &DrawnMotion::onObjectsChanged);
    connect(&document_, &model::Document::keyframesChanged, this, &DrawnMotion::onTrackChanged);
    connect(&document_, &model::Document::trackSettingsChanged, this, &DrawnMotion::onTrackChanged);
    connect(&document_, &model::Document::sketchChanged, this, &DrawnMotion::onTrackChanged);
    connect(&document_, &model::Document::sceneSettingsChanged, this, [this] {
        trajectoryStale_ = true;
        emit changed();
    });
    connect(&document_.undoStack(), &QUndoStack::cleanChanged, this, [this](bool clean) {
        if (clean)
            snapshotOriginalMotion();
    });
    connect(&selection_, &Selection::changed, this, &DrawnMotion::onSelectionChanged);
    connect(&subdivision_, &jobs::SubdivisionJob::subdivided, this,
            [this](std::uint64_t, const std::vector<Pose>& poses, qint64 nanoseconds) { receiveTrail(poses, nanoseconds); });
    connect(&subdivision_, &jobs::SubdivisionJob::failed, this, [this] {
        dropTrail();
        emit changed();
    });
    trailObject_ = selection_.object();
    motion_ = std::make_shared<model::SceneMotion>(document_.scene());
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
    previewTrack_ = std::move(track);
    rebuildMotionInBackground();
}

void DrawnMotion::onSceneReset()
{
    // Opening a project may wait for its motion; only dragging must not. A preview was of the old scene.
    previewTrack_.reset();
    ++motionGeneration_;
    motion_ = std::make_shared<model::SceneMotion>(document_.scene());
    trajectoryStale_ = true;
    trailPoseCount_ = 0; // the old scene's
    snapshotOriginalMotion();
    requestTrail();
    emit sceneReset();
}

void DrawnMotion::onObjectsChanged()
{
    rebuildMotionInBackground();
    trajectoryStale_ = true;
    requestTrail();
    emit changed();
}

void DrawnMotion::onTrackChanged(model::ObjectId id)
{
    rebuildMotionInBackground();
    if (id == selection_.object())
        requestTrail();
    emit changed();
}

void DrawnMotion::onSelectionChanged()
{
    if (selection_.object() != trailObject_) {
        // The trail in hand is another object's: show none until this object's arrives.
        trailObject_ = selection_.object();
        trailPoseCount_ = 0;
    }
    trajectoryStale_ = true;
    requestTrail();
    emit changed();
}

void DrawnMotion::snapshotOriginalMotion()
{
    originalScene_ = document_.scene();
    originalMotion_ = model::SceneMotion(originalScene_);
}

model::Scene DrawnMotion::sceneToDraw() const
{
    model::Scene scene = document_.scene();
    if (previewTrack_)
        if (model::SceneObject* previewed = model::findObject(scene, previewObject_))
            previewed->track = *previewTrack_;
    return scene;
}

void DrawnMotion::rebuildMotionInBackground()
{
    // The whole scene each time, so that the newest request, the one that runs, has every change.
    const std::uint64_t generation = ++motionGeneration_;
    motionThread_.post([this, generation, scene = sceneToDraw()](const std::atomic<bool>&) {
        auto built = std::make_shared<const model::SceneMotion>(scene);
        QMetaObject::invokeMethod(
            this, [this, generation, built = std::move(built)] { receiveMotion(generation, built); },
            Qt::QueuedConnection);
    });
}

void DrawnMotion::receiveMotion(std::uint64_t generation, std::shared_ptr<const model::SceneMotion> built)
{
    if (generation != motionGeneration_)
        return;
    motion_ = std::move(built);
    // A parent's change moves the selected object's trajectory as well as its own.
    trajectoryStale_ = true;
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

void DrawnMotion::requestTrail()
{
    const model::SceneObject* object = selection_.selectedObject();
    if (!isScrewBenderTrack(object)) {
        subdivision_.cancel();
        dropTrail();
        return;
    }
    std::vector<Pose> controlPoses;
    controlPoses.reserve(object->track.keys.size());
    for (const model::Keyframe& key : object->track.keys)
        controlPoses.push_back(key.pose);
    sinceTrailRequest_.start();
    subdivision_.request(std::move(controlPoses), object->track.subdivision);
}

void DrawnMotion::receiveTrail(const std::vector<Pose>& poses, qint64 nanoseconds)
{
    subdivisionMilliseconds_ = double(nanoseconds) / 1e6;
    subdivisionLatencyMilliseconds_ = double(sinceTrailRequest_.nsecsElapsed()) / 1e6;
    trailMatrices_.clear();
    for (const Pose& pose : poses)
        appendPoseMatrix(trailMatrices_, pose);
    trailPoseCount_ = poses.size();
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
    const bool joint = findJoints(scene)[static_cast<std::size_t>(object - scene.objects.data())];
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
