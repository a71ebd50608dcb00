#pragma once
// The motion the viewport draws, following the document: the scene's motion made anew after each
// change from the document's shared track motions, the changed ones built off the UI thread by a
// newest-wins job (a moment behind while a newer one is built), a live fit's preview track
// in place of its object's own, the motion as opened or last saved (the ghost), the selected
// object's trajectory, and its stroboscopic trail: a screw track's subdivided polyscrew (SubdivisionJob),
// any other track's motion sampled at evenly spaced times (sampled_trail.h, on a newest-wins job).

#include "app/selected_track.h"
#include "app/selection.h"
#include "app/viewport/sampled_trail.h"
#include "model/scene_motion.h"
#include "jobs/job.h"
#include "jobs/subdivision_job.h"
#include "model/document.h"

#include <QElapsedTimer>
#include <QObject>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace gyre::app {

class DrawnMotion final : public QObject {
    Q_OBJECT

public:
    DrawnMotion(model::Document& document, Selection& selection, QObject* parent = nullptr);

    const model::SceneMotion& motion() const { return *motion_; }
    // The object's world pose at `time` as opened or last saved; nullopt for an object added since.
    std::optional<Pose> originalWorldPose(model::ObjectId id, double time) const;

    // Follows `track` for `object` instead of its own track, until called with nullopt.
    void setPreviewTrack(model::ObjectId object, std::optional<model::MotionTrack> track);

    // The control poses belong to ScrewBender's editing. Another track's keys may all sit in one place
    // (a spinning top's 85 keys at its tip), where they would only hide the object.
    static bool isScrewBenderTrack(const model::SceneObject* object);

    // How the trail of a track other than a screw one is spaced (sampled_trail.h); clamped to its budget.
    void setTrailSpacing(const TrailSpacing& spacing);
    const TrailSpacing& trailSpacing() const { return trailSpacing_; }

    // The selected object's trail: a column-major 4×4 matrix per copy, in its parent's frame for a
    // screw track (the subdivided poses), in the world for any other (trailInParentFrame).
    const std::vector<float>& trailMatrices() const { return trailMatrices_; }
    bool trailInParentFrame() const { return trailInParentFrame_; }
    std::size_t trailPoseCount() const { return trailPoseCount_; }
    // Whether the trail changed since the last call, which then uploads it.
    bool takeTrailChange() { return std::exchange(trailChanged_, false); }
    // The worker's time for the newest trail, and the time from its request to its arrival.
    double subdivisionMilliseconds() const { return subdivisionMilliseconds_; }
    double subdivisionLatencyMilliseconds() const { return subdivisionLatencyMilliseconds_; }

    // The world path of the selected object's mesh centre over the scene's time range, one point a
    // frame (at most kMaxTrajectorySamples + 1); empty without a selected object.
    const std::vector<Eigen::Vector3f>& trajectory();
    static constexpr int kMaxTrajectorySamples = 4096;

signals:
    // Something drawn changed: the viewport repaints.
    void changed();
    // A new scene's motion is in place: the viewport frames it.
    void sceneReset();
    // The motion or the trail could not be built; the one drawn stays, the trail goes.
    void failed(const QString& message);

private:
    void onDocumentChanged(model::ObjectId object, model::Changes changes);
    void onSelectedTrackChanged(model::Changes changes);
    void snapshotOriginalMotion();
    // Each object's motion: the document's, the preview's in place of its object's.
    model::SceneMotion::MotionOf motionOf() const;
    void rebuildMotionInBackground();
    void receiveMotion(std::shared_ptr<const model::SceneMotion> built);
    void requestTrail();
    // The trail of a track other than a screw one, from the motion drawn now.
    void requestSampledTrail();
    void receiveTrail(const std::vector<Pose>& poses, bool inParentFrame);
    void dropTrail();
    void rebuildTrajectory();

    model::Document& document_;
    Selection& selection_;
    SelectedTrack selectedTrack_;

    std::shared_ptr<const model::SceneMotion> motion_ = std::make_shared<model::SceneMotion>();
    model::ObjectId previewObject_ = model::kNoObject;
    std::shared_ptr<const model::SharedTrackMotion> previewMotion_;
    model::Scene originalScene_; // as opened or last saved, for the ghost
    model::SceneMotion originalMotion_;

    // Kept from frame to frame, so that following the motion allocates nothing once they have grown.
    std::vector<float> trailMatrices_;
    bool trailChanged_ = false;
    std::size_t trailPoseCount_ = 0;
    bool trailInParentFrame_ = true;
    TrailSpacing trailSpacing_;
    model::ObjectId trailObject_ = model::kNoObject; // whose trail trailMatrices_ holds
    std::vector<Eigen::Vector3f> trajectory_;
    bool trajectoryStale_ = true;

    double subdivisionMilliseconds_ = 0.0;
    double subdivisionLatencyMilliseconds_ = 0.0;
    QElapsedTimer sinceTrailRequest_;

    // Last: done first, so no trail or motion arrives once the members above are gone.
    jobs::SubdivisionJob subdivision_;
    jobs::Job<std::shared_ptr<const model::SceneMotion>> motionJob_;
    jobs::Job<std::vector<Pose>> sampledTrailJob_;
};

} // namespace gyre::app
