#pragma once
// The 3D view. It draws every object at the document's current time (a default shape for an object
// without a mesh), the ground grid, the selected object's centre trajectory, its original motion as a
// translucent ghost, its stroboscopic trail (copies of it along its motion, whatever its interpolation:
// for a screw track the subdivided polyscrew of the keys, re-subdivided off the UI thread while a handle
// is dragged), and ScrewBender's editing: the control poses (its keyframes) in place, handles on the
// selected one.
//
// Mouse: left-drag on a handle moves or turns the selected key (one undo step per drag); left-drag
// elsewhere orbits; middle-drag or shift+left-drag pans; the wheel zooms. A left click selects the
// control pose or object under the cursor; a click on empty space keeps the object selected and
// clears the key selection; a Ctrl+click adds the object under the cursor to the selected objects, or
// takes it out (Shift+drag pans, so Shift cannot). The view changes the document only by pushing undo commands.
//
// The widget wires input and the document to its parts: DrawnMotion follows the document,
// SceneRenderer draws, HandleFrame and HandleDrag place and drag the handles, OrbitCamera looks.

#include "app/selection.h"
#include "app/viewport/drawn_motion.h"
#include "app/viewport/frame_lines.h"
#include "app/viewport/handle_drag.h"
#include "app/viewport/offscreen_gl_widget.h"
#include "app/viewport/orbit_camera.h"
#include "app/viewport/pose_handles.h"
#include "app/viewport/scene_renderer.h"
#include "app/viewport/skeleton.h"
#include "model/document.h"

#include <QElapsedTimer>
#include <QPointF>
#include <QSurfaceFormat>

#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <optional>

namespace gyre::app {

class Viewport final : public OffscreenGlWidget {
    Q_OBJECT

public:
    using Handle = app::Handle;

    Viewport(model::Document& document, Selection& selection, QWidget* parent = nullptr);
    ~Viewport() override;

    // What the viewport draws with: OpenGL 3.3, core profile, a depth buffer.
    static QSurfaceFormat surfaceFormat();
    // Whether the display gives such a context. Without one the window shows a message in the
    // viewport's place.
    static bool isSupported();

    // The viewport is what the window is for: it asks for most of it.
    QSize sizeHint() const override { return {960, 640}; }

    // Draws `object` following `track` instead of its own track, until called with nullopt: the
    // preview of a live fit while a stroke is still being drawn. The document is not changed.
    void setPreviewTrack(model::ObjectId object, std::optional<model::MotionTrack> track);

    void setShowGhost(bool show);
    void setShowTrajectory(bool show);
    void setShowControlPoses(bool show);
    void setShowTrail(bool show);
    // How a trail other than a screw track's is spaced (sampled_trail.h).
    void setTrailSpacing(const TrailSpacing& spacing);
    // The selected object's angular momentum as an arrow, and its principal axes (body_overlay.h).
    void setShowAngularMomentum(bool show);
    void setShowPrincipalAxes(bool show);
    // Points the camera at all objects, the selected object's trajectory and its control poses.
    void frameScene();
    // frameScene as soon as the motion drawn holds every object of the scene (after an import, whose
    // motion is built off the UI thread).
    void frameSceneWhenDrawn();
    // Points the camera at the selected object (a joint: its bones); at the scene when none is selected.
    void frameSelected();

    // Blender's number-pad views. Z-up (Blender): front looks along +y, right along −x, top down −z.
    // Y-up (Maya): front looks along −z, right along −x, top down −y. Each opposite looks the other way.
    enum class ViewPoint { Front, Back, Right, Left, Top, Bottom };
    void viewFrom(ViewPoint point);
    void setOrthographic(bool orthographic);
    // Shows the Z-up scene Z-up or Y-up: the camera orbits about that axis, the grid lies across it, and
    // the number-pad views follow (OrbitCamera::setUpAxis). The scene's data does not change.
    void setUpAxis(UpAxis up);
    void setShading(Shading shading);
    Shading shading() const { return shading_; }

    // The joints and bones as the last frame drew them.
    const Skeleton& skeleton() const { return skeleton_; }
    OrbitCamera& camera() { return camera_; }
    // Instances in the last trails drawn, every selected object's together (0 when the last frame drew none).
    std::size_t trailInstanceCount() const { return drawnTrailInstances_; }
    // Points in the centre paths the last frame drew, every selected object's (0 while they are hidden).
    std::size_t pathPointCount() const { return drawnPathPoints_; }
    // Whether the last frame drew the ghost: the original motion differs at the current time.
    bool drewGhost() const { return drewGhost_; }
    std::uint64_t framesDrawn() const { return framesDrawn_; }
    // Whether a mouse drag orbits, pans or moves a handle, from its press to its release.
    bool isDragging() const { return dragging_; }

    // Where to press to grab a handle of the selected key; nullopt when no key is selected.
    std::optional<QPointF> handleScreenPosition(Handle handle) const;
    // The screen point of the selected object's control pose at index `key`, or nullopt.
    std::optional<QPointF> controlPoseScreenPosition(std::size_t key) const;
    // The screen point of the object's origin at the current time, or nullopt for no such object.
    std::optional<QPointF> objectScreenPosition(model::ObjectId id) const;

signals:
    // Every half second of drawing: frames per second over the intervals between frames drawn back
    // to back (pauses of more than kIdleFrameGap are left out), the worker's time for the newest
    // trail, and the time from its request to its arrival on the UI thread.
    void frameStatsChanged(double framesPerSecond, double subdivisionMilliseconds, double subdivisionLatencyMilliseconds);
    // A drag began or ended (isDragging).
    void draggingChanged(bool dragging);
    // The motion or the trail to draw could not be built (DrawnMotion::failed); the message says why.
    void drawingFailed(const QString& message);

protected:
    void initializeGL() override;
    void resizeEvent(QResizeEvent* event) override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    enum class DragKind { None, Orbit, Pan, Handle };

    struct Drag {
        DragKind kind = DragKind::None;
        QPointF pressPosition;
        QPointF lastPosition;
        bool moved = false;
    };

    // The handles on the selected key, or nullopt when no key is selected.
    std::optional<HandleFrame> handleFrame() const;
    // Whether the selected object's control poses are drawn and can be clicked.
    bool showsControlPoses() const;
    // Selects what is under `position`; with `toggle` (Ctrl held) adds the object hit to the selected
    // objects, or takes it out.
    void pickAt(const QPointF& position, bool toggle);
    // The box about what is drawn for the object at scene.objects[index] at the current time.
    Eigen::AlignedBox3d objectBox(std::size_t index) const;
    void updateSkeleton();
    void frameBox(Eigen::AlignedBox3d box);
    void buildLines();
    void measureFrame();
    void setDragging(bool dragging);

    model::Document& document_;
    Selection& selection_;
    DrawnMotion drawn_;
    SceneRenderer renderer_;
    OrbitCamera camera_;
    bool cameraIsFramed_ = false; // by frameScene, and not moved since
    bool framePending_ = false;   // frameSceneWhenDrawn waits for the motion
    bool reframeWithPaths_ = false; // framed by frameSceneWhenDrawn before the selected objects' paths arrived
    Skeleton skeleton_;
    Shading shading_;

    bool showGhost_ = true;
    bool showTrajectory_ = true;
    bool showControlPoses_ = true;
    bool showTrail_ = true;
    bool showAngularMomentum_ = false;
    bool showPrincipalAxes_ = false;

    FrameLines lines_; // kept from frame to frame, so that drawing allocates nothing once it has grown

    std::size_t drawnTrailInstances_ = 0;
    std::size_t drawnPathPoints_ = 0;
    bool drewGhost_ = false;
    std::uint64_t framesDrawn_ = 0;

    Drag drag_;
    bool dragging_ = false;
    HandleDrag handleDrag_;

    QElapsedTimer frameClock_;
    qint64 measuredNanoseconds_ = 0;
    int measuredFrames_ = 0;
};

} // namespace gyre::app
