#include "app/timeline_widget.h"

#include "model/commands/set_keyframe_time_command.h"

#include <QEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gyre::app {

namespace {

// Room at both ends so that a marker at the start or the end of the range can be grabbed whole.
constexpr int kSideMargin = 12;
constexpr int kMarkerRadius = 6;
constexpr int kSelectedMarkerRadius = 8;
// A marker is hit this many pixels beyond its drawn edge too.
constexpr int kMarkerHitSlack = 3;
constexpr int kKeyLaneHeight = 2 * kSelectedMarkerRadius + 10;
constexpr double kMinTickSpacing = 5.0;   // pixels between frame ticks
constexpr double kLabelPadding = 16.0;    // pixels between two labels
// Without snapping, the closest a dragged key comes to its neighbour; far above kKeyMergeSeconds, so
// that baking keeps both keys.
constexpr double kUnsnappedKeyGapSeconds = 1e-3;

bool isWholeNumber(double value)
{
    return std::abs(value - std::round(value)) < 1e-9;
}

// Steps in frames worth putting ticks at, increasing: 1, 2, 5, 10, 20, 50, ...
std::vector<long long> tickSteps(double totalFrames)
{
    std::vector<long long> steps;
    for (long long power = 1; static_cast<double>(power) <= 2.0 * totalFrames + 10.0; power *= 10)
        for (long long factor : {1, 2, 5})
            steps.push_back(power * factor);
    return steps;
}

// Steps in frames worth labelling, increasing. For a whole frame rate, labels fall on whole seconds
// or their halves and quarters where they can (30 fps labels 0.5 s, 1 s, 2 s, not every 10 frames
// at 0.333 s), and on 1, 2 or 5 frames only when zoomed in closer than a quarter second.
std::vector<long long> labelSteps(double fps, double totalFrames)
{
    if (!isWholeNumber(fps))
        return tickSteps(totalFrames);
    const auto perSecond = static_cast<long long>(std::round(fps));
    std::vector<long long> steps;
    for (long long frames : {1, 2, 5})
        if (frames * 4 < perSecond)
            steps.push_back(frames);
    for (long long divisor : {4, 2})
        if (perSecond % divisor == 0)
            steps.push_back(perSecond / divisor);
    for (long long power = 1; static_cast<double>(perSecond * power) <= 2.0 * totalFrames + 10.0 * fps; power *= 10)
        for (long long factor : {1, 2, 5})
            steps.push_back(perSecond * power * factor);
    std::sort(steps.begin(), steps.end());
    steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
    return steps;
}

// The smallest of `steps` at least `minPixels` wide; the largest if none is.
long long firstStepWiderThan(const std::vector<long long>& steps, double pixelsPerFrame, double minPixels)
{
    for (long long step : steps)
        if (static_cast<double>(step) * pixelsPerFrame >= minPixels)
            return step;
    return steps.back();
}

// Seconds to the millisecond, without trailing zeros: "0.5 s", "0.167 s", "2 s".
QString secondsLabel(double seconds)
{
    QString number = QString::number(seconds, 'f', 3);
    while (number.endsWith(QLatin1Char('0')))
        number.chop(1);
    if (number.endsWith(QLatin1Char('.')))
        number.chop(1);
    if (number == QLatin1String("-0"))
        number = QStringLiteral("0");
    return TimelineWidget::tr("%1 s").arg(number);
}

QString frameLabel(long long frame)
{
    return TimelineWidget::tr("%1 f").arg(frame);
}

} // namespace

TimelineWidget::TimelineWidget(model::Document& document, Selection& selection, Playback& playback,
                               QWidget* parent)
    : QWidget(parent)
    , document_(document)
    , selection_(selection)
    , selectedTrack_(document, selection)
    , playback_(playback)
{
    setFocusPolicy(Qt::StrongFocus);
    setAttribute(Qt::WA_OpaquePaintEvent);
    // The cursor alone moves with the current time; the rest is redrawn when what it shows changes.
    connect(&document_, &model::Document::currentTimeChanged, this, [this] { update(); });
    connect(&selectedTrack_, &SelectedTrack::changed, this, [this](model::Changes changes) {
        using model::Change;
        if (changes.testFlag(Change::Scene))
            endKeyDrag(); // the keys a drag was moving are gone with the old scene
        if (changes & (Change::Scene | Change::Keyframes | Change::SceneSettings))
            invalidateStaticLayer();
    });
    // The selected key is drawn apart.
    connect(&selection_, &Selection::changed, this, [this] { invalidateStaticLayer(); });
}

QSize TimelineWidget::sizeHint() const
{
    return {640, rulerRect().height() + kKeyLaneHeight + 8};
}

QSize TimelineWidget::minimumSizeHint() const
{
    return {4 * kSideMargin + 80, rulerRect().height() + kKeyLaneHeight};
}

double TimelineWidget::xForTime(double seconds) const
{
    const model::Scene& scene = document_.scene();
    const double span = width() - 2 * kSideMargin;
    return kSideMargin + (seconds - scene.startTime) / (scene.endTime - scene.startTime) * span;
}

double TimelineWidget::timeAtX(double x) const
{
    const model::Scene& scene = document_.scene();
    const double span = std::max(1, width() - 2 * kSideMargin);
    return scene.startTime + (x - kSideMargin) / span * (scene.endTime - scene.startTime);
}

QRect TimelineWidget::rulerRect() const
{
    // Two lines of labels (seconds, frames) above the tallest ticks.
    return {0, 0, width(), 2 * fontMetrics().height() + 10};
}

QRect TimelineWidget::keyLaneRect() const
{
    const QRect ruler = rulerRect();
    return {0, ruler.bottom() + 1, width(), std::max(kKeyLaneHeight, height() - ruler.height())};
}

std::optional<QPoint> TimelineWidget::keyMarkerCentre(std::size_t key) const
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr || key >= object->track.keys.size())
        return std::nullopt;
    return QPoint(static_cast<int>(std::lround(xForTime(object->track.keys[key].time))), keyLaneRect().center().y());
}

void TimelineWidget::invalidateStaticLayer()
{
    staticLayerStale_ = true;
    // A hidden widget is not painted: the layer is rebuilt at the first paint once it is shown.
    update();
}

void TimelineWidget::resizeEvent(QResizeEvent* event)
{
    staticLayerStale_ = true;
    QWidget::resizeEvent(event);
}

void TimelineWidget::changeEvent(QEvent* event)
{
    switch (event->type()) {
    case QEvent::PaletteChange:
    case QEvent::FontChange:
    case QEvent::StyleChange:
    case QEvent::LanguageChange: // the labels' "s" and "f"
        invalidateStaticLayer();
        break;
    default:
        break;
    }
    QWidget::changeEvent(event);
}

void TimelineWidget::rebuildStaticLayer()
{
    const qreal pixelRatio = devicePixelRatioF();
    staticLayer_ = QPixmap((QSizeF(size()) * pixelRatio).toSize());
    staticLayer_.setDevicePixelRatio(pixelRatio);
    QPainter painter(&staticLayer_);
    painter.setFont(font()); // a painter on a pixmap starts with the application's font, not the widget's
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rulerRect(), palette().button());
    painter.fillRect(keyLaneRect(), palette().base());
    paintRuler(painter);
    paintKeyMarkers(painter);
    staticLayerStale_ = false;
    ++staticLayerBuilds_;
}

void TimelineWidget::paintEvent(QPaintEvent*)
{
    // The screen's pixel ratio changes when the window moves to another screen.
    if (staticLayerStale_ || staticLayer_.devicePixelRatio() != devicePixelRatioF())
        rebuildStaticLayer();
    QPainter painter(this);
    painter.drawPixmap(0, 0, staticLayer_);
    painter.setRenderHint(QPainter::Antialiasing);
    paintCursor(painter);
    if (hasFocus()) {
        painter.setPen(QPen(palette().highlight(), 1.0));
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(QRectF(rect()).adjusted(0.5, 0.5, -0.5, -0.5));
    }
}

void TimelineWidget::paintRuler(QPainter& painter) const
{
    const model::Scene& scene = document_.scene();
    const QRect ruler = rulerRect();
    const double totalFrames = (scene.endTime - scene.startTime) * scene.fps;
    const double pixelsPerFrame = (width() - 2 * kSideMargin) / totalFrames;
    const QFontMetrics metrics = fontMetrics();
    // No label is wider than the range's longer end written to the millisecond, e.g. "-12.345 s".
    const double longerEnd = std::max(std::abs(scene.startTime), std::abs(scene.endTime));
    const QString widestSeconds = TimelineWidget::tr("%1 s").arg(
        (scene.startTime < 0.0 ? QStringLiteral("-") : QString()) + QString::number(longerEnd, 'f', 3));
    const double widestLabel =
        std::max({metrics.horizontalAdvance(widestSeconds),
                  metrics.horizontalAdvance(frameLabel(std::llround(scene.startTime * scene.fps))),
                  metrics.horizontalAdvance(frameLabel(std::llround(scene.endTime * scene.fps)))});
    const long long labelStep =
        firstStepWiderThan(labelSteps(scene.fps, totalFrames), pixelsPerFrame, widestLabel + kLabelPadding);
    // Ticks between the labels, on steps that divide the labels' step, so that labels sit on ticks.
    std::vector<long long> dividingSteps;
    for (long long step : tickSteps(totalFrames))
        if (labelStep % step == 0)
            dividingSteps.push_back(step);
    const long long tickStep = firstStepWiderThan(dividingSteps, pixelsPerFrame, kMinTickSpacing);

    const QColor tickColour = palette().color(QPalette::ButtonText);
    QColor frameTextColour = tickColour;
    frameTextColour.setAlphaF(0.6f);
    const int bottom = ruler.bottom();
    // Frames k with start ≤ k/fps ≤ end, a rounding error either way allowed.
    const auto firstFrame = static_cast<long long>(std::ceil(scene.startTime * scene.fps - 1e-9));
    const auto lastFrame = static_cast<long long>(std::floor(scene.endTime * scene.fps + 1e-9));
    // The first multiple of tickStep at or after firstFrame (frames may be negative).
    long long frame = firstFrame + ((tickStep - firstFrame % tickStep) % tickStep);
    for (; frame <= lastFrame; frame += tickStep) {
        const double seconds = static_cast<double>(frame) / scene.fps;
        const double x = xForTime(seconds);
        const bool labelled = frame % labelStep == 0;
        painter.setPen(QPen(tickColour, 1.0));
        painter.drawLine(QPointF(x, bottom - (labelled ? 8.0 : 4.0)), QPointF(x, bottom));
        if (!labelled)
            continue;
        const QRectF secondsBox(x - widestLabel, ruler.top() + 2, 2 * widestLabel, metrics.height());
        painter.drawText(secondsBox, Qt::AlignHCenter | Qt::AlignTop, secondsLabel(seconds));
        painter.setPen(frameTextColour);
        painter.drawText(secondsBox.translated(0, metrics.height()), Qt::AlignHCenter | Qt::AlignTop,
                         frameLabel(frame));
    }
    painter.setPen(QPen(tickColour, 1.0));
    painter.drawLine(QPointF(xForTime(scene.startTime), bottom + 0.5), QPointF(xForTime(scene.endTime), bottom + 0.5));
}

void TimelineWidget::paintKeyMarkers(QPainter& painter) const
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr)
        return;
    const std::optional<std::size_t> selectedKey = selection_.key();
    const QColor keyColour = palette().color(QPalette::Text);
    const QColor selectedColour = palette().color(QPalette::Highlight);
    painter.save();
    painter.setClipRect(keyLaneRect());
    for (std::size_t index = 0; index < object->track.keys.size(); ++index) {
        const model::Keyframe& key = object->track.keys[index];
        const bool selected = selectedKey == index;
        const double radius = selected ? kSelectedMarkerRadius : kMarkerRadius;
        const QPointF centre(xForTime(key.time), keyLaneRect().center().y());
        QPainterPath diamond;
        diamond.moveTo(centre + QPointF(0, -radius));
        diamond.lineTo(centre + QPointF(radius, 0));
        diamond.lineTo(centre + QPointF(0, radius));
        diamond.lineTo(centre + QPointF(-radius, 0));
        diamond.closeSubpath();
        const QColor colour = selected ? selectedColour : keyColour;
        painter.setPen(QPen(colour, 1.5));
        // Constrained keys are kept by the fit and drawn solid; free keys, which it may move, hollow.
        painter.setBrush(key.constrained ? QBrush(colour) : palette().base());
        painter.drawPath(diamond);
    }
    painter.restore();
}

void TimelineWidget::paintCursor(QPainter& painter) const
{
    const double x = xForTime(document_.scene().currentTime);
    const QColor colour(220, 50, 47);
    painter.setPen(QPen(colour, 1.5));
    painter.drawLine(QPointF(x, rulerRect().top()), QPointF(x, height()));
    // A handle on the ruler, pointing down at the keys.
    const double top = rulerRect().bottom() - 8.0;
    QPainterPath handle;
    handle.moveTo(x - 5.0, top);
    handle.lineTo(x + 5.0, top);
    handle.lineTo(x, top + 8.0);
    handle.closeSubpath();
    painter.setBrush(colour);
    painter.drawPath(handle);
}

std::optional<std::size_t> TimelineWidget::keyAt(const QPoint& point) const
{
    const model::SceneObject* object = selection_.selectedObject();
    const QRect lane = keyLaneRect();
    const int reach = kSelectedMarkerRadius + kMarkerHitSlack;
    if (object == nullptr || std::abs(point.y() - lane.center().y()) > reach)
        return std::nullopt;
    std::optional<std::size_t> nearest;
    double nearestDistance = reach;
    for (std::size_t index = 0; index < object->track.keys.size(); ++index) {
        const double distance = std::abs(xForTime(object->track.keys[index].time) - point.x());
        if (distance <= nearestDistance) {
            nearest = index;
            nearestDistance = distance;
        }
    }
    return nearest;
}

void TimelineWidget::mousePressEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) {
        QWidget::mousePressEvent(event);
        return;
    }
    const QPoint point = event->position().toPoint();
    if (const std::optional<std::size_t> key = keyAt(point)) {
        const model::ObjectId object = selection_.object();
        selection_.selectKey(object, *key);
        const double markerX = xForTime(document_.object(object)->track.keys[*key].time);
        keyDrag_ = KeyDrag{object, *key, event->position().x() - markerX};
        return;
    }
    scrubbing_ = true;
    playback_.pause();
    scrubTo(event->position().x(), event->modifiers());
}

void TimelineWidget::mouseMoveEvent(QMouseEvent* event)
{
    if (!(event->buttons() & Qt::LeftButton)) {
        QWidget::mouseMoveEvent(event);
        return;
    }
    if (keyDrag_)
        dragKeyTo(event->position().x(), event->modifiers());
    else if (scrubbing_)
        scrubTo(event->position().x(), event->modifiers());
}

void TimelineWidget::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) {
        QWidget::mouseReleaseEvent(event);
        return;
    }
    endKeyDrag();
    scrubbing_ = false;
}

void TimelineWidget::keyPressEvent(QKeyEvent* event)
{
    switch (event->key()) {
    case Qt::Key_Left:
        playback_.stepBackward();
        break;
    case Qt::Key_Right:
        playback_.stepForward();
        break;
    case Qt::Key_Home:
        playback_.goToStart();
        break;
    case Qt::Key_End:
        playback_.goToEnd();
        break;
    default:
        QWidget::keyPressEvent(event);
    }
}

void TimelineWidget::scrubTo(double x, Qt::KeyboardModifiers modifiers)
{
    const model::Scene& scene = document_.scene();
    double seconds = std::clamp(timeAtX(x), scene.startTime, scene.endTime);
    if (!(modifiers & Qt::ShiftModifier))
        seconds = std::clamp(snappedToFrame(seconds), scene.startTime, scene.endTime);
    document_.setCurrentTime(seconds);
}

void TimelineWidget::dragKeyTo(double x, Qt::KeyboardModifiers modifiers)
{
    const model::SceneObject* object = document_.object(keyDrag_->object);
    if (object == nullptr || keyDrag_->key >= object->track.keys.size()) {
        // The key went away under the drag (an undo, another view): nothing left to move.
        endKeyDrag();
        return;
    }
    const double target = keyDragTime(object->track.keys, keyDrag_->key, timeAtX(x - keyDrag_->grabOffset),
                                      !(modifiers & Qt::ShiftModifier));
    if (target == object->track.keys[keyDrag_->key].time)
        return;
    if (!dragGesture_)
        dragGesture_.emplace(document_);
    dragGesture_->push(new model::SetKeyframeTimeCommand(document_, object->id, keyDrag_->key, target));
}

void TimelineWidget::endKeyDrag()
{
    keyDrag_.reset();
    dragGesture_.reset(); // finishes the drag's undo step
}

double TimelineWidget::keyDragTime(const std::vector<model::Keyframe>& keys, std::size_t key, double pointerTime,
                                   bool snap) const
{
    const model::Scene& scene = document_.scene();
    const double current = keys[key].time;
    const double before = key > 0 ? keys[key - 1].time : -std::numeric_limits<double>::infinity();
    const double after = key + 1 < keys.size() ? keys[key + 1].time : std::numeric_limits<double>::infinity();
    double time = std::clamp(pointerTime, scene.startTime, scene.endTime);
    if (snap) {
        time = snappedToFrame(time);
        // The first frame after the neighbour before, the last before the neighbour after; the loops
        // step past a frame that k/fps rounds onto the neighbour itself.
        if (time <= before) {
            double frame = std::floor(before * scene.fps) + 1.0;
            while (frame / scene.fps <= before)
                frame += 1.0;
            time = frame / scene.fps;
        }
        if (time >= after) {
            double frame = std::ceil(after * scene.fps) - 1.0;
            while (frame / scene.fps >= after)
                frame -= 1.0;
            time = frame / scene.fps;
        }
    } else {
        const double earliest = before + kUnsnappedKeyGapSeconds;
        const double latest = after - kUnsnappedKeyGapSeconds;
        if (earliest > latest)
            return current;
        time = std::clamp(time, earliest, latest);
    }
    return time > before && time < after ? time : current;
}

double TimelineWidget::snappedToFrame(double seconds) const
{
    const double fps = document_.scene().fps;
    return std::round(seconds * fps) / fps;
}

} // namespace gyre::app
