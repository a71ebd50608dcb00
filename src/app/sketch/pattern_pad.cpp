#include "app/sketch/pattern_pad.h"

#include "model/commands/set_pattern_command.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <utility>

namespace gyre::app {

namespace {

const QColor kPadColor(250, 250, 252);
const QColor kBaselineColor(200, 204, 212);
const QColor kChordColor(150, 155, 165);
const QColor kPatternColor(20, 60, 210);
constexpr double kFitMargin = 0.06; // of the pad's height, kept free around a pattern scaled to fit

} // namespace

PatternCanvas::PatternCanvas(QWidget* parent)
    : QWidget(parent)
{
    setCursor(Qt::CrossCursor);
    setToolTip(tr("Draw the pattern once, left to right: x along the strokes, y across them"));
}

void PatternCanvas::setPattern(std::vector<Eigen::Vector2d> pattern)
{
    pattern_ = std::move(pattern);
    update();
}

QPointF PatternCanvas::toWidget(const Eigen::Vector2d& padPoint) const
{
    const double unit = height();
    return {padPoint.x() * unit, height() / 2.0 - padPoint.y() * unit};
}

Eigen::Vector2d PatternCanvas::toPad(const QPointF& widgetPoint) const
{
    const double unit = height();
    return {widgetPoint.x() / unit, (height() / 2.0 - widgetPoint.y()) / unit};
}

Eigen::Vector2d PatternCanvas::clampedPadPoint(const QPointF& widgetPoint) const
{
    return toPad(QPointF(std::clamp(widgetPoint.x(), 0.0, static_cast<double>(width())),
                         std::clamp(widgetPoint.y(), 0.0, static_cast<double>(height()))));
}

std::vector<Eigen::Vector2d> PatternCanvas::shownPattern() const
{
    if (pattern_.empty())
        return {};
    Eigen::Vector2d low = pattern_.front();
    Eigen::Vector2d high = pattern_.front();
    for (const Eigen::Vector2d& point : pattern_) {
        low = low.cwiseMin(point);
        high = high.cwiseMax(point);
    }
    const Eigen::Vector2d padLow(0.0, -0.5);
    const Eigen::Vector2d padHigh(static_cast<double>(width()) / height(), 0.5);
    if ((low.array() >= padLow.array()).all() && (high.array() <= padHigh.array()).all())
        return pattern_;
    // A pattern from a file may be in any unit: scale it uniformly into the pad, centred.
    const Eigen::Vector2d room = (padHigh - padLow) * (1.0 - 2.0 * kFitMargin);
    const Eigen::Vector2d extent = (high - low).cwiseMax(1e-12);
    const double scale = std::min(room.x() / extent.x(), room.y() / extent.y());
    const Eigen::Vector2d offset = (padLow + padHigh) / 2.0 - scale * (low + high) / 2.0;
    std::vector<Eigen::Vector2d> shown;
    for (const Eigen::Vector2d& point : pattern_)
        shown.push_back(scale * point + offset);
    return shown;
}

void PatternCanvas::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), isEnabled() ? kPadColor : palette().color(QPalette::Window));
    painter.setPen(QPen(kBaselineColor, 1.0, Qt::DotLine));
    painter.drawLine(QPointF(0.0, height() / 2.0), QPointF(width(), height() / 2.0));
    painter.setPen(QPen(kBaselineColor, 1.0));
    painter.drawRect(QRectF(rect()).adjusted(0.5, 0.5, -0.5, -0.5));

    const std::vector<Eigen::Vector2d> points = drawing_ ? *drawing_ : shownPattern();
    if (points.size() < 2)
        return;
    QPolygonF line;
    for (const Eigen::Vector2d& point : points)
        line << toWidget(point);
    // y is measured from the chord through the ends, which lies along the stroke.
    painter.setPen(QPen(kChordColor, 1.0, Qt::DashLine));
    painter.drawLine(line.front(), line.back());
    painter.setPen(QPen(kPatternColor, 2.0));
    painter.drawPolyline(line);
}

void PatternCanvas::mousePressEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton || drawing_)
        return;
    drawing_ = std::vector{clampedPadPoint(event->position())};
    emit drawingStarted();
    update();
}

void PatternCanvas::mouseMoveEvent(QMouseEvent* event)
{
    if (!drawing_)
        return;
    const Eigen::Vector2d point = clampedPadPoint(event->position());
    if ((point - drawing_->back()).norm() * height() < kPointSpacingPixels)
        return;
    drawing_->push_back(point);
    emit drawn(*drawing_);
    update();
}

void PatternCanvas::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton || !drawing_)
        return;
    drawing_.reset();
    emit drawingFinished();
    update();
}

PatternPad::PatternPad(model::Document& document, Selection& selection, QWidget* parent)
    : QWidget(parent)
    , document_(document)
    , selection_(selection)
    , selectedTrack_(document, selection)
    , canvas_(new PatternCanvas(this))
    , repeatBox_(new QSpinBox(this))
    , clearButton_(new QPushButton(tr("Clear Pattern"), this))
    , repeatEdits_(model::Gesture(document).id())
{
    repeatBox_->setRange(0, kMaxRepeat);
    repeatBox_->setSpecialValueText(tr("off"));
    repeatBox_->setToolTip(tr("How many times the pattern repeats along the direction curve; off: not applied"));
    clearButton_->setToolTip(tr("Take the pattern away"));
    auto* repeatLabel = new QLabel(tr("&Repeat:"), this);
    repeatLabel->setBuddy(repeatBox_);

    auto* controls = new QHBoxLayout;
    controls->addWidget(repeatLabel);
    controls->addWidget(repeatBox_);
    controls->addStretch();
    controls->addWidget(clearButton_);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    layout->addWidget(canvas_, 1);
    layout->addLayout(controls);

    connect(canvas_, &PatternCanvas::drawingStarted, this, [this] { gesture_.emplace(document_); });
    connect(canvas_, &PatternCanvas::drawn, this, &PatternPad::setPatternDrawn);
    connect(canvas_, &PatternCanvas::drawingFinished, this, [this] { gesture_.reset(); });
    connect(repeatBox_, &QSpinBox::valueChanged, this, &PatternPad::setRepeat);
    connect(clearButton_, &QPushButton::clicked, this, &PatternPad::clearPattern);

    connect(&selectedTrack_, &SelectedTrack::changed, this, [this](model::Changes changes) {
        using model::Change;
        if (changes & (SelectedTrack::kAnotherObject | Change::Scene | Change::Sketch))
            showSketch();
    });
    showSketch();
}

void PatternPad::showSketch()
{
    const model::SceneObject* object = selection_.selectedObject();
    setEnabled(object != nullptr);
    if (object == nullptr)
        gesture_.reset();
    const QSignalBlocker blocker(repeatBox_);
    repeatBox_->setValue(object != nullptr ? object->track.sketch.patternRepeat : 0);
    canvas_->setPattern(object != nullptr ? object->track.sketch.pattern : std::vector<Eigen::Vector2d>{});
}

void PatternPad::setPatternDrawn(const std::vector<Eigen::Vector2d>& points)
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr || !gesture_)
        return;
    const int repeat = object->track.sketch.patternRepeat > 0 ? object->track.sketch.patternRepeat : kDefaultRepeat;
    gesture_->push(new model::SetPatternCommand(document_, object->id, points, repeat));
}

void PatternPad::setRepeat(int repeat)
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr || repeat == object->track.sketch.patternRepeat)
        return;
    // Merges with the box's previous edit while that is the newest step; a drawn pattern is another
    // gesture, so never merges with these.
    document_.push(new model::SetPatternCommand(document_, object->id, object->track.sketch.pattern, repeat),
                   repeatEdits_);
}

void PatternPad::clearPattern()
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr)
        return;
    document_.push(new model::SetPatternCommand(document_, object->id, {}, 0));
}

} // namespace gyre::app
