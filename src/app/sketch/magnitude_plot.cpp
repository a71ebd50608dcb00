#include "app/sketch/magnitude_plot.h"

#include "model/sketch_fit_problem.h"
#include "model/commands/set_fit_window_command.h"
#include "model/commands/set_magnitude_curve_command.h"
#include "model/track_evaluation.h"

#include <QAction>
#include <QActionGroup>
#include <QLabel>
#include <QMouseEvent>
#include <QStackedLayout>
#include <QToolBar>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gyre::app {

namespace {

constexpr int kMinimumPlotWidth = 240;
constexpr int kMinimumPlotHeight = 160;
constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
// Fit view leaves room above the highest curve to draw higher, and shows at least this |ω|, rad/s
// (about 57 °/s), for a track that does not turn.
constexpr double kHeadroom = 1.15;
constexpr double kSmallestShownMagnitude = 1.0;
// The cursor has a buffered layer of its own, so that moving it at playback's rate repaints one line
// rather than every curve.
const char* const kCursorLayer = "cursor";

const QColor kCurrentColour(60, 60, 60);
const QColor kSketchedColour(31, 119, 180);
const QColor kFittedColour(214, 39, 40);
const QColor kBeforeFitColour(150, 150, 150);
const QColor kKeyColour(60, 60, 60);
const QColor kWindowColour(130, 100, 200);

// `count` evenly spaced times from `start` to `end`, both included.
QVector<double> evenTimes(double start, double end, int count)
{
    QVector<double> times;
    times.reserve(count);
    for (int k = 0; k < count; ++k)
        times.push_back(start + (end - start) * k / (count - 1));
    return times;
}

QVector<double> speedsAt(const model::TrackMotion& motion, const QVector<double>& times)
{
    QVector<double> speeds;
    speeds.reserve(times.size());
    for (double time : times)
        speeds.push_back(motion.angularVelocity(time).norm());
    return speeds;
}

// The keys' span of a track with at least two keys.
std::optional<std::pair<double, double>> keySpan(const model::MotionTrack& track)
{
    if (track.keys.size() < 2)
        return std::nullopt;
    return std::pair(track.keys.front().time, track.keys.back().time);
}

// The window the fit takes when the sketch has none; before anything is sketched, the keys' span,
// so that the artist can set a window first.
std::optional<std::pair<double, double>> impliedWindow(const model::MotionTrack& track)
{
    if (const std::optional<fit::TimeWindow> window = model::editWindow(track))
        return std::pair(window->start, window->end);
    return keySpan(track);
}

// `curve` with its points inside the span of `drawn` replaced by `drawn`.
std::vector<model::MagnitudePoint> withStroke(const std::vector<model::MagnitudePoint>& curve,
                                              const std::vector<model::MagnitudePoint>& drawn)
{
    std::vector<model::MagnitudePoint> merged;
    merged.reserve(curve.size() + drawn.size());
    for (const model::MagnitudePoint& point : curve)
        if (point.time < drawn.front().time)
            merged.push_back(point);
    merged.insert(merged.end(), drawn.begin(), drawn.end());
    for (const model::MagnitudePoint& point : curve)
        if (point.time > drawn.back().time)
            merged.push_back(point);
    return merged;
}

// Gives `graph` these points unless it has exactly them already; true if they changed. A change that
// leaves a curve as it was (a key moved, not turned) then costs no replot.
bool setDataIfChanged(QCPGraph& graph, const QVector<double>& keys, const QVector<double>& values)
{
    const QCPGraphDataContainer& shown = *graph.data();
    bool same = shown.size() == keys.size();
    for (qsizetype i = 0; same && i < keys.size(); ++i)
        same = shown.at(static_cast<int>(i))->key == keys[i] && shown.at(static_cast<int>(i))->value == values[i];
    if (!same)
        graph.setData(keys, values, true);
    return !same;
}

QCPScatterStyle keyMarker(const QBrush& fill)
{
    return QCPScatterStyle(QCPScatterStyle::ssDiamond, QPen(kKeyColour, 1.5), fill, 10);
}

} // namespace

// What the job thread samples for one request.
struct MagnitudePlot::SampledCurves {
    QVector<double> times, speeds;                 // the current motion over the scene's range
    QVector<double> fittedTimes, fitted, beforeFit; // over the fit's span; empty without a fit
    QVector<double> constrainedKeyTimes, constrainedKeySpeeds;
    QVector<double> freeKeyTimes, freeKeySpeeds;
};

MagnitudePlot::SampledCurves MagnitudePlot::sampleTrack(const model::SharedTrackMotion& shared, double start, double end)
{
    SampledCurves curves;
    const model::MotionTrack& track = shared.track();
    const model::TrackMotion& motion = shared.motion();
    curves.times = evenTimes(start, end, MagnitudePlot::kSampleCount);
    curves.speeds = speedsAt(motion, curves.times);
    for (const model::Keyframe& key : track.keys) {
        const double speed = motion.angularVelocity(key.time).norm();
        (key.constrained ? curves.constrainedKeyTimes : curves.freeKeyTimes).push_back(key.time);
        (key.constrained ? curves.constrainedKeySpeeds : curves.freeKeySpeeds).push_back(speed);
    }
    const std::vector<HermiteControlPoint>& fitted = track.sketch.fittedCurve;
    if (fitted.empty())
        return curves;
    curves.fittedTimes = evenTimes(fitted.front().time, fitted.back().time, MagnitudePlot::kFittedSampleCount);
    curves.fitted = speedsAt(motion, curves.fittedTimes);
    curves.beforeFit = speedsAt(shared.motionWithoutFit(), curves.fittedTimes);
    return curves;
}

MagnitudePlot::MagnitudePlot(model::Document& document, Selection& selection, QWidget* parent)
    : QWidget(parent)
    , document_(document)
    , selection_(selection)
    , selectedTrack_(document, selection)
    , stack_(new QStackedLayout)
    , placeholder_(new QLabel(tr("Select an object to see and sketch the speed of its rotation."), this))
    , plot_(new QCustomPlot(this))
    , replot_(*this, 0, [this] { plot_->replot(); })
    , cursorReplot_(*this, 0, [this] { plot_->layer(QString::fromLatin1(kCursorLayer))->replot(); })
    , sampler_(
          *this, selection, document,
          [](const std::shared_ptr<const model::SharedTrackMotion>& motion, const model::Scene& scene) {
              return [motion, start = scene.startTime, end = scene.endTime] {
                  return sampleTrack(*motion, start, end);
              };
          },
          [this](const SampledCurves& curves) { showCurves(curves); })
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    setUpToolBar();
    placeholder_->setAlignment(Qt::AlignCenter);
    placeholder_->setWordWrap(true);
    stack_->addWidget(placeholder_);
    stack_->addWidget(plot_);
    layout->addLayout(stack_, 1);
    setUpPlot();

    followDocument();
    showSelection();
}

QCPGraph* MagnitudePlot::graph(Curve curve) const
{
    switch (curve) {
    case Curve::Current:
        return currentGraph_;
    case Curve::Sketched:
        return sketchedGraph_;
    case Curve::Fitted:
        return fittedGraph_;
    case Curve::BeforeFit:
        return beforeFitGraph_;
    case Curve::ConstrainedKeys:
        return constrainedKeysGraph_;
    case Curve::FreeKeys:
        break;
    }
    return freeKeysGraph_;
}

QPointF MagnitudePlot::pixelFor(double time, double magnitude) const
{
    return {plot_->xAxis->coordToPixel(time), plot_->yAxis->coordToPixel(magnitude)};
}

std::pair<double, double> MagnitudePlot::valueAt(const QPointF& pixel) const
{
    return {plot_->xAxis->pixelToCoord(pixel.x()), plot_->yAxis->pixelToCoord(pixel.y())};
}

QRect MagnitudePlot::plotArea() const
{
    return plot_->axisRect()->rect();
}

void MagnitudePlot::setUpToolBar()
{
    auto* toolBar = new QToolBar(this);
    toolBar->setIconSize(QSize(16, 16));
    toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    layout()->addWidget(toolBar);

    // The shortcuts act while the plot has the focus, not across the main window.
    auto makeAction = [this, toolBar](const QString& text, const QKeySequence& shortcut, const QString& tip) {
        auto* action = new QAction(text, this);
        action->setShortcut(shortcut);
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        action->setToolTip(tr("%1 (%2)").arg(tip, shortcut.toString(QKeySequence::NativeText)));
        toolBar->addAction(action);
        QWidget::addAction(action);
        return action;
    };
    drawAction_ = makeAction(tr("Draw"), QKeySequence(Qt::Key_D),
                            tr("Left-drag draws the magnitude |ω| over time; going back erases"));
    panAction_ = makeAction(tr("Pan"), QKeySequence(Qt::Key_P), tr("Left-drag pans the view"));
    auto* tools = new QActionGroup(this);
    for (QAction* tool : {drawAction_, panAction_}) {
        tool->setCheckable(true);
        tools->addAction(tool);
    }
    drawAction_->setChecked(true);
    connect(drawAction_, &QAction::toggled, this, &MagnitudePlot::setTool);
    toolBar->addSeparator();
    fitViewAction_ = makeAction(tr("Fit View"), QKeySequence(Qt::Key_F),
                               tr("Show the scene's time range and the curves' height; double-click does too"));
    connect(fitViewAction_, &QAction::triggered, this, &MagnitudePlot::fitView);
    clearMagnitudeAction_ = makeAction(tr("Clear Magnitude"), QKeySequence(Qt::SHIFT | Qt::Key_Delete),
                                      tr("Remove the sketched magnitude curve"));
    connect(clearMagnitudeAction_, &QAction::triggered, this, &MagnitudePlot::clearMagnitude);
}

void MagnitudePlot::setUpPlot()
{
    plot_->setMinimumSize(kMinimumPlotWidth, kMinimumPlotHeight);
    plot_->setMouseTracking(true); // the cursor shape tells what a press would grab
    plot_->installEventFilter(this);
    plot_->setAutoAddPlottableToLegend(false);
    plot_->axisRect()->setRangeZoom(Qt::Horizontal);
    plot_->axisRect()->setRangeDrag(Qt::Horizontal | Qt::Vertical);
    setTool(true);

    plot_->xAxis->setLabel(tr("time (s)"));
    plot_->yAxis->setLabel(tr("|ω| (rad/s)"));
    // Animators read degrees: the right axis shows the same values in °/s.
    plot_->yAxis2->setVisible(true);
    plot_->yAxis2->setLabel(tr("|ω| (°/s)"));
    connect(plot_->yAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), plot_->yAxis2,
            [this](const QCPRange& range) {
                plot_->yAxis2->setRange(range.lower * kDegreesPerRadian, range.upper * kDegreesPerRadian);
            });

    addWindowBand();
    auto graphNamed = [this](const QString& name, const QPen& pen) {
        QCPGraph* graph = plot_->addGraph();
        graph->setName(name);
        graph->setPen(pen);
        return graph;
    };
    beforeFitGraph_ = graphNamed(tr("before fit"), QPen(kBeforeFitColour, 1.5, Qt::DashLine));
    currentGraph_ = graphNamed(tr("current"), QPen(kCurrentColour, 1.5));
    fittedGraph_ = graphNamed(tr("fitted"), QPen(kFittedColour, 2.0));
    sketchedGraph_ = graphNamed(tr("sketched"), QPen(kSketchedColour, 2.5));
    constrainedKeysGraph_ = graphNamed(tr("constrained keys"), Qt::NoPen);
    constrainedKeysGraph_->setScatterStyle(keyMarker(kKeyColour));
    freeKeysGraph_ = graphNamed(tr("free keys"), Qt::NoPen);
    freeKeysGraph_->setScatterStyle(keyMarker(Qt::white));
    for (QCPGraph* keys : {constrainedKeysGraph_, freeKeysGraph_})
        keys->setLineStyle(QCPGraph::lsNone);

    // The legend gets a row of its own above the axes, where it hides no curve.
    plot_->axisRect()->insetLayout()->take(plot_->legend);
    plot_->plotLayout()->insertRow(0);
    plot_->plotLayout()->addElement(0, 0, plot_->legend);
    plot_->plotLayout()->setRowStretchFactor(0, 0.001);
    plot_->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    plot_->legend->setBorderPen(Qt::NoPen);
    plot_->legend->setVisible(true);
    for (QCPGraph* graph : {currentGraph_, sketchedGraph_, fittedGraph_, beforeFitGraph_})
        graph->addToLegend();

    addCursor();
}

void MagnitudePlot::addCursor()
{
    plot_->addLayer(QString::fromLatin1(kCursorLayer));
    QCPLayer* layer = plot_->layer(QString::fromLatin1(kCursorLayer));
    layer->setMode(QCPLayer::lmBuffered);
    cursor_ = new QCPItemStraightLine(plot_);
    cursor_->setLayer(layer);
    cursor_->setPen(QPen(QColor(255, 140, 0), 1.5));
}

void MagnitudePlot::addWindowBand()
{
    // Both rectangles span the axis rect's height; the grip is the band's top kGripHeight pixels.
    windowBand_ = new QCPItemRect(plot_);
    windowGrip_ = new QCPItemRect(plot_);
    for (QCPItemRect* rect : {windowBand_, windowGrip_}) {
        rect->setLayer(QStringLiteral("grid")); // under the curves
        rect->setVisible(false); // as the window shown so far, none (showWindow)
        for (QCPItemPosition* corner : {rect->topLeft, rect->bottomRight})
            corner->setTypeY(QCPItemPosition::ptAxisRectRatio);
    }
    windowGrip_->bottomRight->setTypeY(QCPItemPosition::ptAbsolute);
    windowGrip_->bottomRight->setParentAnchorY(windowBand_->topLeft);
}

void MagnitudePlot::followDocument()
{
    // Selecting another key of the same object leaves the plot as it is (SelectedTrack).
    connect(&selectedTrack_, &SelectedTrack::changed, this, [this](model::Changes changes) {
        using model::Change;
        if (changes & (SelectedTrack::kAnotherObject | Change::Scene)) {
            endGesture();
            fitViewOnNextCurves_ = true;
            showSelection();
            return;
        }
        if (changes.testFlag(Change::SceneSettings))
            fitViewOnNextCurves_ = true;
        if (changes.testFlag(Change::Sketch))
            showSketch();
        if (changes & (Change::Sketch | Change::Keyframes))
            showWindow();
        if (changes & (model::kMotionChanges | Change::SceneSettings))
            sampler_.schedule(); // a fit changes the motion too
    });
    // The cursor's layer is redrawn once per turn of the event loop at most, and not while hidden.
    connect(&document_, &model::Document::currentTimeChanged, this, [this] {
        moveCursor();
        cursorReplot_.request();
    });
}

void MagnitudePlot::showSelection()
{
    const bool hasObject = selection_.selectedObject() != nullptr;
    stack_->setCurrentWidget(hasObject ? static_cast<QWidget*>(plot_) : placeholder_);
    for (QAction* action : {drawAction_, panAction_, fitViewAction_})
        action->setEnabled(hasObject);
    showSketch();
    showWindow();
    moveCursor();
    sampler_.schedule();
}

void MagnitudePlot::setTool(bool drawing)
{
    plot_->setInteraction(QCP::iRangeZoom, true);
    plot_->setInteraction(QCP::iRangeDrag, !drawing);
    showToolCursor();
}

void MagnitudePlot::showToolCursor()
{
    plot_->setCursor(drawAction_->isChecked() ? Qt::CrossCursor : Qt::OpenHandCursor);
}

void MagnitudePlot::showCurves(const SampledCurves& curves)
{
    // Every graph is compared, none skipped: `|` rather than `||`.
    const bool changed = setDataIfChanged(*currentGraph_, curves.times, curves.speeds)
                       | setDataIfChanged(*fittedGraph_, curves.fittedTimes, curves.fitted)
                       | setDataIfChanged(*beforeFitGraph_, curves.fittedTimes, curves.beforeFit)
                       | setDataIfChanged(*constrainedKeysGraph_, curves.constrainedKeyTimes, curves.constrainedKeySpeeds)
                       | setDataIfChanged(*freeKeysGraph_, curves.freeKeyTimes, curves.freeKeySpeeds);
    if (fitViewOnNextCurves_) {
        fitViewOnNextCurves_ = false;
        fitView();
    } else if (changed) {
        if (!gesture_)
            followCurvesHeight();
        plot_->replot();
    }
    emit curvesUpdated();
}

void MagnitudePlot::showSketch()
{
    QVector<double> times;
    QVector<double> magnitudes;
    if (const model::SceneObject* object = selection_.selectedObject()) {
        for (const model::MagnitudePoint& point : object->track.sketch.magnitude) {
            times.push_back(point.time);
            magnitudes.push_back(point.magnitude);
        }
    }
    if (setDataIfChanged(*sketchedGraph_, times, magnitudes))
        replot_.request();
    clearMagnitudeAction_->setEnabled(!times.isEmpty());
}

void MagnitudePlot::showWindow()
{
    const model::SceneObject* object = selection_.selectedObject();
    const bool own = object != nullptr && object->track.sketch.window.has_value();
    std::optional<std::pair<double, double>> window;
    if (object != nullptr)
        window = own ? object->track.sketch.window : impliedWindow(object->track);
    // Most key edits (a key moved or turned) leave the window as it is.
    if (window == shownWindow_ && own == shownWindowIsOwn_)
        return;
    shownWindow_ = window;
    shownWindowIsOwn_ = own;

    windowBand_->setVisible(shownWindow_.has_value());
    windowGrip_->setVisible(shownWindow_.has_value());
    if (shownWindow_) {
        const auto [start, end] = *shownWindow_;
        windowBand_->topLeft->setCoords(start, 0.0);
        windowBand_->bottomRight->setCoords(end, 1.0);
        windowGrip_->topLeft->setCoords(start, 0.0);
        windowGrip_->bottomRight->setCoords(end, kGripHeight);
    }
    // The sketch's own window is solid; the one the fit would take without it is lighter and dashed.
    const int alpha = shownWindowIsOwn_ ? 60 : 25;
    const Qt::PenStyle edge = shownWindowIsOwn_ ? Qt::SolidLine : Qt::DashLine;
    windowBand_->setPen(QPen(kWindowColour.darker(130), 1.5, edge));
    windowBand_->setBrush(QColor(kWindowColour.red(), kWindowColour.green(), kWindowColour.blue(), alpha));
    windowGrip_->setPen(Qt::NoPen);
    windowGrip_->setBrush(QColor(kWindowColour.red(), kWindowColour.green(), kWindowColour.blue(), 2 * alpha));
    replot_.request();
}

void MagnitudePlot::moveCursor()
{
    const double now = document_.scene().currentTime;
    cursor_->point1->setCoords(now, 0.0);
    cursor_->point2->setCoords(now, 1.0);
}

void MagnitudePlot::fitView()
{
    const model::Scene& scene = document_.scene();
    plot_->xAxis->setRange(scene.startTime, scene.endTime);
    viewMovedByHand_ = false;
    followCurvesHeight();
    plot_->replot();
}

void MagnitudePlot::followCurvesHeight()
{
    if (viewMovedByHand_)
        return;
    double highest = kSmallestShownMagnitude;
    for (QCPGraph* graph : {currentGraph_, sketchedGraph_, fittedGraph_, beforeFitGraph_})
        for (const QCPGraphData& point : *graph->data())
            highest = std::max(highest, point.value);
    plot_->yAxis->setRange(0.0, highest * kHeadroom);
}

void MagnitudePlot::clearMagnitude()
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr || object->track.sketch.magnitude.empty())
        return;
    document_.push(new model::SetMagnitudeCurveCommand(document_, object->id, {}));
}

bool MagnitudePlot::eventFilter(QObject* watched, QEvent* event)
{
    if (watched != plot_)
        return QWidget::eventFilter(watched, event);
    switch (event->type()) {
    case QEvent::MouseButtonPress:
        return pressed(*static_cast<QMouseEvent*>(event));
    case QEvent::MouseMove:
        return moved(*static_cast<QMouseEvent*>(event));
    case QEvent::MouseButtonRelease:
        return released(*static_cast<QMouseEvent*>(event));
    case QEvent::Wheel:
        viewMovedByHand_ = true; // QCustomPlot zooms
        return false;
    case QEvent::MouseButtonDblClick:
        if (static_cast<QMouseEvent*>(event)->button() != Qt::LeftButton)
            return false;
        fitView();
        return true;
    default:
        return false;
    }
}

bool MagnitudePlot::pressed(const QMouseEvent& event)
{
    const model::SceneObject* object = selection_.selectedObject();
    if (event.button() != Qt::LeftButton || object == nullptr || gesture_)
        return false;
    const QPointF pixel = event.position();
    if (const std::optional<WindowPart> part = windowPartAt(pixel)) {
        windowDrag_ = WindowDrag{*part, *shownWindow_, valueAt(pixel).first};
    } else if (drawAction_->isChecked() && plotArea().contains(pixel.toPoint())) {
        stroke_ = Stroke{object->track.sketch.magnitude, {}};
    } else {
        return false; // QCustomPlot pans
    }
    gesture_.emplace(document_);
    gestureObject_ = object->id;
    if (stroke_)
        extendStroke(pixel);
    return true;
}

bool MagnitudePlot::moved(const QMouseEvent& event)
{
    if (windowDrag_) {
        dragWindow(event.position());
        return true;
    }
    if (stroke_) {
        extendStroke(event.position());
        return true;
    }
    if (event.buttons() == Qt::NoButton)
        updateHoverCursor(event.position());
    else if (event.buttons().testFlag(Qt::LeftButton) && panAction_->isChecked())
        viewMovedByHand_ = true; // QCustomPlot pans
    return false;
}

bool MagnitudePlot::released(const QMouseEvent& event)
{
    if (event.button() != Qt::LeftButton || !gesture_)
        return false;
    endGesture();
    // The height held still under the pen now follows what was drawn.
    followCurvesHeight();
    plot_->replot();
    return true;
}

std::optional<MagnitudePlot::WindowPart> MagnitudePlot::windowPartAt(const QPointF& pixel) const
{
    const QRect area = plotArea();
    if (!shownWindow_ || pixel.y() < area.top() || pixel.y() > area.bottom())
        return std::nullopt;
    // The pen draws over the window the fit would take by itself, whose edges are often the keys'
    // first and last, where a stroke starts; the Pan tool, or a window of the sketch's own, grabs it.
    if (drawAction_->isChecked() && !shownWindowIsOwn_)
        return std::nullopt;
    const double startX = plot_->xAxis->coordToPixel(shownWindow_->first);
    const double endX = plot_->xAxis->coordToPixel(shownWindow_->second);
    if (std::abs(pixel.x() - startX) <= kEdgeReach)
        return WindowPart::Start;
    if (std::abs(pixel.x() - endX) <= kEdgeReach)
        return WindowPart::End;
    if (pixel.x() > startX && pixel.x() < endX && pixel.y() <= area.top() + kGripHeight)
        return WindowPart::Grip;
    return std::nullopt;
}

void MagnitudePlot::updateHoverCursor(const QPointF& pixel)
{
    const std::optional<WindowPart> part = windowPartAt(pixel);
    if (!part)
        showToolCursor();
    else
        plot_->setCursor(*part == WindowPart::Grip ? Qt::SizeAllCursor : Qt::SizeHorCursor);
}

void MagnitudePlot::dragWindow(const QPointF& pixel)
{
    const model::SceneObject* object = document_.object(gestureObject_);
    const std::optional<std::pair<double, double>> keys = object ? keySpan(object->track) : std::nullopt;
    if (!keys || keys->second <= keys->first)
        return;
    // At least a frame long, and inside the keys' span, where the fit can edit.
    const double shortest = std::min(1.0 / document_.scene().fps, keys->second - keys->first);
    const double delta = valueAt(pixel).first - windowDrag_->pressTime;
    auto [start, end] = windowDrag_->original;
    start = std::clamp(start, keys->first, keys->second - shortest);
    end = std::clamp(end, start + shortest, keys->second);
    switch (windowDrag_->part) {
    case WindowPart::Start:
        start = std::clamp(start + delta, keys->first, end - shortest);
        break;
    case WindowPart::End:
        end = std::clamp(end + delta, start + shortest, keys->second);
        break;
    case WindowPart::Grip: {
        const double length = end - start;
        start = std::clamp(start + delta, keys->first, keys->second - length);
        end = start + length;
        break;
    }
    }
    const std::pair window(start, end);
    if (object->track.sketch.window != window)
        gesture_->push(new model::SetFitWindowCommand(document_, gestureObject_, window));
}

void MagnitudePlot::extendStroke(const QPointF& pixel)
{
    const model::Scene& scene = document_.scene();
    const auto [time, magnitude] = valueAt(pixel);
    const model::MagnitudePoint point{std::clamp(time, scene.startTime, scene.endTime), std::max(0.0, magnitude)};
    // Time only goes forward: going back erases what this stroke drew from there on.
    std::vector<model::MagnitudePoint>& drawn = stroke_->drawn;
    while (!drawn.empty() && drawn.back().time >= point.time)
        drawn.pop_back();
    drawn.push_back(point);
    // A single point spans no time and draws nothing; if the stroke had drawn, it takes that back.
    if (drawn.size() < 2 && !gesture_->hasStep())
        return;
    std::vector<model::MagnitudePoint> curve = drawn.size() < 2 ? stroke_->before : withStroke(stroke_->before, drawn);
    gesture_->push(new model::SetMagnitudeCurveCommand(document_, gestureObject_, std::move(curve)));
}

void MagnitudePlot::endGesture()
{
    gesture_.reset();
    gestureObject_ = model::kNoObject;
    windowDrag_.reset();
    stroke_.reset();
}

} // namespace gyre::app
