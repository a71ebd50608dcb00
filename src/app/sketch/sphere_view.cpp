#include "app/sketch/sphere_view.h"

#include "model/commands/add_stroke_command.h"
#include "model/commands/edit_stroke_command.h"
#include "model/commands/erase_stroke_command.h"

#include <QAction>
#include <QActionGroup>
#include <QEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QRadialGradient>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace gyre::app {

namespace {

const QColor kBackground(41, 43, 48);
const QColor kDiscLight(236, 239, 245, 225);
const QColor kDiscShade(140, 148, 162, 225);
const QColor kRimColor(25, 27, 32);
const QColor kGridColor(96, 104, 118);
const std::array<QColor, 3> kAxisColors{QColor(214, 48, 48), QColor(40, 150, 60), QColor(45, 95, 220)};
const QColor kMotionColor(225, 140, 20);
const QColor kFittedColor(215, 25, 25);
const QColor kBeforeFitColor(100, 100, 110);
const QColor kDrawnStrokeColor(80, 130, 255);
const QColor kTargetStrokeColor(20, 60, 210);
const QColor kCurrentTimeColor(255, 215, 0);
const QColor kTextColor(230, 232, 236);
const QColor kTickColor(110, 60, 0);

constexpr double kBackOpacity = 0.3;      // of the back side's lines, seen through the disc
constexpr int kCircleSegments = 96;
constexpr double kMajorTickPixels = 6.0;
constexpr double kMinorTickPixels = 3.0;
constexpr double kTickLabelPixels = 14.0;
constexpr double kMinorTickSeconds = 0.25;
constexpr double kLongestMinorTickedRange = 30.0; // seconds: beyond, quarter-second ticks would crowd
constexpr int kMostTimeLabels = 8;
constexpr double kTangentSeconds = 0.01;  // half the span over which a tick's direction is measured
constexpr double kCurrentTimeRadius = 5.0;

QPen faded(QPen pen, double opacity)
{
    QColor color = pen.color();
    color.setAlphaF(static_cast<float>(static_cast<double>(color.alphaF()) * opacity));
    pen.setColor(color);
    return pen;
}

// The current-time dot at `opacity`, centred in a transparent image with room for its rim's pen and
// the antialiasing around it.
QImage currentTimeDot(double opacity, qreal pixelRatio)
{
    const double half = kCurrentTimeRadius + 2.0;
    QImage dot((QSizeF(2.0 * half, 2.0 * half) * pixelRatio).toSize(), QImage::Format_ARGB32_Premultiplied);
    dot.setDevicePixelRatio(pixelRatio);
    dot.fill(Qt::transparent);
    QPainter painter(&dot);
    painter.setRenderHint(QPainter::Antialiasing);
    QColor fill = kCurrentTimeColor;
    fill.setAlphaF(static_cast<float>(opacity));
    painter.setBrush(fill);
    painter.setPen(faded(QPen(kRimColor, 1.5), opacity));
    painter.drawEllipse(QPointF(half, half), kCurrentTimeRadius, kCurrentTimeRadius);
    return dot;
}

// Circles of latitude every 30° about the world z axis, and meridians every 30°.
const std::vector<std::vector<Eigen::Vector3d>>& gridCircles()
{
    static const std::vector<std::vector<Eigen::Vector3d>> circles = [] {
        std::vector<std::vector<Eigen::Vector3d>> result;
        auto circle = [](auto pointAt) {
            std::vector<Eigen::Vector3d> points;
            for (int i = 0; i <= kCircleSegments; ++i)
                points.push_back(pointAt(2.0 * std::numbers::pi * i / kCircleSegments));
            return points;
        };
        for (int degrees = -60; degrees <= 60; degrees += 30) {
            const double latitude = degrees * std::numbers::pi / 180.0;
            result.push_back(circle([latitude](double angle) {
                return Eigen::Vector3d(std::cos(latitude) * std::cos(angle), std::cos(latitude) * std::sin(angle),
                                       std::sin(latitude));
            }));
        }
        for (int degrees = 0; degrees < 180; degrees += 30) {
            const double longitude = degrees * std::numbers::pi / 180.0;
            result.push_back(circle([longitude](double angle) {
                return Eigen::Vector3d(std::cos(longitude) * std::cos(angle), std::sin(longitude) * std::cos(angle),
                                       std::sin(angle));
            }));
        }
        return result;
    }();
    return circles;
}

// The whole seconds between time labels: 1, 2 or 5 times a power of ten, so that at most
// kMostTimeLabels fit the range.
double timeLabelStep(double rangeSeconds)
{
    for (double scale = 1.0;; scale *= 10.0)
        for (double step : {1.0, 2.0, 5.0})
            if (rangeSeconds / (step * scale) <= kMostTimeLabels)
                return step * scale;
}

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

std::vector<Eigen::Vector3d> directionsOf(const std::vector<fit::TimedVector>& samples)
{
    std::vector<Eigen::Vector3d> points;
    points.reserve(samples.size());
    for (const fit::TimedVector& sample : samples)
        points.push_back(sample.value);
    return points;
}

} // namespace

SphereView::SphereView(model::Document& document, Selection& selection, QWidget* parent)
    : QWidget(parent)
    , document_(document)
    , selection_(selection)
    , selectedTrack_(document, selection)
    , toolGroup_(new QActionGroup(this))
    , sampler_(
          *this, selection, document,
          [](const std::shared_ptr<const model::SharedTrackMotion>& motion, const model::Scene& scene) {
              return [motion, start = scene.startTime, end = scene.endTime] {
                  return sphereCurves(*motion, start, end);
              };
          },
          [this](const SphereCurves& curves) { showCurves(curves); })
{
    setFocusPolicy(Qt::StrongFocus);
    // The back layer, filled with the background, covers the view: Qt need not clear it first.
    setAttribute(Qt::WA_OpaquePaintEvent);
    setCursor(Qt::CrossCursor);
    createActions();

    // Selecting another key of the same object leaves the view as it is (SelectedTrack).
    connect(&selectedTrack_, &SelectedTrack::changed, this, [this](model::Changes changes) {
        using model::Change;
        if (changes & (SelectedTrack::kAnotherObject | Change::Scene)) {
            endDrag();
            forgetCurves();
            sampler_.schedule();
            return;
        }
        // At once: the strokes as drawn (the patterned ones and a new fit follow with the curves),
        // the time ticks (the curves over the new range follow), the message naming the object.
        if (changes & (Change::Sketch | Change::SceneSettings | Change::Object))
            invalidateLayers();
        if (changes & (model::kMotionChanges | Change::SceneSettings))
            sampler_.schedule();
    });
    // Only the dot moves: update() repaints the cached layers, and does nothing while the view is hidden.
    connect(&document_, &model::Document::currentTimeChanged, this, [this] { update(); });
    sampler_.schedule();
}

SphereView::~SphereView() = default;

void SphereView::createActions()
{
    auto makeTool = [this](const QString& text, Qt::Key key, const QString& toolTip, Tool tool) {
        auto* action = new QAction(text, this);
        action->setCheckable(true);
        action->setShortcut(key);
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        action->setToolTip(QStringLiteral("%1 (%2)").arg(toolTip, QKeySequence(key).toString(QKeySequence::NativeText)));
        toolGroup_->addAction(action);
        addAction(action);
        connect(action, &QAction::triggered, this, [this, tool] { setTool(tool); });
        return action;
    };
    drawAction_ = makeTool(tr("Draw"), Qt::Key_D,
                           tr("Draw the direction of the angular velocity on the front of the sphere"), Tool::Draw);
    eraseAction_ = makeTool(tr("Erase"), Qt::Key_E, tr("Erase the strokes' points under the pointer"), Tool::Erase);
    patternAction_ = makeTool(tr("Pattern"), Qt::Key_P,
                              tr("Draw a pattern to repeat along the strokes, on the pad"), Tool::Pattern);
    drawAction_->setChecked(true);

    resetViewAction_ = new QAction(tr("Reset View"), this);
    resetViewAction_->setShortcut(Qt::Key_R); // Home frames the 3D view, window-wide
    resetViewAction_->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    resetViewAction_->setToolTip(tr("Turn the sphere back to its first view, z up (R)"));
    addAction(resetViewAction_);
    connect(resetViewAction_, &QAction::triggered, this, [this] {
        projection_.setRotation(SphereProjection::defaultRotation());
        invalidateLayers();
    });
}

void SphereView::setTool(Tool tool)
{
    if (tool == tool_)
        return;
    endDrag();
    tool_ = tool;
    const std::array actions{drawAction_, eraseAction_, patternAction_};
    actions[static_cast<std::size_t>(tool)]->setChecked(true);
    setCursor(tool == Tool::Pattern ? Qt::OpenHandCursor : Qt::CrossCursor);
    emit toolChanged(tool);
}

QPointF SphereView::projectToWidget(const Eigen::Vector3d& direction) const
{
    return projection_.project(direction);
}

double SphereView::sphereRadius() const
{
    return projection_.radius();
}

bool SphereView::facesViewer(const Eigen::Vector3d& direction) const
{
    return projection_.facesViewer(direction);
}

Eigen::Vector3d SphereView::sphereAt(const QPointF& widgetPoint) const
{
    return projection_.cast(widgetPoint);
}

QString SphereView::message() const
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr)
        return tr("Select an object to sketch the direction of its angular velocity.");
    if (curvesShown_ && curves_.motion.empty())
        return tr("%1 does not turn: key it in two orientations to give it an angular velocity to sketch.")
            .arg(object->name);
    return {};
}

// ---------------------------------------------------------------------------------------------
// Curves

void SphereView::forgetCurves()
{
    // Another object's curves are not shown, not even until this one's arrive.
    curves_ = {};
    curvesShown_ = false;
    invalidateLayers();
}

void SphereView::showCurves(SphereCurves curves)
{
    const bool shown = selection_.selectedObject() != nullptr;
    if (shown != curvesShown_ || !sameCurves(curves, curves_)) {
        curves_ = std::move(curves);
        curvesShown_ = shown;
        invalidateLayers();
    }
    emit curvesUpdated();
}

// ---------------------------------------------------------------------------------------------
// Gestures

void SphereView::resizeEvent(QResizeEvent* event)
{
    projection_.setViewportSize(width(), height());
    layersStale_ = true;
    QWidget::resizeEvent(event);
}

void SphereView::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::FontChange || event->type() == QEvent::LanguageChange)
        invalidateLayers();
    QWidget::changeEvent(event);
}

void SphereView::mousePressEvent(QMouseEvent* event)
{
    if (drag_ != DragKind::None)
        return;
    const QPointF position = event->position();
    const bool turns = event->button() == Qt::RightButton || event->button() == Qt::MiddleButton
                       || (event->button() == Qt::LeftButton && tool_ == Tool::Pattern);
    if (turns) {
        projection_.beginTurn(position);
        drag_ = DragKind::Turn;
        setCursor(Qt::ClosedHandCursor);
        return;
    }
    if (event->button() != Qt::LeftButton || selection_.selectedObject() == nullptr)
        return;
    dragObject_ = selection_.object();
    gesture_.emplace(document_);
    if (tool_ == Tool::Draw) {
        drag_ = DragKind::Draw;
        strokePoints_ = {projection_.cast(position)};
        strokeIndex_.reset();
    } else {
        drag_ = DragKind::Erase;
        eraseAt(position);
    }
}

void SphereView::mouseMoveEvent(QMouseEvent* event)
{
    switch (drag_) {
    case DragKind::Turn:
        projection_.turnTo(event->position());
        invalidateLayers();
        break;
    case DragKind::Draw:
        extendStroke(event->position());
        break;
    case DragKind::Erase:
        eraseAt(event->position());
        break;
    case DragKind::None:
        break;
    }
}

void SphereView::mouseReleaseEvent(QMouseEvent* event)
{
    if (drag_ == DragKind::None)
        return;
    if (drag_ == DragKind::Draw)
        extendStroke(event->position());
    endDrag();
}

void SphereView::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Escape && drag_ != DragKind::None) {
        cancelDrag();
        return;
    }
    QWidget::keyPressEvent(event);
}

void SphereView::extendStroke(const QPointF& position)
{
    const model::SceneObject* object = document_.object(dragObject_);
    if (object == nullptr) {
        endDrag();
        return;
    }
    const Eigen::Vector3d point = projection_.cast(position);
    if (angleBetween(strokePoints_.back(), point) < kStrokeStepRadians)
        return;
    strokePoints_.push_back(point);
    model::DirectionStroke stroke{strokePoints_, strokeTimes(strokePoints_, curves_.motion, document_.scene().fps)};
    const std::size_t strokeCount = object->track.sketch.directionStrokes.size();
    if (!strokeIndex_) {
        strokeIndex_ = strokeCount;
        gesture_->push(new model::AddStrokeCommand(document_, dragObject_, std::move(stroke)));
    } else if (*strokeIndex_ < strokeCount) {
        gesture_->push(new model::EditStrokeCommand(document_, dragObject_, *strokeIndex_, std::move(stroke)));
    } else {
        endDrag(); // the stroke was taken away under the pen (an undo from the keyboard)
    }
}

void SphereView::eraseAt(const QPointF& position)
{
    const model::SceneObject* object = document_.object(dragObject_);
    if (object == nullptr) {
        endDrag();
        return;
    }
    auto underPen = [this, position](const Eigen::Vector3d& point) {
        const QPointF offset = projection_.project(point) - position;
        return projection_.facesViewer(point) && std::hypot(offset.x(), offset.y()) <= kEraseRadiusPixels;
    };
    // A copy: every command below changes the document's strokes. Last to first, so that erasing a
    // stroke leaves the indices of those still to visit as they were; split-off parts go after all.
    const std::vector<model::DirectionStroke> strokes = object->track.sketch.directionStrokes;
    for (std::size_t index = strokes.size(); index-- > 0;) {
        std::optional<std::vector<model::DirectionStroke>> pieces = eraseStrokePoints(strokes[index], underPen);
        if (!pieces)
            continue;
        if (pieces->empty()) {
            gesture_->push(new model::EraseStrokeCommand(document_, dragObject_, index));
            continue;
        }
        gesture_->push(new model::EditStrokeCommand(document_, dragObject_, index, std::move(pieces->front())));
        for (std::size_t piece = 1; piece < pieces->size(); ++piece)
            gesture_->push(new model::AddStrokeCommand(document_, dragObject_, std::move((*pieces)[piece])));
    }
}

void SphereView::endDrag()
{
    gesture_.reset(); // finishes the gesture's undo step
    drag_ = DragKind::None;
    dragObject_ = model::kNoObject;
    strokePoints_.clear();
    strokeIndex_.reset();
    setCursor(tool_ == Tool::Pattern ? Qt::OpenHandCursor : Qt::CrossCursor);
}

void SphereView::cancelDrag()
{
    // Taken back while the gesture is still open, so that nothing waiting for its end (a fit held
    // back while drawing) lands first and is undone in its place.
    if (gesture_ && gesture_->hasStep())
        document_.undoStack().undo();
    endDrag();
}

// ---------------------------------------------------------------------------------------------
// Drawing

void SphereView::invalidateLayers()
{
    layersStale_ = true;
    update();
}

QImage SphereView::layerImage() const
{
    const qreal pixelRatio = devicePixelRatioF();
    QImage image((QSizeF(size()) * pixelRatio).toSize(), QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(pixelRatio);
    image.fill(Qt::transparent);
    return image;
}

void SphereView::rebuildLayers()
{
    auto startPainting = [this](QPainter& painter) {
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setRenderHint(QPainter::TextAntialiasing);
        painter.setFont(font()); // a painter on an image starts with the application's font
    };
    const bool selected = selection_.selectedObject() != nullptr;
    backLayer_ = layerImage();
    backLayer_.fill(kBackground);
    if (selected) {
        QPainter painter(&backLayer_);
        startPainting(painter);
        drawSphereLayers(painter, Side::Back);
    }
    frontLayer_ = layerImage();
    {
        QPainter painter(&frontLayer_);
        startPainting(painter);
        if (selected) {
            drawDisc(painter);
            drawSphereLayers(painter, Side::Front);
            drawLegend(painter);
        }
        drawMessage(painter, message());
    }
    currentTimeDots_[static_cast<std::size_t>(Side::Back)] = currentTimeDot(kBackOpacity, devicePixelRatioF());
    currentTimeDots_[static_cast<std::size_t>(Side::Front)] = currentTimeDot(1.0, devicePixelRatioF());
    layersStale_ = false;
    ++layerBuilds_;
}

void SphereView::paintEvent(QPaintEvent*)
{
    // The screen's pixel ratio changes when the window moves to another screen.
    if (layersStale_ || backLayer_.devicePixelRatio() != devicePixelRatioF())
        rebuildLayers();
    QPainter painter(this);
    painter.drawImage(QPointF(0.0, 0.0), backLayer_);
    if (selection_.selectedObject() != nullptr)
        drawCurrentTime(painter, Side::Back);
    painter.drawImage(QPointF(0.0, 0.0), frontLayer_);
    if (selection_.selectedObject() != nullptr)
        drawCurrentTime(painter, Side::Front);
}

void SphereView::drawSphereLayers(QPainter& painter, Side side) const
{
    drawGrid(painter, side);
    drawAxes(painter, side);
    // The sketch under the motion: where the fit achieves it, the red lies on the blue.
    drawStrokes(painter, side);
    drawMotion(painter, side);
    drawTimeTicks(painter, side);
}

void SphereView::drawDisc(QPainter& painter) const
{
    // Lit from the upper left: the highlight off centre, the rim in shade.
    const QPointF centre = projection_.centre();
    const double radius = projection_.radius();
    QRadialGradient shading(centre, radius, centre + QPointF(-0.35 * radius, -0.4 * radius));
    shading.setColorAt(0.0, kDiscLight);
    shading.setColorAt(1.0, kDiscShade);
    painter.setBrush(shading);
    painter.setPen(QPen(kRimColor, 1.5));
    painter.drawEllipse(centre, radius, radius);
    painter.setBrush(Qt::NoBrush);
}

void SphereView::drawCurve(QPainter& painter, const std::vector<Eigen::Vector3d>& points, const QPen& pen,
                           Side side) const
{
    painter.setPen(side == Side::Front ? pen : faded(pen, kBackOpacity));
    QPolygonF run;
    auto flush = [&] {
        if (run.size() >= 2)
            painter.drawPolyline(run);
        run.clear();
    };
    for (std::size_t i = 1; i < points.size(); ++i) {
        // A segment is on the side its middle is on.
        const bool front = projection_.facesViewer(points[i - 1] + points[i]);
        if (front != (side == Side::Front)) {
            flush();
            continue;
        }
        if (run.isEmpty())
            run << projection_.project(points[i - 1]);
        run << projection_.project(points[i]);
    }
    flush();
}

void SphereView::drawRuns(QPainter& painter, const std::vector<DirectionRun>& runs, const QPen& pen, Side side,
                          double from, double to) const
{
    for (const DirectionRun& run : runs) {
        std::vector<Eigen::Vector3d> points;
        for (const fit::TimedVector& sample : run)
            if (sample.time >= from && sample.time <= to)
                points.push_back(sample.value);
        drawCurve(painter, points, pen, side);
    }
}

void SphereView::drawGrid(QPainter& painter, Side side) const
{
    for (const std::vector<Eigen::Vector3d>& circle : gridCircles())
        drawCurve(painter, circle, QPen(kGridColor, 0.8), side);
}

void SphereView::drawAxes(QPainter& painter, Side side) const
{
    const std::array<QString, 3> names{QStringLiteral("x"), QStringLiteral("y"), QStringLiteral("z")};
    QFont font = painter.font();
    font.setBold(true);
    painter.setFont(font);
    for (int axis = 0; axis < 3; ++axis) {
        const Eigen::Vector3d direction = Eigen::Vector3d::Unit(axis);
        if (projection_.facesViewer(direction) != (side == Side::Front))
            continue;
        const double opacity = side == Side::Front ? 1.0 : kBackOpacity;
        const QPen pen = faded(QPen(kAxisColors[static_cast<std::size_t>(axis)], 2.0), opacity);
        painter.setPen(pen);
        painter.drawLine(projection_.centre(), projection_.project(SphereProjection::kAxisOvershoot * direction));
        const QPointF labelAt = projection_.project(SphereProjection::kAxisLabelDistance * direction);
        painter.drawText(QRectF(labelAt - QPointF(10.0, 10.0), QSizeF(20.0, 20.0)), Qt::AlignCenter,
                         names[static_cast<std::size_t>(axis)]);
    }
    painter.setFont(QFont());
}

void SphereView::drawMotion(QPainter& painter, Side side) const
{
    const double infinity = std::numeric_limits<double>::infinity();
    const QPen motionPen(kMotionColor, 2.0);
    if (!curves_.fitSpan) {
        drawRuns(painter, curves_.motion, motionPen, side, -infinity, infinity);
        return;
    }
    const auto [fitStart, fitEnd] = *curves_.fitSpan;
    drawRuns(painter, curves_.motion, motionPen, side, -infinity, fitStart);
    drawRuns(painter, curves_.motion, motionPen, side, fitEnd, infinity);
    drawRuns(painter, curves_.beforeFit, QPen(kBeforeFitColor, 2.0, Qt::DashLine), side, fitStart, fitEnd);
    drawRuns(painter, curves_.motion, QPen(kFittedColor, 1.8), side, fitStart, fitEnd);
}

void SphereView::drawTimeTicks(QPainter& painter, Side side) const
{
    const model::Scene& scene = document_.scene();
    const double range = scene.endTime - scene.startTime;
    if (curves_.motion.empty() || !(range > 0.0) || !std::isfinite(range))
        return;
    const double labelStep = timeLabelStep(range);
    const double tickStep = range <= kLongestMinorTickedRange ? kMinorTickSeconds : 1.0;
    const double opacity = side == Side::Front ? 1.0 : kBackOpacity;
    painter.setPen(faded(QPen(kTickColor, 1.5), opacity));
    QFont font = painter.font();
    font.setPointSizeF(font.pointSizeF() * 0.85);
    painter.setFont(font);
    for (double tick = std::ceil(scene.startTime / tickStep) * tickStep; tick <= scene.endTime; tick += tickStep) {
        const std::optional<Eigen::Vector3d> direction = directionAt(curves_.motion, tick);
        if (!direction || projection_.facesViewer(*direction) != (side == Side::Front))
            continue;
        const Eigen::Vector3d before = directionAt(curves_.motion, tick - kTangentSeconds).value_or(*direction);
        const Eigen::Vector3d after = directionAt(curves_.motion, tick + kTangentSeconds).value_or(*direction);
        const QPointF tangent = projection_.project(after) - projection_.project(before);
        const double length = std::hypot(tangent.x(), tangent.y());
        if (length < 1e-9)
            continue; // the curve stands still on screen: no direction to tick across
        const QPointF across(-tangent.y() / length, tangent.x() / length);
        const QPointF at = projection_.project(*direction);
        const bool wholeSecond = std::abs(tick - std::round(tick)) < 1e-9;
        const double half = wholeSecond ? kMajorTickPixels : kMinorTickPixels;
        painter.drawLine(at - half * across, at + half * across);
        const bool labelled = wholeSecond && std::abs(std::remainder(tick, labelStep)) < 1e-9;
        if (labelled && side == Side::Front) {
            const QPointF labelAt = at + kTickLabelPixels * across;
            painter.drawText(QRectF(labelAt - QPointF(20.0, 8.0), QSizeF(40.0, 16.0)), Qt::AlignCenter,
                             tr("%1 s").arg(tick));
        }
    }
    painter.setFont(QFont());
}

void SphereView::drawStrokes(QPainter& painter, Side side) const
{
    for (const std::vector<fit::TimedVector>& target : curves_.targetStrokes)
        drawCurve(painter, directionsOf(target), QPen(kTargetStrokeColor, 2.5), side);
    const model::SceneObject* object = selection_.selectedObject();
    for (const model::DirectionStroke& stroke : object->track.sketch.directionStrokes)
        drawCurve(painter, stroke.points, QPen(kDrawnStrokeColor, 1.2), side);
}

void SphereView::drawCurrentTime(QPainter& painter, Side side) const
{
    const std::optional<Eigen::Vector3d> direction = directionAt(curves_.motion, document_.scene().currentTime);
    if (!direction || projection_.facesViewer(*direction) != (side == Side::Front))
        return;
    const QImage& dot = currentTimeDots_[static_cast<std::size_t>(side)];
    // Its corner on a device pixel, so that the image is copied rather than resampled.
    const double pixelRatio = dot.devicePixelRatio();
    const QPointF corner = projection_.project(*direction) - QPointF(dot.width(), dot.height()) / (2.0 * pixelRatio);
    painter.drawImage(QPointF(std::round(corner.x() * pixelRatio), std::round(corner.y() * pixelRatio)) / pixelRatio, dot);
}

void SphereView::drawLegend(QPainter& painter) const
{
    struct Entry {
        QPen pen;
        QString text;
    };
    std::vector<Entry> entries{{QPen(kMotionColor, 2.0), tr("motion: ω/|ω|")}};
    if (curves_.fitSpan) {
        entries.push_back({QPen(kFittedColor, 1.8), tr("fitted")});
        entries.push_back({QPen(kBeforeFitColor, 2.0, Qt::DashLine), tr("before the fit")});
    }
    entries.push_back({QPen(kDrawnStrokeColor, 1.2), tr("sketch as drawn")});
    entries.push_back({QPen(kTargetStrokeColor, 2.5), tr("sketch as fitted, pattern applied")});
    const QFontMetricsF metrics(painter.font());
    const double lineHeight = metrics.height() + 2.0;
    QPointF at(8.0, height() - 8.0 - lineHeight * static_cast<double>(entries.size()));
    for (const Entry& entry : entries) {
        const double middle = at.y() + lineHeight / 2.0;
        painter.setPen(entry.pen);
        painter.drawLine(QPointF(at.x(), middle), QPointF(at.x() + 18.0, middle));
        painter.setPen(kTextColor);
        painter.drawText(QRectF(at.x() + 24.0, at.y(), width(), lineHeight), Qt::AlignLeft | Qt::AlignVCenter,
                         entry.text);
        at.ry() += lineHeight;
    }
}

void SphereView::drawMessage(QPainter& painter, const QString& text) const
{
    if (text.isEmpty())
        return;
    // With nothing selected the message is all there is; otherwise it heads the sphere.
    const bool alone = selection_.selectedObject() == nullptr;
    painter.setPen(kTextColor);
    painter.drawText(rect().adjusted(12, 8, -12, -8),
                     (alone ? Qt::AlignCenter : Qt::AlignTop | Qt::AlignHCenter) | Qt::TextWordWrap, text);
}

} // namespace gyre::app
