#include "app/viewport/viewport.h"

#include "app/viewport/default_shape.h"
#include "app/viewport/mesh_winding.h"
#include "model/commands/set_keyframe_orientation_command.h"
#include "model/commands/set_keyframe_position_command.h"
#include "model/scene_queries.h"

#include <QMatrix4x4>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QSurfaceFormat>
#include <QVector3D>
#include <QWheelEvent>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>

namespace gyre::app {

namespace {

// Mesh shader attributes: position, normal, then the instance's model matrix as four columns.
constexpr GLuint kPositionAttribute = 0;
constexpr GLuint kNormalAttribute = 1;
constexpr GLuint kInstanceAttribute = 2;
constexpr int kFloatsPerMatrix = 16;

constexpr double kControlPoseScale = 0.6; // control poses are drawn as small copies
constexpr double kHandlePixels = 90.0;    // arrow length on screen
constexpr double kRingRadius = 0.7;       // of the arrow length
constexpr int kRingSegments = 64;
constexpr double kArrowPressPoint = 0.95; // where along an arrow handleScreenPosition points
constexpr double kGrabPixels = 8.0;       // how near a handle a press grabs it
constexpr double kClickPixels = 3.0;      // a press that moves less is a click
constexpr float kHandlePointSize = 11.0F;
constexpr int kGridHalfLines = 10;        // a 20 × 20 grid of unit squares about the origin
constexpr int kMaxTrajectorySamples = 4096;
constexpr double kGhostTolerance = 1e-6;  // the ghost is drawn where the motions differ by more
constexpr qint64 kIdleFrameGap = 1'000'000'000; // ns: a longer gap between frames is idling, not drawing
constexpr qint64 kStatsWindow = 500'000'000;  // ns of drawing per frameStatsChanged

struct Rgba {
    float r, g, b, a;
};

constexpr Rgba kBackground{0.16F, 0.17F, 0.19F, 1.0F};
constexpr Rgba kObjectColor{0.62F, 0.66F, 0.72F, 1.0F};
constexpr Rgba kSelectedColor{0.98F, 0.63F, 0.22F, 1.0F};
constexpr Rgba kTrailStart{0.30F, 0.55F, 0.95F, 0.3F};
constexpr Rgba kTrailEnd{0.55F, 0.90F, 0.75F, 0.3F};
constexpr Rgba kControlPoseColor{0.95F, 0.95F, 0.98F, 0.35F};
constexpr Rgba kSelectedKeyColor{1.0F, 0.85F, 0.30F, 0.6F};
constexpr Rgba kGhostColor{0.85F, 0.85F, 1.0F, 0.25F};
constexpr Rgba kGridColor{0.32F, 0.33F, 0.36F, 1.0F};
constexpr Rgba kTrajectoryColor{1.0F, 0.9F, 0.35F, 1.0F};
constexpr Rgba kAxisColors[3] = {{0.95F, 0.30F, 0.30F, 1.0F}, {0.35F, 0.85F, 0.35F, 1.0F}, {0.35F, 0.55F, 1.0F, 1.0F}};

QVector4D toVector(const Rgba& color)
{
    return {color.r, color.g, color.b, color.a};
}

QMatrix4x4 toQMatrix(const Eigen::Matrix4d& matrix)
{
    // QMatrix4x4 takes its 16 values in row-major order.
    const Eigen::Matrix<float, 4, 4, Eigen::RowMajor> rows = matrix.cast<float>();
    return QMatrix4x4(rows.data());
}

Eigen::Matrix4d poseMatrix(const Pose& pose, double scale = 1.0)
{
    Eigen::Matrix4d matrix = Eigen::Matrix4d::Identity();
    matrix.block<3, 3>(0, 0) = scale * pose.orientation.toRotationMatrix();
    matrix.block<3, 1>(0, 3) = pose.position;
    return matrix;
}

void appendMatrix(std::vector<float>& out, const Pose& pose, double scale = 1.0)
{
    const Eigen::Matrix4f matrix = poseMatrix(pose, scale).cast<float>(); // column-major, as the shader reads it
    out.insert(out.end(), matrix.data(), matrix.data() + kFloatsPerMatrix);
}

const model::Mesh& meshOf(const model::SceneObject& object)
{
    return object.mesh ? *object.mesh : defaultShapeMesh();
}

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

// The front face of a closed mesh, whose back faces the viewport culls; none for an open mesh.
std::optional<GLenum> cullableFrontFace(const model::Mesh& mesh)
{
    switch (meshWinding(mesh)) {
    case MeshWinding::CounterClockwise:
        return GL_CCW;
    case MeshWinding::Clockwise:
        return GL_CW;
    case MeshWinding::Open:
        break;
    }
    return std::nullopt;
}

bool samePose(const Pose& a, const Pose& b)
{
    return a.orientation.angularDistance(b.orientation) <= kGhostTolerance
           && (a.position - b.position).norm() <= kGhostTolerance * std::max(1.0, a.position.norm());
}

double wrapAngle(double angle)
{
    return std::remainder(angle, 2 * std::numbers::pi);
}

} // namespace

QSurfaceFormat Viewport::surfaceFormat()
{
    QSurfaceFormat format = QSurfaceFormat::defaultFormat();
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    return format;
}

bool Viewport::isSupported()
{
    QOpenGLContext probe;
    probe.setFormat(surfaceFormat());
    return probe.create() && probe.format().version() >= std::pair(3, 3);
}

Viewport::Viewport(model::Document& document, Selection& selection, QWidget* parent)
    : QOpenGLWidget(parent)
    , document_(document)
    , selection_(selection)
{
    setFormat(surfaceFormat());
    setMinimumSize(200, 150);
    setFocusPolicy(Qt::ClickFocus);

    connect(&document_, &model::Document::sceneReset, this, &Viewport::onSceneReset);
    connect(&document_, &model::Document::objectAdded, this, &Viewport::onObjectsChanged);
    connect(&document_, &model::Document::objectRemoved, this, &Viewport::onObjectsChanged);
    connect(&document_, &model::Document::objectChanged, this, &Viewport::onObjectsChanged);
    connect(&document_, &model::Document::keyframesChanged, this, &Viewport::onTrackChanged);
    connect(&document_, &model::Document::trackSettingsChanged, this, &Viewport::onTrackChanged);
    connect(&document_, &model::Document::sketchChanged, this, &Viewport::onTrackChanged);
    connect(&document_, &model::Document::sceneSettingsChanged, this, [this] {
        trajectoryStale_ = true;
        update();
    });
    connect(&document_, &model::Document::currentTimeChanged, this, [this] { update(); });
    connect(&document_.undoStack(), &QUndoStack::cleanChanged, this, [this](bool clean) {
        if (clean)
            snapshotOriginalMotion();
    });
    connect(&selection_, &Selection::changed, this, &Viewport::onSelectionChanged);
    connect(&subdivision_, &jobs::SubdivisionJob::subdivided, this, &Viewport::receiveTrail);
    connect(&subdivision_, &jobs::SubdivisionJob::failed, this, [this] {
        trailPoseCount_ = 0;
        trailMatrices_.clear();
        trailUploadPending_ = true;
        update();
    });
    trailObject_ = selection_.object();
    motion_ = std::make_shared<SceneMotion>(document_.scene());
    snapshotOriginalMotion();
    requestTrail();
}

Viewport::~Viewport()
{
    // QOpenGLWidget's destructor destroys the context after this part of the object is gone: its
    // aboutToBeDestroyed must not reach releaseGl then.
    if (QOpenGLContext* glContext = context())
        disconnect(glContext, nullptr, this, nullptr);
    releaseGl();
}

void Viewport::setPreviewTrack(model::ObjectId object, std::optional<model::MotionTrack> track)
{
    previewObject_ = object;
    previewTrack_ = std::move(track);
    rebuildMotionInBackground();
}

void Viewport::setShowGhost(bool show)
{
    showGhost_ = show;
    update();
}

void Viewport::setShowTrajectory(bool show)
{
    showTrajectory_ = show;
    update();
}

void Viewport::setShowControlPoses(bool show)
{
    showControlPoses_ = show;
    update();
}

void Viewport::setShowTrail(bool show)
{
    showTrail_ = show;
    update();
}

void Viewport::frameScene()
{
    const model::Scene& scene = document_.scene();
    const SceneMotion& sceneMotion = motion();
    Eigen::AlignedBox3d box;
    for (const model::SceneObject& object : scene.objects) {
        const Pose pose = sceneMotion.worldPose(object.id, scene.currentTime);
        for (const Eigen::Vector3f& position : meshOf(object).positions)
            box.extend(pose.apply(position.cast<double>()));
    }
    if (const model::SceneObject* selected = selection_.selectedObject()) {
        const Pose frame = sceneMotion.parentWorldPose(selected->id, scene.currentTime);
        for (const model::Keyframe& key : selected->track.keys)
            box.extend(frame.apply(key.pose.position));
    }
    if (trajectoryStale_)
        rebuildTrajectory();
    for (const LineVertex& vertex : trajectoryVertices_)
        box.extend(Eigen::Vector3f(vertex.position[0], vertex.position[1], vertex.position[2]).cast<double>());
    if (box.isEmpty())
        box = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-kGridHalfLines / 2.0), Eigen::Vector3d::Constant(kGridHalfLines / 2.0));
    camera_.frame(box.min(), box.max());
    cameraIsFramed_ = true;
    update();
}

// --- Following the model ---------------------------------------------------------------------------

void Viewport::onSceneReset()
{
    // Opening a project may wait for its motion; only dragging must not. A preview was of the old scene.
    previewTrack_.reset();
    ++motionGeneration_;
    motion_ = std::make_shared<SceneMotion>(document_.scene());
    meshesMayBeUnused_ = true;
    trajectoryStale_ = true;
    trailPoseCount_ = 0; // the old scene's
    snapshotOriginalMotion();
    requestTrail();
    frameScene();
}

void Viewport::onObjectsChanged()
{
    rebuildMotionInBackground();
    meshesMayBeUnused_ = true;
    trajectoryStale_ = true;
    requestTrail();
    update();
}

void Viewport::onTrackChanged(model::ObjectId id)
{
    rebuildMotionInBackground();
    if (id == selection_.object())
        requestTrail();
    update();
}

void Viewport::onSelectionChanged()
{
    if (selection_.object() != trailObject_) {
        // The trail in hand is another object's: show none until this object's arrives.
        trailObject_ = selection_.object();
        trailPoseCount_ = 0;
    }
    trajectoryStale_ = true;
    requestTrail();
    update();
}

void Viewport::snapshotOriginalMotion()
{
    originalScene_ = document_.scene();
    originalMotion_ = SceneMotion(originalScene_);
}

model::Scene Viewport::sceneToDraw() const
{
    model::Scene scene = document_.scene();
    if (previewTrack_)
        if (model::SceneObject* previewed = model::findObject(scene, previewObject_))
            previewed->track = *previewTrack_;
    return scene;
}

void Viewport::rebuildMotionInBackground()
{
    // The whole scene each time, so that the newest request, the one that runs, has every change.
    const std::uint64_t generation = ++motionGeneration_;
    motionThread_.post([this, generation, scene = sceneToDraw()](const std::atomic<bool>&) {
        auto built = std::make_shared<const SceneMotion>(scene);
        QMetaObject::invokeMethod(
            this, [this, generation, built = std::move(built)] { receiveMotion(generation, built); },
            Qt::QueuedConnection);
    });
}

void Viewport::receiveMotion(std::uint64_t generation, std::shared_ptr<const SceneMotion> built)
{
    if (generation != motionGeneration_)
        return;
    motion_ = std::move(built);
    // A parent's change moves the selected object's trajectory as well as its own.
    trajectoryStale_ = true;
    update();
}

// The trail and the control poses belong to ScrewBender's editing. Another track's keys may all sit
// in one place (a spinning top's 85 keys at its tip), where they would only hide the object.
bool Viewport::isScrewBenderTrack(const model::SceneObject* object)
{
    return object != nullptr && !object->track.keys.empty() && object->track.interpolation == InterpolationMethod::Screw;
}

void Viewport::requestTrail()
{
    const model::SceneObject* object = selection_.selectedObject();
    if (!isScrewBenderTrack(object)) {
        subdivision_.cancel();
        trailPoseCount_ = 0;
        trailMatrices_.clear();
        trailUploadPending_ = true;
        return;
    }
    std::vector<Pose> controlPoses;
    controlPoses.reserve(object->track.keys.size());
    for (const model::Keyframe& key : object->track.keys)
        controlPoses.push_back(key.pose);
    sinceTrailRequest_.start();
    subdivision_.request(std::move(controlPoses), object->track.subdivision);
}

void Viewport::receiveTrail(std::uint64_t, const std::vector<Pose>& poses, qint64 nanoseconds)
{
    subdivisionMilliseconds_ = double(nanoseconds) / 1e6;
    subdivisionLatencyMilliseconds_ = double(sinceTrailRequest_.nsecsElapsed()) / 1e6;
    trailMatrices_.clear();
    for (const Pose& pose : poses)
        appendMatrix(trailMatrices_, pose);
    trailPoseCount_ = poses.size();
    trailUploadPending_ = true;
    update();
}

// --- Geometry --------------------------------------------------------------------------------------

QPointF Viewport::toScreen(const Eigen::Vector3d& world) const
{
    const Eigen::Vector3d screen = camera_.project(world);
    return {screen.x(), screen.y()};
}

double Viewport::pixelSizeAt(const Eigen::Vector3d& world) const
{
    // The world size of a pixel at this point's distance: 2·d·tan(fovY/2) / height.
    return 2 * (world - camera_.eye()).norm() * std::tan(OrbitCamera::kFieldOfViewY / 2) / camera_.height();
}

std::optional<Viewport::HandleFrame> Viewport::handleFrame() const
{
    const model::Keyframe* key = selection_.selectedKey();
    if (key == nullptr)
        return std::nullopt;
    const Pose frame = motion().parentWorldPose(selection_.object(), document_.scene().currentTime);
    HandleFrame handles;
    handles.centre = frame.apply(key->pose.position);
    handles.axes = frame.orientation.toRotationMatrix();
    handles.length = kHandlePixels * pixelSizeAt(handles.centre);
    return handles;
}

Eigen::Vector3d Viewport::ringPoint(const HandleFrame& frame, int axis, double angle) const
{
    // The ring about axis k lies in the plane of the next two axes, k+1 and k+2.
    const Eigen::Vector3d u = frame.axes.col((axis + 1) % 3);
    const Eigen::Vector3d v = frame.axes.col((axis + 2) % 3);
    return frame.centre + kRingRadius * frame.length * (std::cos(angle) * u + std::sin(angle) * v);
}

std::optional<QPointF> Viewport::handleScreenPosition(Handle handle) const
{
    const std::optional<HandleFrame> frame = handleFrame();
    if (!frame)
        return std::nullopt;
    const int index = static_cast<int>(handle);
    if (index < 3)
        return toScreen(frame->centre + kArrowPressPoint * frame->length * frame->axes.col(index));
    // Halfway between the two arrows the ring passes, away from both.
    return toScreen(ringPoint(*frame, index - 3, std::numbers::pi / 4));
}

std::optional<Viewport::Handle> Viewport::handleAt(const QPointF& position) const
{
    const std::optional<HandleFrame> frame = handleFrame();
    if (!frame)
        return std::nullopt;
    const Eigen::Vector2d point(position.x(), position.y());
    const auto screen = [this](const Eigen::Vector3d& world) {
        const QPointF p = toScreen(world);
        return Eigen::Vector2d(p.x(), p.y());
    };
    std::optional<Handle> nearest;
    double nearestDistance = kGrabPixels;
    const auto consider = [&](Handle handle, double distance) {
        if (distance <= nearestDistance) {
            nearest = handle;
            nearestDistance = distance;
        }
    };
    const Eigen::Vector2d centre = screen(frame->centre);
    for (int axis = 0; axis < 3; ++axis) {
        const Eigen::Vector2d tip = screen(frame->centre + frame->length * frame->axes.col(axis));
        consider(static_cast<Handle>(axis), distanceToSegment(point, centre, tip));
        Eigen::Vector2d previous = screen(ringPoint(*frame, axis, 0));
        for (int segment = 1; segment <= kRingSegments; ++segment) {
            const Eigen::Vector2d next = screen(ringPoint(*frame, axis, 2 * std::numbers::pi * segment / kRingSegments));
            consider(static_cast<Handle>(3 + axis), distanceToSegment(point, previous, next));
            previous = next;
        }
    }
    return nearest;
}

std::optional<QPointF> Viewport::controlPoseScreenPosition(std::size_t key) const
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr || key >= object->track.keys.size())
        return std::nullopt;
    const Pose frame = motion().parentWorldPose(object->id, document_.scene().currentTime);
    return toScreen(frame.apply(object->track.keys[key].pose.position));
}

std::optional<QPointF> Viewport::objectScreenPosition(model::ObjectId id) const
{
    if (document_.object(id) == nullptr)
        return std::nullopt;
    return toScreen(motion().worldPose(id, document_.scene().currentTime).position);
}

double Viewport::screenAngle(const QPointF& position) const
{
    // Counter-clockwise on screen from the right, about the handle's centre; screen y points down.
    const QPointF centre = toScreen(drag_.centre);
    return std::atan2(centre.y() - position.y(), position.x() - centre.x());
}

void Viewport::pickAt(const QPointF& position)
{
    const Ray ray = camera_.ray(position.x(), position.y());
    const model::Scene& scene = document_.scene();
    const SceneMotion& sceneMotion = motion();
    std::vector<MeshPlacement> placements;
    std::vector<model::ObjectId> objects;
    std::vector<std::optional<std::size_t>> keys;
    for (const model::SceneObject& object : scene.objects) {
        placements.push_back({&meshOf(object), sceneMotion.worldPose(object.id, scene.currentTime), 1.0});
        objects.push_back(object.id);
        keys.emplace_back();
    }
    const model::SceneObject* selected = selection_.selectedObject();
    if (showControlPoses_ && isScrewBenderTrack(selected)) {
        const Pose frame = sceneMotion.parentWorldPose(selected->id, scene.currentTime);
        for (std::size_t key = 0; key < selected->track.keys.size(); ++key) {
            placements.push_back({&meshOf(*selected), frame * selected->track.keys[key].pose, kControlPoseScale});
            objects.push_back(selected->id);
            keys.emplace_back(key);
        }
    }
    const std::optional<std::size_t> hit = nearestHit(ray, placements);
    if (!hit)
        selection_.selectObject(selection_.object()); // empty space: keep the object, drop the key
    else if (keys[*hit])
        selection_.selectKey(objects[*hit], *keys[*hit]);
    else
        selection_.selectObject(objects[*hit]);
}

// --- Mouse -----------------------------------------------------------------------------------------

void Viewport::mousePressEvent(QMouseEvent* event)
{
    const QPointF position = event->position();
    drag_ = Drag{};
    drag_.pressPosition = position;
    drag_.lastPosition = position;
    const bool pan = event->button() == Qt::MiddleButton
                     || (event->button() == Qt::LeftButton && event->modifiers().testFlag(Qt::ShiftModifier));
    if (pan) {
        drag_.kind = DragKind::Pan;
    } else if (event->button() == Qt::LeftButton) {
        const std::optional<Handle> handle = handleAt(position);
        if (!handle || !startHandleDrag(*handle, position))
            drag_.kind = DragKind::Orbit;
    }
    event->accept();
}

bool Viewport::startHandleDrag(Handle handle, const QPointF& position)
{
    const std::optional<HandleFrame> frame = handleFrame();
    const model::Keyframe* key = selection_.selectedKey();
    if (!frame || key == nullptr)
        return false;
    drag_.handle = handle;
    drag_.object = selection_.object();
    drag_.key = *selection_.key();
    drag_.startKeyPose = key->pose;
    drag_.axisIndex = static_cast<int>(handle) % 3;
    drag_.worldAxis = frame->axes.col(drag_.axisIndex);
    drag_.centre = frame->centre;
    if (static_cast<int>(handle) < 3) {
        const std::optional<double> along = nearestOnAxis(camera_.ray(position.x(), position.y()), drag_.centre, drag_.worldAxis);
        if (!along)
            return false; // the axis points at the eye: moving along it cannot follow the cursor
        drag_.startAxisParameter = *along;
    } else {
        drag_.startScreenAngle = screenAngle(position);
    }
    drag_.kind = DragKind::Handle;
    gesture_.emplace(document_.undoStack());
    return true;
}

void Viewport::mouseMoveEvent(QMouseEvent* event)
{
    const QPointF position = event->position();
    const QPointF delta = position - drag_.lastPosition;
    if ((position - drag_.pressPosition).manhattanLength() > kClickPixels)
        drag_.moved = true;
    switch (drag_.kind) {
    case DragKind::Orbit:
        camera_.orbit(delta.x(), delta.y());
        cameraIsFramed_ = false;
        update();
        break;
    case DragKind::Pan:
        camera_.pan(delta.x(), delta.y());
        cameraIsFramed_ = false;
        update();
        break;
    case DragKind::Handle:
        dragHandle(position);
        break;
    case DragKind::None:
        break;
    }
    drag_.lastPosition = position;
    event->accept();
}

void Viewport::dragHandle(const QPointF& position)
{
    const model::SceneObject* object = document_.object(drag_.object);
    if (object == nullptr || drag_.key >= object->track.keys.size()) {
        // Another view removed the key mid-drag: the drag has nothing left to move.
        gesture_.reset();
        drag_.kind = DragKind::None;
        return;
    }
    const Eigen::Vector3d localAxis = Eigen::Vector3d::Unit(drag_.axisIndex);
    if (static_cast<int>(drag_.handle) < 3) {
        const std::optional<double> along = nearestOnAxis(camera_.ray(position.x(), position.y()), drag_.centre, drag_.worldAxis);
        if (!along)
            return;
        // The world axis is the parent frame's axis, so the same distance moves the local position.
        const Eigen::Vector3d moved = drag_.startKeyPose.position + (*along - drag_.startAxisParameter) * localAxis;
        if (moved.allFinite())
            gesture_->push(new model::SetKeyframePositionCommand(document_, drag_.object, drag_.key, moved));
    } else {
        // Turning the cursor counter-clockwise about the centre turns the pose counter-clockwise as
        // seen from the eye: about +axis if it points at the eye, about −axis otherwise.
        const double facing = drag_.worldAxis.dot(camera_.eye() - drag_.centre) >= 0 ? 1.0 : -1.0;
        const double angle = facing * wrapAngle(screenAngle(position) - drag_.startScreenAngle);
        const Eigen::Quaterniond turned = (Eigen::Quaterniond(Eigen::AngleAxisd(angle, localAxis)) * drag_.startKeyPose.orientation).normalized();
        gesture_->push(new model::SetKeyframeOrientationCommand(document_, drag_.object, drag_.key, turned));
    }
}

void Viewport::mouseReleaseEvent(QMouseEvent* event)
{
    if (drag_.kind == DragKind::Orbit && !drag_.moved && event->button() == Qt::LeftButton)
        pickAt(event->position());
    gesture_.reset(); // ends the drag's undo step
    drag_.kind = DragKind::None;
    event->accept();
}

void Viewport::wheelEvent(QWheelEvent* event)
{
    // angleDelta is in eighths of a degree; a wheel step is 15°.
    camera_.zoom(event->angleDelta().y() / 120.0);
    cameraIsFramed_ = false;
    update();
    event->accept();
}

// --- OpenGL ----------------------------------------------------------------------------------------

void Viewport::initializeGL()
{
    initializeOpenGLFunctions();
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::releaseGl, Qt::UniqueConnection);

    const auto buildProgram = [this](const QString& name) {
        auto program = std::make_unique<QOpenGLShaderProgram>();
        // The shaders are compiled into the program: failing to build them is a broken build or a
        // driver without OpenGL 3.3, and the log says which.
        if (!program->addShaderFromSourceFile(QOpenGLShader::Vertex, QStringLiteral(":/shaders/%1.vert").arg(name))
            || !program->addShaderFromSourceFile(QOpenGLShader::Fragment, QStringLiteral(":/shaders/%1.frag").arg(name))
            || !program->link())
            qCritical("Viewport: the %s shaders do not build: %s", qPrintable(name), qPrintable(program->log()));
        return program;
    };
    meshProgram_ = buildProgram(QStringLiteral("mesh"));
    lineProgram_ = buildProgram(QStringLiteral("line"));

    identityInstance_.create();
    identityInstance_.bind();
    const Eigen::Matrix4f identity = Eigen::Matrix4f::Identity();
    identityInstance_.allocate(identity.data(), kFloatsPerMatrix * sizeof(float));
    identityInstance_.release();
    for (QOpenGLBuffer* buffer : {&trailInstances_, &controlPoseInstances_, &lineBuffer_}) {
        buffer->create();
        buffer->setUsagePattern(QOpenGLBuffer::DynamicDraw);
    }
    trailUploadPending_ = true;

    lineArray_ = std::make_unique<QOpenGLVertexArrayObject>();
    lineArray_->create();
    lineArray_->bind();
    lineBuffer_.bind();
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(LineVertex), reinterpret_cast<const void*>(offsetof(LineVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(LineVertex), reinterpret_cast<const void*>(offsetof(LineVertex, color)));
    lineArray_->release();
    lineBuffer_.release();

    glEnable(GL_PROGRAM_POINT_SIZE);
    // Colour blends by the source's alpha; the framebuffer's own alpha stays 1 (1·a + 1·(1 − a)), so
    // the widget is opaque wherever it is composed: on screen and in QWidget::grab's pictures.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
}

void Viewport::releaseGl()
{
    if (!meshProgram_)
        return;
    makeCurrent();
    gpuMeshes_.clear();
    lineArray_.reset();
    for (QOpenGLBuffer* buffer : {&identityInstance_, &trailInstances_, &controlPoseInstances_, &lineBuffer_})
        buffer->destroy();
    meshProgram_.reset();
    lineProgram_.reset();
    doneCurrent();
}

void Viewport::resizeGL(int width, int height)
{
    // The camera works in widget pixels, as mouse events give them; OpenGL's viewport, in device
    // pixels, is set by QOpenGLWidget.
    Q_UNUSED(width);
    Q_UNUSED(height);
    camera_.setViewportSize(this->width(), this->height());
    // A project opens before the window has its final size; until the artist moves the camera,
    // the framing follows the size.
    if (cameraIsFramed_)
        frameScene();
}

Viewport::GpuMesh& Viewport::gpuMesh(const model::SceneObject& object)
{
    const model::Mesh& mesh = meshOf(object);
    const auto found = gpuMeshes_.find(&mesh);
    if (found != gpuMeshes_.end())
        return found->second;

    GpuMesh& gpu = gpuMeshes_[&mesh];
    gpu.owner = object.mesh;
    // Interleaved position and normal. A mesh without normals gets each vertex's area-weighted mean
    // of its triangles' normals (the cross product's length is twice the area).
    std::vector<Eigen::Vector3f> normals = mesh.normals;
    if (normals.size() != mesh.positions.size()) {
        normals.assign(mesh.positions.size(), Eigen::Vector3f::Zero());
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const Eigen::Vector3f& a = mesh.positions[mesh.indices[i]];
            const Eigen::Vector3f normal = (mesh.positions[mesh.indices[i + 1]] - a).cross(mesh.positions[mesh.indices[i + 2]] - a);
            for (std::size_t k = 0; k < 3; ++k)
                normals[mesh.indices[i + k]] += normal;
        }
        for (Eigen::Vector3f& normal : normals)
            normal.normalize();
    }
    std::vector<float> interleaved;
    interleaved.reserve(mesh.positions.size() * 6);
    gpu.radius = 0.0F;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        interleaved.insert(interleaved.end(), mesh.positions[i].data(), mesh.positions[i].data() + 3);
        interleaved.insert(interleaved.end(), normals[i].data(), normals[i].data() + 3);
        gpu.radius = std::max(gpu.radius, mesh.positions[i].norm());
    }
    gpu.vertexArray = std::make_unique<QOpenGLVertexArrayObject>();
    gpu.vertexArray->create();
    gpu.vertexArray->bind();
    gpu.vertices.create();
    gpu.vertices.bind();
    gpu.vertices.allocate(interleaved.data(), static_cast<int>(interleaved.size() * sizeof(float)));
    constexpr int kStride = 6 * sizeof(float);
    glEnableVertexAttribArray(kPositionAttribute);
    glVertexAttribPointer(kPositionAttribute, 3, GL_FLOAT, GL_FALSE, kStride, nullptr);
    glEnableVertexAttribArray(kNormalAttribute);
    glVertexAttribPointer(kNormalAttribute, 3, GL_FLOAT, GL_FALSE, kStride, reinterpret_cast<const void*>(3 * sizeof(float)));
    for (GLuint column = 0; column < 4; ++column) {
        glEnableVertexAttribArray(kInstanceAttribute + column);
        glVertexAttribDivisor(kInstanceAttribute + column, 1);
    }
    gpu.indices.create();
    gpu.indices.bind();
    gpu.indices.allocate(mesh.indices.data(), static_cast<int>(mesh.indices.size() * sizeof(std::uint32_t)));
    gpu.indexCount = static_cast<int>(mesh.indices.size());
    gpu.frontFace = cullableFrontFace(mesh);
    gpu.vertexArray->release();
    gpu.vertices.release();
    gpu.indices.release();
    return gpu;
}

void Viewport::dropUnusedMeshes()
{
    // A mesh only the cache still holds belongs to no object any more.
    std::erase_if(gpuMeshes_, [](const auto& entry) { return entry.second.owner && entry.second.owner.use_count() == 1; });
    meshesMayBeUnused_ = false;
}

void Viewport::drawMesh(GpuMesh& mesh, QOpenGLBuffer& instances, int instanceCount)
{
    mesh.vertexArray->bind();
    instances.bind();
    for (GLuint column = 0; column < 4; ++column)
        glVertexAttribPointer(kInstanceAttribute + column, 4, GL_FLOAT, GL_FALSE, kFloatsPerMatrix * sizeof(float),
                              reinterpret_cast<const void*>(column * 4 * sizeof(float)));
    meshProgram_->setUniformValue("uInstanceCount", instanceCount);
    if (mesh.frontFace) {
        glEnable(GL_CULL_FACE);
        glFrontFace(*mesh.frontFace);
    }
    glDrawElementsInstanced(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr, instanceCount);
    glDisable(GL_CULL_FACE);
    instances.release();
    mesh.vertexArray->release();
}

void Viewport::rebuildTrajectory()
{
    trajectoryVertices_.clear();
    trajectoryStale_ = false;
    const model::SceneObject* object = selection_.selectedObject();
    const model::Scene& scene = document_.scene();
    if (object == nullptr || !(scene.endTime > scene.startTime))
        return;
    const Eigen::Vector3d centre = meshCentre(meshOf(*object));
    // One sample per frame of the scene, fewer for very long scenes.
    const double frames = std::ceil((scene.endTime - scene.startTime) * scene.fps);
    const int samples = static_cast<int>(std::clamp(frames, 1.0, double(kMaxTrajectorySamples))) + 1;
    const SceneMotion& sceneMotion = motion();
    for (int i = 0; i < samples; ++i) {
        const double time = scene.startTime + (scene.endTime - scene.startTime) * i / (samples - 1);
        const Eigen::Vector3f point = sceneMotion.worldPose(object->id, time).apply(centre).cast<float>();
        trajectoryVertices_.push_back({{point.x(), point.y(), point.z()}, {kTrajectoryColor.r, kTrajectoryColor.g, kTrajectoryColor.b, kTrajectoryColor.a}});
    }
}

void Viewport::buildLines()
{
    lineVertices_.clear();
    const auto add = [this](const Eigen::Vector3d& point, const Rgba& color) {
        lineVertices_.push_back({{float(point.x()), float(point.y()), float(point.z())}, {color.r, color.g, color.b, color.a}});
    };
    const auto rangeFrom = [this](int first) { return LineRange{first, static_cast<int>(lineVertices_.size()) - first}; };

    int first = 0;
    for (int i = -kGridHalfLines; i <= kGridHalfLines; ++i) {
        // The x axis red and the y axis green, on the ground plane z = 0.
        const double across = i;
        const double extent = kGridHalfLines;
        add(Eigen::Vector3d(across, -extent, 0.0), i == 0 ? kAxisColors[1] : kGridColor);
        add(Eigen::Vector3d(across, extent, 0.0), i == 0 ? kAxisColors[1] : kGridColor);
        add(Eigen::Vector3d(-extent, across, 0.0), i == 0 ? kAxisColors[0] : kGridColor);
        add(Eigen::Vector3d(extent, across, 0.0), i == 0 ? kAxisColors[0] : kGridColor);
    }
    gridLines_ = rangeFrom(first);

    first = static_cast<int>(lineVertices_.size());
    if (showTrajectory_) {
        if (trajectoryStale_)
            rebuildTrajectory();
        lineVertices_.insert(lineVertices_.end(), trajectoryVertices_.begin(), trajectoryVertices_.end());
    }
    trajectoryStrip_ = rangeFrom(first);

    first = static_cast<int>(lineVertices_.size());
    const model::SceneObject* selected = selection_.selectedObject();
    if (showControlPoses_ && isScrewBenderTrack(selected)) {
        const auto found = gpuMeshes_.find(&meshOf(*selected));
        const double axisLength = kControlPoseScale * (found != gpuMeshes_.end() ? double(found->second.radius) : 1.0);
        const Pose frame = motion().parentWorldPose(selected->id, document_.scene().currentTime);
        for (const model::Keyframe& key : selected->track.keys) {
            const Pose pose = frame * key.pose;
            for (int axis = 0; axis < 3; ++axis) {
                add(pose.position, kAxisColors[axis]);
                add(pose.apply(axisLength * Eigen::Vector3d::Unit(axis)), kAxisColors[axis]);
            }
        }
    }
    axisLines_ = rangeFrom(first);

    first = static_cast<int>(lineVertices_.size());
    const std::optional<HandleFrame> handles = handleFrame();
    if (handles) {
        for (int axis = 0; axis < 3; ++axis) {
            add(handles->centre, kAxisColors[axis]);
            add(handles->centre + handles->length * handles->axes.col(axis), kAxisColors[axis]);
            for (int segment = 0; segment < kRingSegments; ++segment) {
                add(ringPoint(*handles, axis, 2 * std::numbers::pi * segment / kRingSegments), kAxisColors[axis]);
                add(ringPoint(*handles, axis, 2 * std::numbers::pi * (segment + 1) / kRingSegments), kAxisColors[axis]);
            }
        }
    }
    handleLines_ = rangeFrom(first);

    first = static_cast<int>(lineVertices_.size());
    if (handles) {
        for (int axis = 0; axis < 3; ++axis)
            add(handles->centre + handles->length * handles->axes.col(axis), kAxisColors[axis]);
    }
    handlePoints_ = rangeFrom(first);

    lineBuffer_.bind();
    lineBuffer_.allocate(lineVertices_.data(), static_cast<int>(lineVertices_.size() * sizeof(LineVertex)));
    lineBuffer_.release();
}

void Viewport::drawLines(GLenum mode, LineRange range)
{
    if (range.count > 0)
        glDrawArrays(mode, range.first, range.count);
}

void Viewport::uploadControlPoses(const model::SceneObject& object)
{
    controlPoseMatrices_.clear();
    for (const model::Keyframe& key : object.track.keys)
        appendMatrix(controlPoseMatrices_, key.pose, kControlPoseScale);
    controlPoseInstances_.bind();
    controlPoseInstances_.allocate(controlPoseMatrices_.data(), static_cast<int>(controlPoseMatrices_.size() * sizeof(float)));
    controlPoseInstances_.release();
}

void Viewport::measureFrame()
{
    ++framesDrawn_;
    if (!frameClock_.isValid()) {
        frameClock_.start();
        return;
    }
    const qint64 interval = frameClock_.nsecsElapsed();
    frameClock_.restart();
    if (interval > kIdleFrameGap)
        return;
    measuredNanoseconds_ += interval;
    ++measuredFrames_;
    if (measuredNanoseconds_ < kStatsWindow)
        return;
    emit frameStatsChanged(measuredFrames_ * 1e9 / double(measuredNanoseconds_), subdivisionMilliseconds_,
                           subdivisionLatencyMilliseconds_);
    measuredNanoseconds_ = 0;
    measuredFrames_ = 0;
}

void Viewport::paintGL()
{
    measureFrame();
    glClearColor(kBackground.r, kBackground.g, kBackground.b, kBackground.a);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!meshProgram_->isLinked() || !lineProgram_->isLinked())
        return;
    if (meshesMayBeUnused_)
        dropUnusedMeshes();

    const model::Scene& scene = document_.scene();
    const SceneMotion& sceneMotion = motion();
    const QMatrix4x4 viewProjection = toQMatrix(camera_.viewProjectionMatrix());
    const Eigen::Vector3f eye = camera_.eye().cast<float>();
    const model::SceneObject* selected = selection_.selectedObject();
    if (selected != nullptr)
        gpuMesh(*selected); // its radius sizes the control poses' axes
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);

    lineProgram_->bind();
    lineProgram_->setUniformValue("uViewProjection", viewProjection);
    lineProgram_->setUniformValue("uPointSize", kHandlePointSize);
    buildLines();
    lineArray_->bind();
    drawLines(GL_LINES, gridLines_);
    drawLines(GL_LINE_STRIP, trajectoryStrip_);
    drawLines(GL_LINES, axisLines_);
    lineArray_->release();

    meshProgram_->bind();
    meshProgram_->setUniformValue("uViewProjection", viewProjection);
    meshProgram_->setUniformValue("uEye", QVector3D(eye.x(), eye.y(), eye.z()));
    meshProgram_->setUniformValue("uHighlightInstance", -1);
    const auto setColors = [this](const Rgba& start, const Rgba& end) {
        meshProgram_->setUniformValue("uColor", toVector(start));
        meshProgram_->setUniformValue("uColorEnd", toVector(end));
    };

    Pose selectedPose;
    for (const model::SceneObject& object : scene.objects) {
        const Pose pose = sceneMotion.worldPose(object.id, scene.currentTime);
        if (&object == selected)
            selectedPose = pose;
        const Rgba& color = &object == selected ? kSelectedColor : kObjectColor;
        setColors(color, color);
        meshProgram_->setUniformValue("uFrame", toQMatrix(poseMatrix(pose)));
        drawMesh(gpuMesh(object), identityInstance_, 1);
    }

    drawnTrailInstances_ = 0;
    if (trailUploadPending_) {
        trailInstances_.bind();
        trailInstances_.allocate(trailMatrices_.data(), static_cast<int>(trailMatrices_.size() * sizeof(float)));
        trailInstances_.release();
        trailUploadPending_ = false;
    }
    const QMatrix4x4 selectedFrame = selected != nullptr
        ? toQMatrix(poseMatrix(sceneMotion.parentWorldPose(selected->id, scene.currentTime)))
        : QMatrix4x4();
    // Translucent last, over everything opaque, without hiding each other. The trail too: a few
    // hundred instances opaque would hide the object, its trajectory and its control poses.
    glEnable(GL_BLEND);
    glDepthMask(GL_FALSE);
    if (showTrail_ && selected != nullptr && trailPoseCount_ > 0) {
        // Behind the object itself, which stands on the trail and would otherwise fight it for depth.
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.0F, 1.0F);
        setColors(kTrailStart, kTrailEnd);
        meshProgram_->setUniformValue("uFrame", selectedFrame);
        drawMesh(gpuMesh(*selected), trailInstances_, static_cast<int>(trailPoseCount_));
        glDisable(GL_POLYGON_OFFSET_FILL);
        drawnTrailInstances_ = trailPoseCount_;
    }
    if (showControlPoses_ && isScrewBenderTrack(selected)) {
        uploadControlPoses(*selected);
        setColors(kControlPoseColor, kControlPoseColor);
        meshProgram_->setUniformValue("uHighlightInstance", selection_.key() ? static_cast<int>(*selection_.key()) : -1);
        meshProgram_->setUniformValue("uHighlightColor", toVector(kSelectedKeyColor));
        meshProgram_->setUniformValue("uFrame", selectedFrame);
        drawMesh(gpuMesh(*selected), controlPoseInstances_, static_cast<int>(selected->track.keys.size()));
        meshProgram_->setUniformValue("uHighlightInstance", -1);
    }
    drewGhost_ = false;
    if (showGhost_ && selected != nullptr && model::findObject(originalScene_, selected->id) != nullptr) {
        const Pose original = originalMotion_.worldPose(selected->id, scene.currentTime);
        if (!samePose(original, selectedPose)) {
            setColors(kGhostColor, kGhostColor);
            meshProgram_->setUniformValue("uFrame", toQMatrix(poseMatrix(original)));
            drawMesh(gpuMesh(*selected), identityInstance_, 1);
            drewGhost_ = true;
        }
    }
    glDepthMask(GL_TRUE);

    // The handles on top of everything, so that they can always be grabbed.
    glDisable(GL_DEPTH_TEST);
    lineProgram_->bind();
    lineArray_->bind();
    drawLines(GL_LINES, handleLines_);
    drawLines(GL_POINTS, handlePoints_);
    lineArray_->release();
    glDisable(GL_BLEND);
}

} // namespace gyre::app
