#pragma once
// The 3D view. It draws every object at the document's current time (a default shape for an object
// without a mesh), the ground grid, the selected object's centre trajectory, its original motion as a
// translucent ghost, and ScrewBender's editing: the selected object's control poses (its keyframes)
// in place, handles on the selected one, and the stroboscopic trail of the subdivided polyscrew of the
// keys, re-subdivided off the UI thread (SubdivisionJob) while a handle is dragged.
//
// Mouse: left-drag on a handle moves or turns the selected key (one undo step per drag); left-drag
// elsewhere orbits; middle-drag or shift+left-drag pans; the wheel zooms. A left click selects the
// control pose or object under the cursor; a click on empty space keeps the object selected and
// clears the key selection. The view changes the document only by pushing undo commands.

#include "app/selection.h"
#include "app/undo_gesture.h"
#include "app/viewport/orbit_camera.h"
#include "app/viewport/picking.h"
#include "app/viewport/scene_motion.h"
#include "jobs/subdivision_job.h"
#include "model/document.h"

#include <QElapsedTimer>
#include <QOpenGLBuffer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QOpenGLWidget>
#include <QSurfaceFormat>
#include <QPointF>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

namespace gyre::app {

class Viewport final : public QOpenGLWidget, protected QOpenGLExtraFunctions {
    Q_OBJECT

public:
    // The handles on the selected key pose: arrows along and rings about its parent frame's axes.
    enum class Handle { MoveX, MoveY, MoveZ, RotateX, RotateY, RotateZ };

    Viewport(model::Document& document, Selection& selection, QWidget* parent = nullptr);
    ~Viewport() override;

    // What the viewport draws with: OpenGL 3.3, core profile, a depth buffer.
    static QSurfaceFormat surfaceFormat();
    // Whether the display gives such a context. Without one, Qt 6.4 brings the whole window down as
    // soon as a QOpenGLWidget is shown, so the window asks first.
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
    // Points the camera at all objects, the selected object's trajectory and its control poses.
    void frameScene();

    OrbitCamera& camera() { return camera_; }
    // Instances in the last trail drawn (0 when the last frame drew none).
    std::size_t trailInstanceCount() const { return drawnTrailInstances_; }
    // Whether the last frame drew the ghost: the original motion differs at the current time.
    bool drewGhost() const { return drewGhost_; }
    std::uint64_t framesDrawn() const { return framesDrawn_; }

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

protected:
    void initializeGL() override;
    void resizeGL(int width, int height) override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    struct GpuMesh {
        std::shared_ptr<const model::Mesh> owner; // keeps the mesh, and so its address, alive; null for the default shape
        std::unique_ptr<QOpenGLVertexArrayObject> vertexArray;
        QOpenGLBuffer vertices{QOpenGLBuffer::VertexBuffer};
        QOpenGLBuffer indices{QOpenGLBuffer::IndexBuffer};
        int indexCount = 0;
        float radius = 1.0F; // of the bounding sphere about the local origin
        std::optional<GLenum> frontFace; // GL_CCW or GL_CW for a closed mesh, whose back faces are culled
    };

    struct LineVertex {
        float position[3];
        float color[4];
    };

    // A run of lineVertices_ drawn as one primitive.
    struct LineRange {
        int first = 0;
        int count = 0;
    };

    // The selected key's handles in the world: centre, the parent frame's axes (columns) and the
    // arrows' length, which keeps their size on screen.
    struct HandleFrame {
        Eigen::Vector3d centre = Eigen::Vector3d::Zero();
        Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
        double length = 1.0;
    };

    enum class DragKind { None, Orbit, Pan, Handle };

    struct Drag {
        DragKind kind = DragKind::None;
        QPointF pressPosition;
        QPointF lastPosition;
        bool moved = false;
        Handle handle = Handle::MoveX;
        model::ObjectId object = model::kNoObject;
        std::size_t key = 0;
        Pose startKeyPose;          // the key's local pose when the drag began
        Eigen::Vector3d worldAxis = Eigen::Vector3d::UnitX(); // the handle's axis in the world
        int axisIndex = 0;          // 0, 1, 2: x, y, z of the parent frame
        Eigen::Vector3d centre = Eigen::Vector3d::Zero();    // the key's world position when the drag began
        double startAxisParameter = 0.0;
        double startScreenAngle = 0.0;
    };

    // Model changes, followed lazily: the motions are rebuilt once per frame, not per signal.
    void onSceneReset();
    void onObjectsChanged();
    void onTrackChanged(model::ObjectId id);
    void onSelectionChanged();
    void snapshotOriginalMotion();
    // The document's scene with the preview track in place of its object's track.
    model::Scene sceneToDraw() const;
    void rebuildMotionInBackground();
    void receiveMotion(std::uint64_t generation, std::shared_ptr<const SceneMotion> motion);
    void requestTrail();
    static bool isScrewBenderTrack(const model::SceneObject* object);
    void receiveTrail(std::uint64_t generation, const std::vector<Pose>& poses, qint64 nanoseconds);
    const SceneMotion& motion() const { return *motion_; }

    // Geometry shared by drawing, picking and the accessors.
    std::optional<HandleFrame> handleFrame() const;
    std::optional<Handle> handleAt(const QPointF& position) const;
    double pixelSizeAt(const Eigen::Vector3d& world) const;
    QPointF toScreen(const Eigen::Vector3d& world) const;
    Eigen::Vector3d ringPoint(const HandleFrame& frame, int axis, double angle) const;
    void pickAt(const QPointF& position);
    bool startHandleDrag(Handle handle, const QPointF& position);
    void dragHandle(const QPointF& position);
    double screenAngle(const QPointF& position) const;

    // Drawing.
    void releaseGl();
    GpuMesh& gpuMesh(const model::SceneObject& object);
    void dropUnusedMeshes();
    void drawMesh(GpuMesh& mesh, QOpenGLBuffer& instances, int instanceCount);
    void buildLines();
    void rebuildTrajectory();
    void drawLines(GLenum mode, LineRange range);
    void uploadControlPoses(const model::SceneObject& object);
    void measureFrame();

    model::Document& document_;
    Selection& selection_;
    OrbitCamera camera_;
    bool cameraIsFramed_ = false; // by frameScene, and not moved since

    bool showGhost_ = true;
    bool showTrajectory_ = true;
    bool showControlPoses_ = true;
    bool showTrail_ = true;

    // The motion drawn: the document's, or a moment behind it while a newer one is built.
    std::shared_ptr<const SceneMotion> motion_ = std::make_shared<SceneMotion>();
    std::uint64_t motionGeneration_ = 0; // of the newest motion asked for
    model::ObjectId previewObject_ = model::kNoObject;
    std::optional<model::MotionTrack> previewTrack_;
    model::Scene originalScene_; // as opened or last saved, for the ghost
    SceneMotion originalMotion_;

    std::unique_ptr<QOpenGLShaderProgram> meshProgram_;
    std::unique_ptr<QOpenGLShaderProgram> lineProgram_;
    std::unordered_map<const model::Mesh*, GpuMesh> gpuMeshes_;
    bool meshesMayBeUnused_ = false;
    QOpenGLBuffer identityInstance_{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer trailInstances_{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer controlPoseInstances_{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer lineBuffer_{QOpenGLBuffer::VertexBuffer};
    std::unique_ptr<QOpenGLVertexArrayObject> lineArray_;

    // Buffers kept from frame to frame, so that drawing allocates nothing once they have grown.
    std::vector<float> trailMatrices_;        // column-major 4×4 per subdivided pose, local to the parent
    bool trailUploadPending_ = false;
    std::size_t trailPoseCount_ = 0;
    model::ObjectId trailObject_ = model::kNoObject; // whose trail trailMatrices_ holds
    std::vector<float> controlPoseMatrices_;
    std::vector<LineVertex> lineVertices_;
    std::vector<LineVertex> trajectoryVertices_;
    bool trajectoryStale_ = true;
    LineRange gridLines_, trajectoryStrip_, axisLines_, handleLines_, handlePoints_;

    std::size_t drawnTrailInstances_ = 0;
    bool drewGhost_ = false;
    std::uint64_t framesDrawn_ = 0;

    Drag drag_;
    std::optional<UndoGesture> gesture_;

    QElapsedTimer frameClock_;
    qint64 measuredNanoseconds_ = 0;
    int measuredFrames_ = 0;
    double subdivisionMilliseconds_ = 0.0;
    double subdivisionLatencyMilliseconds_ = 0.0;
    QElapsedTimer sinceTrailRequest_;

    // Last: joined first, so no trail or motion arrives once the members above are gone.
    jobs::SubdivisionJob subdivision_;
    jobs::JobThread motionThread_;
};

} // namespace gyre::app
