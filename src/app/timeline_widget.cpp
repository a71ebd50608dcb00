#include "app/timeline_widget.h"

#include "model/commands/replace_keyframes_command.h"
#include "model/key_edits.h"

#include <QEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

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
// A press that moves less than this many pixels is a click.
constexpr int kDragStartPixels = 4;

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
    , playback_(playback)
{
    setFocusPolicy(Qt::StrongFocus);
    setAttribute(Qt::WA_OpaquePaintEvent);
    // The cursor alone moves with the current time; the rest is redrawn when what it shows changes.
    connect(&document_, &model::Document::currentTimeChanged, this, [this] { update(); });
    connect(&document_, &model::Document::changed, this, [this](model::ObjectId object, model::Changes changes) {
        using model::Change;
        if (changes.testFlag(Change::Scene))
            endKeyDrag(); // the keys a drag was moving are gone with the old scene
        const bool shownRow = selection_.isObjectSelected(object) &&
                              (changes & (Change::Keyframes | Change::Object | Change::Removed | Change::Added));
        if (shownRow || (changes & (Change::Scene | Change::SceneSettings)))
            invalidateStaticLayer();
    });
    // The rows and the selected keys follow the selection.
    connect(&selection_, &Selection::changed, this, [this] {
        invalidateStaticLayer();
        updateGeometry();
    });
}

QSize TimelineWidget::sizeHint() const
{
    const auto rowCount = static_cast<int>(std::max<std::size_t>(1, rows().size()));
    return {640, rulerRect().height() + rowCount * kKeyLaneHeight + 8};
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

std::vector<model::ObjectId> TimelineWidget::rows() const
{
    std::vector<model::ObjectId> shown = selection_.objects();
    if (shown.size() > kMaxRows) {
        const model::ObjectId active = selection_.object();
        const bool activeShown = std::find(shown.begin(), shown.begin() + kMaxRows, active) != shown.begin() + kMaxRows;
        shown.resize(kMaxRows);
        if (!activeShown && active != model::kNoObject)
            shown.back() = active;
    }
    return shown;
}

QRect TimelineWidget::rowRect(std::size_t row, std::size_t rowCount) const
{
    const QRect lanes = keyLaneRect();
    const auto count = static_cast<int>(std::max<std::size_t>(1, rowCount));
    const int top = lanes.top() + lanes.height() * static_cast<int>(row) / count;
    const int bottom = lanes.top() + lanes.height() * (static_cast<int>(row) + 1) / count;
    return {0, top, width(), bottom - top};
}

std::optional<QPoint> TimelineWidget::keyMarkerCentre(std::size_t key) const
{
    return keyMarkerCentre(selection_.object(), key);
}

std::optional<QPoint> TimelineWidget::keyMarkerCentre(model::ObjectId object, std::size_t key) const
{
    const std::vector<model::ObjectId> shown = rows();
    const auto row = std::find(shown.begin(), shown.end(), object);
    const model::SceneObject* found = document_.object(object);
    if (row == shown.end() || found == nullptr || key >= found->track.keys.size())
        return std::nullopt;
    const QRect lane = rowRect(static_cast<std::size_t>(row - shown.begin()), shown.size());
    return QPoint(static_cast<int>(std::lround(xForTime(found->track.keys[key].time))), lane.center().y());
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
    paintBox(painter);
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
    const std::vector<model::ObjectId> shown = rows();
    const QColor keyColour = palette().color(QPalette::Text);
    const QColor selectedColour = palette().color(QPalette::Highlight);
    QColor labelColour = keyColour;
    labelColour.setAlphaF(0.45f);
    painter.save();
    painter.setClipRect(keyLaneRect());
    for (std::size_t row = 0; row < shown.size(); ++row) {
        const model::SceneObject* object = document_.object(shown[row]);
        const QRect lane = rowRect(row, shown.size());
        if (shown.size() > 1) {
            // Which object the row is: its name under the markers, and a line between rows.
            painter.setPen(labelColour);
            painter.drawText(lane.adjusted(kSideMargin + 2, 0, 0, 0), Qt::AlignLeft | Qt::AlignTop, object->name);
            if (row > 0)
                painter.drawLine(lane.topLeft(), lane.topRight());
        }
        const std::vector<std::size_t> selectedKeys = selection_.keysOf(object->id);
        auto nextSelected = selectedKeys.begin();
        for (std::size_t index = 0; index < object->track.keys.size(); ++index) {
            const model::Keyframe& key = object->track.keys[index];
            const bool selected = nextSelected != selectedKeys.end() && *nextSelected == index;
            if (selected)
                ++nextSelected;
            const double radius = selected ? kSelectedMarkerRadius : kMarkerRadius;
            const QPointF centre(xForTime(key.time), lane.center().y());
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
    }
    painter.restore();
}

void TimelineWidget::paintBox(QPainter& painter) const
{
    if (!box_ || !box_->dragged)
        return;
    QColor fill = palette().color(QPalette::Highlight);
    fill.setAlphaF(0.2f);
    painter.setPen(QPen(palette().color(QPalette::Highlight), 1.0, Qt::DashLine));
    painter.setBrush(fill);
    painter.drawRect(QRect(box_->from, box_->to).normalized());
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

std::optional<KeyRef> TimelineWidget::keyAt(const QPoint& point) const
{
    const std::vector<model::ObjectId> shown = rows();
    const int reach = kSelectedMarkerRadius + kMarkerHitSlack;
    for (std::size_t row = 0; row < shown.size(); ++row) {
        const QRect lane = rowRect(row, shown.size());
        if (point.y() < lane.top() || point.y() > lane.bottom() || std::abs(point.y() - lane.center().y()) > reach)
            continue;
        const model::SceneObject* object = document_.object(shown[row]);
        std::optional<KeyRef> nearest;
        double nearestDistance = reach;
        for (std::size_t index = 0; index < object->track.keys.size(); ++index) {
            const double distance = std::abs(xForTime(object->track.keys[index].time) - point.x());
            if (distance <= nearestDistance) {
                nearest = KeyRef{object->id, index};
                nearestDistance = distance;
            }
        }
        return nearest;
    }
    return std::nullopt;
}

void TimelineWidget::mousePressEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) {
        QWidget::mousePressEvent(event);
        return;
    }
    const QPoint point = event->position().toPoint();
    if (const std::optional<KeyRef> key = keyAt(point)) {
        pressKey(*key, *event);
        return;
    }
    if (keyLaneRect().contains(point)) {
        box_ = BoxPress{point, point, false};
        return;
    }
    scrubbing_ = true;
    playback_.pause();
    scrubTo(event->position().x(), event->modifiers());
}

void TimelineWidget::pressKey(const KeyRef& key, const QMouseEvent& event)
{
    if (event.modifiers().testFlag(Qt::ShiftModifier)) {
        shiftPress_.emplace(key, event.position().toPoint());
        return;
    }
    const bool selected = selection_.isKeySelected(key.first, key.second);
    if (!selected)
        selection_.selectKey(key.first, key.second);
    startKeyDrag(key, timeAtX(event.position().x()), selected);
}

void TimelineWidget::startKeyDrag(const KeyRef& pressed, double pressTime, bool selectsOnClick)
{
    KeyDrag drag;
    for (model::ObjectId object : selection_.objects()) {
        std::vector<std::size_t> indices = selection_.keysOf(object);
        if (!indices.empty())
            drag.objects.push_back({object, document_.object(object)->track.keys, std::move(indices)});
    }
    drag.pressedKeyTime = document_.object(pressed.first)->track.keys[pressed.second].time;
    drag.pressTime = pressTime;
    if (selectsOnClick)
        drag.selectsOnClick = pressed;
    keyDrag_ = std::move(drag);
}

void TimelineWidget::mouseMoveEvent(QMouseEvent* event)
{
    if (!(event->buttons() & Qt::LeftButton)) {
        QWidget::mouseMoveEvent(event);
        return;
    }
    const QPoint point = event->position().toPoint();
    if (shiftPress_ && (point - shiftPress_->second).manhattanLength() >= kDragStartPixels) {
        // A Shift+drag of a marker moves the selected keys, unsnapped; its key joins them.
        const auto [key, from] = *shiftPress_;
        shiftPress_.reset();
        if (!selection_.isKeySelected(key.first, key.second))
            selection_.toggleKey(key.first, key.second);
        startKeyDrag(key, timeAtX(from.x()), false);
    }
    if (keyDrag_) {
        dragKeysTo(event->position().x(), event->modifiers());
    } else if (box_) {
        box_->to = point;
        box_->dragged = box_->dragged || (point - box_->from).manhattanLength() >= kDragStartPixels;
        update();
    } else if (scrubbing_) {
        scrubTo(event->position().x(), event->modifiers());
    }
}

void TimelineWidget::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) {
        QWidget::mouseReleaseEvent(event);
        return;
    }
    if (shiftPress_) {
        selection_.toggleKey(shiftPress_->first.first, shiftPress_->first.second);
        shiftPress_.reset();
    }
    if (box_)
        finishBox(event->modifiers());
    if (keyDrag_ && !dragGesture_ && keyDrag_->selectsOnClick)
        selection_.selectKey(keyDrag_->selectsOnClick->first, keyDrag_->selectsOnClick->second);
    endKeyDrag();
    scrubbing_ = false;
}

void TimelineWidget::finishBox(Qt::KeyboardModifiers modifiers)
{
    const BoxPress box = *box_;
    box_.reset();
    update();
    if (!box.dragged) {
        // A click between markers: scrub there, and let go of the keys.
        if (!modifiers.testFlag(Qt::ShiftModifier))
            selection_.deselectKeys();
        playback_.pause();
        scrubTo(box.from.x(), modifiers);
        return;
    }
    const QRect area = QRect(box.from, box.to).normalized();
    const std::vector<model::ObjectId> shown = rows();
    std::set<KeyRef> inside;
    for (std::size_t row = 0; row < shown.size(); ++row) {
        const int y = rowRect(row, shown.size()).center().y();
        const auto& keys = document_.object(shown[row])->track.keys;
        for (std::size_t index = 0; index < keys.size(); ++index)
            if (area.contains(QPoint(static_cast<int>(std::lround(xForTime(keys[index].time))), y)))
                inside.insert({shown[row], index});
    }
    selection_.selectKeys(inside, modifiers.testFlag(Qt::ShiftModifier));
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

void TimelineWidget::dragKeysTo(double x, Qt::KeyboardModifiers modifiers)
{
    for (const KeyDrag::Moved& moved : keyDrag_->objects) {
        const model::SceneObject* object = document_.object(moved.object);
        if (object == nullptr || object->track.keys.size() != moved.keys.size()) {
            // The keys went away under the drag (an undo, another view): nothing left to move.
            endKeyDrag();
            return;
        }
    }
    const model::Scene& scene = document_.scene();
    const bool snap = !modifiers.testFlag(Qt::ShiftModifier);
    double shift = timeAtX(x) - keyDrag_->pressTime;
    if (snap) // the pressed key lands on a frame, the others keep their distances to it
        shift = snappedToFrame(keyDrag_->pressedKeyTime + shift) - keyDrag_->pressedKeyTime;
    const double gap = snap ? 1.0 / scene.fps : kUnsnappedKeyGapSeconds;
    double lower = -std::numeric_limits<double>::infinity();
    double upper = std::numeric_limits<double>::infinity();
    for (const KeyDrag::Moved& moved : keyDrag_->objects) {
        const auto [low, high] = model::shiftRange(moved.keys, moved.indices, gap, scene.startTime, scene.endTime);
        lower = std::max(lower, low);
        upper = std::min(upper, high);
    }
    shift = lower <= upper ? std::clamp(shift, lower, upper) : 0.0;
    if (shift == keyDrag_->shift)
        return;
    keyDrag_->shift = shift;
    model::ObjectKeys keys;
    for (const KeyDrag::Moved& moved : keyDrag_->objects)
        keys.emplace_back(moved.object, model::shiftedKeys(moved.keys, moved.indices, shift));
    if (!dragGesture_)
        dragGesture_.emplace(document_);
    dragGesture_->push(new model::ReplaceKeyframesCommand(document_, std::move(keys),
                                                          model::ReplaceKeyframesCommand::Edit::Move));
}

void TimelineWidget::endKeyDrag()
{
    keyDrag_.reset();
    dragGesture_.reset(); // finishes the drag's undo step
}

double TimelineWidget::snappedToFrame(double seconds) const
{
    const double fps = document_.scene().fps;
    return std::round(seconds * fps) / fps;
}

} // namespace gyre::app
