#include "app/viewport/viewport.h"

#include "app/viewport/body_overlay.h"
#include "app/viewport/default_shape.h"
#include "app/viewport/picking.h"
#include "core/quaternion_math.h"
#include "model/object_mass.h"
#include "model/scene_queries.h"
#include "model/skinning.h"
#include "model/track_evaluation.h"

#include <QMouseEvent>
#include <QOpenGLContext>
#include <QResizeEvent>
#include <QWheelEvent>

#include <Eigen/Geometry>

#include <algorithm>
#include <list>
#include <numbers>
#include <vector>

namespace gyre::app {

namespace {

constexpr double kClickPixels = 3.0;      // a press that moves less is a click
constexpr int kGridHalfLines = 10;        // a 20 × 20 grid of unit squares about the origin
constexpr double kGhostTolerance = 1e-6;  // the ghost is drawn where the motions differ by more
constexpr qint64 kIdleFrameGap = 1'000'000'000; // ns: a longer gap between frames is idling, not drawing
constexpr qint64 kStatsWindow = 500'000'000;  // ns of drawing per frameStatsChanged

constexpr Rgba kGridColor{0.32F, 0.33F, 0.36F, 1.0F};
constexpr Rgba kTrajectoryColor{1.0F, 0.9F, 0.35F, 1.0F};
constexpr Rgba kEmptyColor{0.85F, 0.86F, 0.88F, 1.0F};

bool samePose(const Pose& a, const Pose& b)
{
    return a.orientation.angularDistance(b.orientation) <= kGhostTolerance
           && (a.position - b.position).norm() <= kGhostTolerance * std::max(1.0, a.position.norm());
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
    : OffscreenGlWidget(surfaceFormat(), parent)
    , document_(document)
    , selection_(selection)
    , drawn_(document, selection)
    , handleDrag_(document)
{
    setMinimumSize(200, 150);
    setFocusPolicy(Qt::ClickFocus);

    connect(&drawn_, &DrawnMotion::changed, this, [this] { update(); });
    connect(&drawn_, &DrawnMotion::sceneReset, this, &Viewport::frameScene);
    connect(&drawn_, &DrawnMotion::failed, this, &Viewport::drawingFailed);
    // An object gone, or given another mesh, may leave a mesh that no object holds.
    connect(&document_, &model::Document::changed, this, [this](model::ObjectId, model::Changes changes) {
        using model::Change;
        if (changes & (Change::Added | Change::Removed | Change::Object | Change::Scene))
            renderer_.dropUnusedMeshesNextFrame();
    });
    connect(&document_, &model::Document::currentTimeChanged, this, [this] { update(); });
}

Viewport::~Viewport()
{
    // The renderer's buffers live in the context, which OffscreenGlWidget destroys after this.
    if (renderer_.isInitialized() && makeCurrent()) {
        renderer_.release();
        doneCurrent();
    }
}

void Viewport::setPreviewTrack(model::ObjectId object, std::optional<model::MotionTrack> track)
{
    drawn_.setPreviewTrack(object, std::move(track));
}

void Viewport::setShowGhost(bool show)
{
    showGhost_ = show;
    update();
}

void Viewport::setShowAngularMomentum(bool show)
{
    showAngularMomentum_ = show;
    update();
}

void Viewport::setShowPrincipalAxes(bool show)
{
    showPrincipalAxes_ = show;
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

void Viewport::setTrailSpacing(const TrailSpacing& spacing)
{
    drawn_.setTrailSpacing(spacing);
}

void Viewport::updateSkeleton()
{
    const model::Scene& scene = document_.scene();
    skeleton_.update(scene, drawn_.motion(), scene.currentTime);
}

Eigen::AlignedBox3d Viewport::objectBox(std::size_t index) const
{
    const model::Scene& scene = document_.scene();
    const model::SceneObject& object = scene.objects[index];
    Eigen::AlignedBox3d box;
    if (skeleton_.isJoint(index)) {
        for (const Bone& bone : skeleton_.bones())
            if (bone.joint == object.id)
                box.extend(bone.head()).extend(bone.tail());
        box.extend(drawn_.motion().worldPose(object.id, scene.currentTime).position);
        return box;
    }
    const Pose pose = drawn_.motion().worldPose(object.id, scene.currentTime);
    for (const Eigen::Vector3f& position : displayMesh(object).positions)
        box.extend(pose.apply(position.cast<double>()));
    return box;
}

void Viewport::frameBox(Eigen::AlignedBox3d box)
{
    if (box.isEmpty())
        box = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-kGridHalfLines / 2.0), Eigen::Vector3d::Constant(kGridHalfLines / 2.0));
    camera_.frame(box.min(), box.max());
    update();
}

void Viewport::frameScene()
{
    const model::Scene& scene = document_.scene();
    const model::SceneMotion& motion = drawn_.motion();
    updateSkeleton();
    Eigen::AlignedBox3d box;
    // As Blender's View All: what is hidden is not framed.
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].visible)
            box.extend(objectBox(i));
    if (const model::SceneObject* selected = selection_.selectedObject()) {
        const Pose frame = motion.parentWorldPose(selected->id, scene.currentTime);
        for (const model::Keyframe& key : selected->track.keys)
            box.extend(frame.apply(key.pose.position));
    }
    for (const std::vector<Eigen::Vector3f>& path : drawn_.trajectories())
        for (const Eigen::Vector3f& point : path)
            box.extend(point.cast<double>());
    frameBox(box);
    cameraIsFramed_ = true;
}

void Viewport::frameSceneWhenDrawn()
{
    framePending_ = true;
    update();
}

void Viewport::frameSelected()
{
    const model::Scene& scene = document_.scene();
    const auto selected = std::find_if(scene.objects.begin(), scene.objects.end(),
                                       [this](const model::SceneObject& object) { return object.id == selection_.object(); });
    if (selected == scene.objects.end()) {
        frameScene();
        return;
    }
    updateSkeleton();
    frameBox(objectBox(static_cast<std::size_t>(selected - scene.objects.begin())));
    cameraIsFramed_ = false;
}

void Viewport::viewFrom(ViewPoint point)
{
    // (yaw, pitch) of the direction from the target towards the eye.
    constexpr double kQuarter = std::numbers::pi / 2;
    switch (point) {
    case ViewPoint::Front:
        camera_.lookFrom(-kQuarter, 0.0);
        break;
    case ViewPoint::Back:
        camera_.lookFrom(kQuarter, 0.0);
        break;
    case ViewPoint::Right:
        camera_.lookFrom(0.0, 0.0);
        break;
    case ViewPoint::Left:
        camera_.lookFrom(std::numbers::pi, 0.0);
        break;
    case ViewPoint::Top:
        camera_.lookFrom(-kQuarter, kQuarter);
        break;
    case ViewPoint::Bottom:
        camera_.lookFrom(-kQuarter, -kQuarter);
        break;
    }
    update();
}

void Viewport::setOrthographic(bool orthographic)
{
    camera_.setOrthographic(orthographic);
    update();
}

void Viewport::setUpAxis(UpAxis up)
{
    camera_.setUpAxis(up);
    update();
}

void Viewport::setShading(Shading shading)
{
    shading_ = shading;
    update();
}

// --- Geometry --------------------------------------------------------------------------------------

bool Viewport::showsControlPoses() const
{
    return showControlPoses_ && DrawnMotion::isScrewBenderTrack(selection_.selectedObject());
}

std::optional<HandleFrame> Viewport::handleFrame() const
{
    const model::Keyframe* key = selection_.selectedKey();
    if (key == nullptr)
        return std::nullopt;
    const Pose frame = drawn_.motion().parentWorldPose(selection_.object(), document_.scene().currentTime);
    return HandleFrame::place(frame, key->pose.position, camera_);
}

std::optional<QPointF> Viewport::handleScreenPosition(Handle handle) const
{
    const std::optional<HandleFrame> handles = handleFrame();
    if (!handles)
        return std::nullopt;
    return handles->pressPoint(handle, camera_);
}

std::optional<QPointF> Viewport::controlPoseScreenPosition(std::size_t key) const
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr || key >= object->track.keys.size())
        return std::nullopt;
    const Pose frame = drawn_.motion().parentWorldPose(object->id, document_.scene().currentTime);
    return toScreen(camera_, frame.apply(object->track.keys[key].pose.position));
}

std::optional<QPointF> Viewport::objectScreenPosition(model::ObjectId id) const
{
    if (document_.object(id) == nullptr)
        return std::nullopt;
    return toScreen(camera_, drawn_.motion().worldPose(id, document_.scene().currentTime).position);
}

void Viewport::pickAt(const QPointF& position, bool toggle)
{
    const Ray ray = camera_.ray(position.x(), position.y());
    const model::Scene& scene = document_.scene();
    const model::SceneMotion& motion = drawn_.motion();
    std::vector<MeshPlacement> placements;
    std::vector<model::ObjectId> objects;
    std::vector<std::optional<std::size_t>> keys;
    // A skinned mesh is tested where it is drawn, its positions skinned on the CPU as the shader does.
    std::list<std::vector<Eigen::Vector3f>> skinned; // a list: the placements point into it
    updateSkeleton();
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const model::SceneObject& object = scene.objects[i];
        if (skeleton_.isJoint(i) || !object.visible)
            continue;
        const std::vector<Eigen::Vector3f>* positions = nullptr;
        if (object.mesh && !object.mesh->skin.empty())
            positions = &skinned.emplace_back(model::skinnedPositions(
                *object.mesh, model::jointMatrices(object.mesh->skin, object.id, motion, scene.currentTime)));
        placements.push_back({&displayMesh(object), motion.worldPose(object.id, scene.currentTime), 1.0, positions});
        objects.push_back(object.id);
        keys.emplace_back();
    }
    for (const Bone& bone : skeleton_.bones()) {
        placements.push_back({&boneMesh(), bone.pose, bone.length});
        objects.push_back(bone.joint);
        keys.emplace_back();
    }
    if (showsControlPoses()) {
        const model::SceneObject* selected = selection_.selectedObject();
        const Pose frame = motion.parentWorldPose(selected->id, scene.currentTime);
        for (std::size_t key = 0; key < selected->track.keys.size(); ++key) {
            placements.push_back({&displayMesh(*selected), frame * selected->track.keys[key].pose, SceneRenderer::kControlPoseScale});
            objects.push_back(selected->id);
            keys.emplace_back(key);
        }
    }
    const std::optional<std::size_t> hit = nearestHit(ray, placements);
    if (toggle) {
        if (hit && !keys[*hit])
            selection_.toggleObject(objects[*hit]);
    } else if (!hit)
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
        const std::optional<HandleFrame> handles = handleFrame();
        const std::optional<Handle> handle = handles ? handles->handleAt(position, camera_) : std::nullopt;
        const bool grabbed = handle && handleDrag_.start(*handle, *handles, selection_.object(), *selection_.key(), position, camera_);
        drag_.kind = grabbed ? DragKind::Handle : DragKind::Orbit;
    }
    setDragging(drag_.kind != DragKind::None);
    event->accept();
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
        handleDrag_.moveTo(position, camera_);
        if (!handleDrag_.isActive())
            drag_.kind = DragKind::None; // the key went mid-drag
        break;
    case DragKind::None:
        break;
    }
    drag_.lastPosition = position;
    event->accept();
}

void Viewport::mouseReleaseEvent(QMouseEvent* event)
{
    if (drag_.kind == DragKind::Orbit && !drag_.moved && event->button() == Qt::LeftButton)
        pickAt(event->position(), event->modifiers().testFlag(Qt::ControlModifier));
    handleDrag_.finish(); // ends the drag's undo step
    drag_.kind = DragKind::None;
    setDragging(false);
    event->accept();
}

void Viewport::setDragging(bool dragging)
{
    if (dragging == dragging_)
        return;
    dragging_ = dragging;
    emit draggingChanged(dragging_);
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
    renderer_.initialize();
}

void Viewport::resizeEvent(QResizeEvent* event)
{
    // The camera works in widget pixels, as mouse events give them, and follows the size at once, not
    // at the next frame: a click may come first. OpenGL's viewport, in device pixels, is set by
    // OffscreenGlWidget.
    camera_.setViewportSize(width(), height());
    // A project opens before the window has its final size; until the artist moves the camera,
    // the framing follows the size.
    if (cameraIsFramed_)
        frameScene();
    OffscreenGlWidget::resizeEvent(event);
}

void Viewport::buildLines()
{
    std::vector<LineVertex>& vertices = lines_.vertices;
    vertices.clear();
    const auto rangeFrom = [&vertices](std::size_t first) {
        return LineRange{static_cast<int>(first), static_cast<int>(vertices.size() - first)};
    };

    // On the view's ground plane (z = 0 Z-up, y = 0 Y-up), each axis in its colour: x red, y green, z blue.
    const Eigen::Matrix3d ground = camera_.viewFrame();
    const Rgba& acrossColor = kAxisColors[camera_.upAxis() == UpAxis::Y ? 2 : 1];
    for (int i = -kGridHalfLines; i <= kGridHalfLines; ++i) {
        const double across = i;
        const double extent = kGridHalfLines;
        vertices.push_back(lineVertex(ground * Eigen::Vector3d(across, -extent, 0.0), i == 0 ? acrossColor : kGridColor));
        vertices.push_back(lineVertex(ground * Eigen::Vector3d(across, extent, 0.0), i == 0 ? acrossColor : kGridColor));
        vertices.push_back(lineVertex(ground * Eigen::Vector3d(-extent, across, 0.0), i == 0 ? kAxisColors[0] : kGridColor));
        vertices.push_back(lineVertex(ground * Eigen::Vector3d(extent, across, 0.0), i == 0 ? kAxisColors[0] : kGridColor));
    }
    lines_.grid = rangeFrom(0);

    // The selected objects' paths, uploaded when they change (paintGL).
    lines_.drawPaths = showTrajectory_;

    std::size_t first = vertices.size();
    // Each empty as Blender's plain axes: three lines through its origin.
    const model::Scene& scene = document_.scene();
    for (const model::SceneObject& object : scene.objects) {
        if (!object.empty || !object.visible)
            continue;
        const Pose pose = drawn_.motion().worldPose(object.id, scene.currentTime);
        const Rgba& color = &object == selection_.selectedObject() ? kSelectedColor : kEmptyColor;
        for (int axis = 0; axis < 3; ++axis) {
            vertices.push_back(lineVertex(pose.apply(-kEmptyAxisLength * Eigen::Vector3d::Unit(axis)), color));
            vertices.push_back(lineVertex(pose.apply(kEmptyAxisLength * Eigen::Vector3d::Unit(axis)), color));
        }
    }
    if (showsControlPoses()) {
        const model::SceneObject& selected = *selection_.selectedObject();
        const double axisLength = SceneRenderer::kControlPoseScale * double(renderer_.meshRadius(selected));
        const Pose frame = drawn_.motion().parentWorldPose(selected.id, document_.scene().currentTime);
        for (const model::Keyframe& key : selected.track.keys) {
            const Pose pose = frame * key.pose;
            for (int axis = 0; axis < 3; ++axis) {
                vertices.push_back(lineVertex(pose.position, kAxisColors[axis]));
                vertices.push_back(lineVertex(pose.apply(axisLength * Eigen::Vector3d::Unit(axis)), kAxisColors[axis]));
            }
        }
    }
    lines_.axes = rangeFrom(first);

    const std::optional<HandleFrame> handles = handleFrame();
    first = vertices.size();
    if (handles)
        handles->appendLines(vertices);
    lines_.handles = rangeFrom(first);
    first = vertices.size();
    if (handles)
        handles->appendTips(vertices);
    lines_.handlePoints = rangeFrom(first);

    first = vertices.size();
    const model::SceneObject* selected = selection_.selectedObject();
    if (selected && (showAngularMomentum_ || showPrincipalAxes_)) {
        const MassProperties mass = model::objectMassProperties(*selected).properties;
        const double radius = renderer_.meshRadius(*selected);
        const double time = document_.scene().currentTime;
        const Pose pose = drawn_.motion().worldPose(selected->id, time);
        if (showPrincipalAxes_)
            appendPrincipalAxes(vertices, pose, mass, radius);
        if (showAngularMomentum_) {
            // The world angular velocity, parents' turning included: ω ≈ log(q(t+h)·q(t−h)⁻¹)/h.
            const double h = model::kAngularVelocityStep;
            const Eigen::Quaterniond after = drawn_.motion().worldPose(selected->id, time + h).orientation;
            const Eigen::Quaterniond before = drawn_.motion().worldPose(selected->id, time - h).orientation;
            const Eigen::Vector3d velocity = 2.0 * quatLog(after * before.conjugate()) / (2.0 * h);
            appendMomentumArrow(vertices, pose, mass, velocity, radius);
        }
    }
    lines_.physics = rangeFrom(first);
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
    emit frameStatsChanged(measuredFrames_ * 1e9 / double(measuredNanoseconds_), drawn_.subdivisionMilliseconds(),
                           drawn_.subdivisionLatencyMilliseconds());
    measuredNanoseconds_ = 0;
    measuredFrames_ = 0;
}

void Viewport::paintGL()
{
    measureFrame();
    const model::Scene& scene = document_.scene();
    if (framePending_ && std::all_of(scene.objects.begin(), scene.objects.end(),
                                     [this](const model::SceneObject& object) { return drawn_.motion().contains(object.id); })) {
        framePending_ = false;
        frameScene();
        reframeWithPaths_ = drawn_.trajectoriesPending();
    } else if (reframeWithPaths_ && !drawn_.trajectoriesPending()) {
        // The selected objects' paths, sampled on a worker, arrive after the motion: until the artist moves the
        // camera, the framing takes them in too.
        reframeWithPaths_ = false;
        if (cameraIsFramed_)
            frameScene();
    }
    updateSkeleton();
    const model::SceneObject* selected = selection_.selectedObject();
    if (drawn_.takeTrajectoriesChange())
        renderer_.setPaths(drawn_.trajectories(), kTrajectoryColor);
    if (drawn_.takeTrailChange())
        renderer_.setTrail(drawn_.trailMatrices());
    buildLines();

    FrameMeshes meshes;
    meshes.scene = &scene;
    meshes.motion = &drawn_.motion();
    meshes.skeleton = &skeleton_;
    meshes.shading = shading_;
    meshes.selected = selected;
    if (selected != nullptr) {
        meshes.selectedParentFrame = drawn_.motion().parentWorldPose(selected->id, scene.currentTime);
        meshes.controlPoses = showsControlPoses();
        meshes.highlightedKey = selection_.key();
        if (showGhost_) {
            const std::optional<Pose> original = drawn_.originalWorldPose(selected->id, scene.currentTime);
            if (original && !samePose(*original, drawn_.motion().worldPose(selected->id, scene.currentTime)))
                meshes.ghost = original;
        }
    }
    std::size_t trailInstances = 0;
    if (showTrail_)
        for (const DrawnMotion::DrawnTrail& trail : drawn_.trails())
            if (const model::SceneObject* object = model::findObject(scene, trail.object)) {
                const Pose frame = trail.inParentFrame ? drawn_.motion().parentWorldPose(trail.object, scene.currentTime) : Pose{};
                meshes.trails.push_back({object, frame, int(trail.first), int(trail.count)});
                trailInstances += trail.count;
            }
    renderer_.drawFrame(camera_.viewProjectionMatrix(), camera_.eye(), lines_, meshes);
    drawnTrailInstances_ = trailInstances;
    drawnPathPoints_ = 0;
    if (showTrajectory_)
        for (const std::vector<Eigen::Vector3f>& path : drawn_.trajectories())
            drawnPathPoints_ += path.size() >= 2 ? path.size() : 0; // as SceneRenderer::setPaths draws them
    drewGhost_ = meshes.ghost.has_value();
}

} // namespace gyre::app
