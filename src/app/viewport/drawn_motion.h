#pragma once
// The motion the viewport draws, following the document: the scene's motion made anew after each
// change from the document's shared track motions, the changed ones built off the UI thread by a
// newest-wins job (a moment behind while a newer one is built), a live fit's preview track
// in place of its object's own, the motion as opened or last saved (the ghost), and for every selected
// object its centre's path and its stroboscopic trail, as sampled_trail.h's planTrails shares their budget:
// each selected screw track's subdivided polyscrew (all of them on one newest-wins SubdivisionJob, as
// ScrewBender edits them; while a pose of the active one is dragged, only its track is subdivided again), and
// every other selected object's motion sampled at evenly spaced times. The sampled trails and the centre paths
// (centre_path.h, within its budget) are sampled off the UI thread from the motion drawn, on one newest-wins
// job: like the trails, the paths are a moment behind an edit, and follow it once sampled; they are sampled
// again only when the motion, the selection or the scene's range changed, not when the current time moves the
// copies.

#include "app/selection.h"
#include "app/viewport/centre_path.h"
#include "app/viewport/pose_matrix.h"
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

    // How the trail of a track other than a screw one is spaced (sampled_trail.h), clamped to its budget; the
    // copies also decide how the selected objects share the trails' budget (planTrails).
    void setTrailSpacing(const TrailSpacing& spacing);
    const TrailSpacing& trailSpacing() const { return trailSpacing_; }

    // Where one object's copies are in trailMatrices(): `count` matrices from `first`, in the object's parent's
    // frame for a screw track's (its subdivided poses), in the world for any other.
    struct DrawnTrail {
        model::ObjectId object = model::kNoObject;
        std::size_t first = 0;
        std::size_t count = 0;
        bool inParentFrame = false;
    };
    // The selected objects' trails: a column-major 4×4 matrix per copy, every object's in one array.
    const std::vector<float>& trailMatrices() const { return trailMatrices_; }
    const std::vector<DrawnTrail>& trails() const { return trails_; }
    // Every object's copies together.
    std::size_t trailPoseCount() const { return trailMatrices_.size() / kFloatsPerMatrix; }
    // Whether the trail changed since the last call, which then uploads it.
    bool takeTrailChange() { return std::exchange(trailChanged_, false); }
    // The worker's time for the newest screw trails, and the time from their request to their arrival.
    double subdivisionMilliseconds() const { return subdivisionMilliseconds_; }
    double subdivisionLatencyMilliseconds() const { return subdivisionLatencyMilliseconds_; }

    // The world paths of the selected objects' mesh centres over the scene's time range (centre_path.h: the
    // active object's first, within its budget), as last sampled; none without a selected object.
    const std::vector<std::vector<Eigen::Vector3f>>& trajectories() const { return trajectories_; }
    // Whether the paths changed since the last call (the viewport then uploads them).
    bool takeTrajectoriesChange() { return std::exchange(trajectoriesChanged_, false); }
    // Whether the paths are being sampled anew (after a change of the motion, the selection or the scene's
    // range): trajectories() is then a moment behind.
    bool trajectoriesPending() const { return trajectoriesStale_; }

signals:
    // Something drawn changed: the viewport repaints.
    void changed();
    // A new scene's motion is in place: the viewport frames it.
    void sceneReset();
    // The motion or the trail could not be built; the one drawn stays, the trail goes.
    void failed(const QString& message);

private:
    // What the sampled-trail job makes: the sampled trails and, when they were stale, the centre paths.
    struct Sampled {
        std::vector<ObjectTrail> trails;
        std::optional<std::vector<std::vector<Eigen::Vector3f>>> paths;
    };
    // One selected screw track's subdivided poses.
    struct ScrewTrail {
        model::ObjectId object = model::kNoObject;
        jobs::SubdivisionJob::SubdividedPoses poses;
    };

    void onDocumentChanged(model::ObjectId object, model::Changes changes);
    // Another set of selected objects or another active one: their trails and paths.
    void onSelectionChanged();
    void snapshotOriginalMotion();
    // Each object's motion: the document's, the preview's in place of its object's.
    model::SceneMotion::MotionOf motionOf() const;
    void rebuildMotionInBackground();
    void receiveMotion(std::shared_ptr<const model::SceneMotion> built);
    // planTrails on the selection as it is now.
    TrailPlan currentTrailPlan() const;
    // Every trail: the screw tracks' and the sampled ones.
    void requestTrail();
    // The selected screw tracks' subdivisions, from their keys.
    void requestScrewTrails();
    // The trails of the tracks other than screw ones, and the centre paths if stale, from the motion drawn now.
    void requestSampledTrail();
    void receiveScrewTrails(const std::vector<jobs::SubdivisionJob::SubdividedPoses>& poses);
    void receiveSampled(Sampled sampled);
    // trailMatrices_ and trails_ from the screw trails and the sampled ones.
    void composeTrails();
    void setTrajectories(std::vector<std::vector<Eigen::Vector3f>> paths);
    void dropTrail();

    model::Document& document_;
    Selection& selection_;

    std::shared_ptr<const model::SceneMotion> motion_ = std::make_shared<model::SceneMotion>();
    model::ObjectId previewObject_ = model::kNoObject;
    std::shared_ptr<const model::SharedTrackMotion> previewMotion_;
    model::Scene originalScene_; // as opened or last saved, for the ghost
    model::SceneMotion originalMotion_;

    // Kept from frame to frame, so that following the motion allocates nothing once they have grown.
    std::vector<float> trailMatrices_;
    std::vector<DrawnTrail> trails_;
    bool trailChanged_ = false;
    TrailSpacing trailSpacing_;
    std::vector<model::ObjectId> screwTrailObjects_; // whose subdivisions the newest request asked for, in its order
    std::vector<ScrewTrail> screwTrails_;
    std::vector<ObjectTrail> sampledTrails_;
    // As the trails and paths were last asked for.
    std::vector<model::ObjectId> selectedObjects_;
    model::ObjectId activeObject_ = model::kNoObject;
    std::vector<std::vector<Eigen::Vector3f>> trajectories_; // set by setTrajectories alone
    bool trajectoriesChanged_ = false;
    bool trajectoriesStale_ = true;

    double subdivisionMilliseconds_ = 0.0;
    double subdivisionLatencyMilliseconds_ = 0.0;
    QElapsedTimer sinceTrailRequest_;

    // Last: done first, so no trail or motion arrives once the members above are gone.
    jobs::SubdivisionJob subdivision_;
    jobs::Job<std::shared_ptr<const model::SceneMotion>> motionJob_;
    jobs::Job<Sampled> sampledJob_;
};

} // namespace gyre::app
