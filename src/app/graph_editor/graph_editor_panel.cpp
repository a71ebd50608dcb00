#include "app/graph_editor/graph_editor_panel.h"

#include "app/euler_convention_choosers.h"
#include "core/quaternion_math.h"
#include "model/commands/replace_keyframes_command.h"
#include "model/commands/set_keyframe_orientation_command.h"
#include "model/key_edits.h"
#include "model/object_mass.h"

#include <QAction>
#include <QComboBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QListView>
#include <QSplitter>
#include <QToolButton>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <numbers>
#include <stdexcept>

namespace gyre::app {

namespace {

using model::Channel;

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
constexpr int kMinimumPlotWidth = 320;
constexpr int kMinimumPlotHeight = 200;
constexpr double kKeyMarkerPixels = 7.0;
// Room above and below the framed curves, as a factor of their span.
constexpr double kFrameMargin = 1.1;

QPen channelPen(Channel channel)
{
    // x, y, z in red, green, blue throughout; the kind of channel by the line's dashes. One pixel wide:
    // QPainter strokes a wider pen as a filled outline, and with a motion capture's curves a replot of
    // the three Euler curves took 350 to 420 ms instead of 30 to 45 (tst_view_drawing, Release).
    const std::array<QColor, 4> colours{QColor(214, 39, 40), QColor(44, 160, 44), QColor(31, 119, 180),
                                        QColor(90, 90, 90)};
    const auto index = static_cast<int>(channel);
    if (model::isEulerChannel(channel))
        return QPen(colours[static_cast<std::size_t>(index)], 1.0);
    if (channel <= Channel::QuaternionZ) {
        // w grey, then x, y, z.
        const int component = index - static_cast<int>(Channel::QuaternionW);
        return QPen(colours[static_cast<std::size_t>((component + 3) % 4)], 1.0, Qt::DashLine);
    }
    if (channel <= Channel::AngularSpeed) {
        const int component = index - static_cast<int>(Channel::AngularVelocityX);
        return QPen(colours[static_cast<std::size_t>(component)], 1.0, Qt::DotLine);
    }
    if (channel <= Channel::PositionZ) {
        const int component = index - static_cast<int>(Channel::PositionX);
        return QPen(colours[static_cast<std::size_t>(component)], 1.0, Qt::DashDotLine);
    }
    if (channel <= Channel::AngularMomentumMagnitude) {
        const int component = index - static_cast<int>(Channel::AngularMomentumX);
        return QPen(colours[static_cast<std::size_t>(component)], 1.0, Qt::DashDotDotLine);
    }
    return QPen(QColor(230, 120, 20), 1.0); // the kinetic energy, alone in orange
}

bool isFrameAllKey(const QKeyEvent& event)
{
    return event.key() == Qt::Key_Home && event.modifiers() == Qt::NoModifier;
}

} // namespace

GraphEditorPanel::GraphEditorPanel(model::Document& document, Selection& selection, QWidget* parent)
    : QWidget(parent)
    , document_(document)
    , selection_(selection)
    , selectedTrack_(document, selection)
    , plot_(new QCustomPlot(this))
    , sampler_(
          *this, selection, document,
          [this](const std::shared_ptr<const model::SharedTrackMotion>& motion, const model::Scene&) {
              // The body's mesh, for its inertia, which the job computes if no view has yet.
              model::SceneObject body;
              if (const model::SceneObject* object = document_.object(selection_.object())) {
                  body.mesh = object->mesh;
                  body.massOverride = object->massOverride;
              }
              return [motion, settings = settings(), body = std::move(body)]() mutable {
                  settings.inertia = model::objectMassProperties(body).properties.inertia;
                  return model::sampleChannels(motion->motion(), motion->track().keys, settings);
              };
          },
          [this](const model::ChannelCurves& curves) { showCurves(curves); })
{
    channelList_ = new QListView(this);
    channelList_->setObjectName(QStringLiteral("graphChannelList"));
    channelList_->setModel(&channels_);
    channelList_->setToolTip(tr("The channels to plot: check one to show its curve"));
    channelList_->setMinimumWidth(channelList_->sizeHintForColumn(0) + 24);

    auto* splitter = new QSplitter(this);
    splitter->addWidget(channelList_);
    splitter->addWidget(plot_);
    splitter->setStretchFactor(1, 1);
    plot_->setMinimumSize(kMinimumPlotWidth, kMinimumPlotHeight);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(makeChoosers());
    layout->addWidget(splitter, 1);
    setUpPlot();

    connect(&channels_, &ChannelListModel::shownChanged, this, &GraphEditorPanel::showChannel);
    connect(&selectedTrack_, &SelectedTrack::changed, this, [this](model::Changes changes) {
        if (changes & (SelectedTrack::kAnotherObject | model::Change::Scene)) {
            releasePlot(); // the held key is another object's now
            if (transform_)
                finishTransform(true);
        }
        if (changes & (model::kMotionChanges | model::Change::SceneSettings))
            sampler_.schedule();
    });
    connect(&selection_, &Selection::changed, this, [this] {
        showSelectedKeys();
        plot_->replot();
    });
    sampler_.schedule();
}

QWidget* GraphEditorPanel::makeChoosers()
{
    auto* row = new QWidget(this);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(6, 2, 6, 2);
    orderChooser_ = new QComboBox(row);
    orderChooser_->setObjectName(QStringLiteral("graphEulerOrderCombo"));
    frameChooser_ = new QComboBox(row);
    frameChooser_->setObjectName(QStringLiteral("graphEulerFrameCombo"));
    fillConventionChoosers(*orderChooser_, *frameChooser_);
    orderChooser_->setToolTip(tr("The order of the Euler angles, as the inspector shows them"));
    auto* orderLabel = new QLabel(tr("Euler &order:"), row);
    orderLabel->setBuddy(orderChooser_);
    velocityFrameChooser_ = new QComboBox(row);
    velocityFrameChooser_->setObjectName(QStringLiteral("graphVelocityFrameCombo"));
    velocityFrameChooser_->addItem(tr("world frame"), static_cast<int>(model::VelocityFrame::World));
    velocityFrameChooser_->addItem(tr("object's frame"), static_cast<int>(model::VelocityFrame::Local));
    velocityFrameChooser_->setToolTip(tr("The frame the angular velocity's and angular momentum's components are given in"));
    auto* velocityLabel = new QLabel(tr("ω &in:"), row);
    velocityLabel->setBuddy(velocityFrameChooser_);

    // Home is View ▸ Frame Scene's in the rest of the window: the plot takes it as a key while it has
    // the focus (event), not as a second shortcut, which Qt would find ambiguous and run neither.
    frameAll_ = new QAction(tr("Frame &All"), this);
    frameAll_->setToolTip(tr("Show the whole time range and every shown curve (Home)"));
    frameSelected_ = new QAction(tr("Frame &Selected"), this);
    frameSelected_->setShortcut(Qt::Key_F);
    frameSelected_->setStatusTip(tr("Show the selected key between its neighbours"));
    for (QAction* action : {frameAll_, frameSelected_}) {
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        addAction(action);
        auto* button = new QToolButton(row);
        button->setDefaultAction(action);
        layout->addWidget(button);
    }
    moveKeys_ = new QAction(tr("&Move Keys"), this);
    moveKeys_->setShortcut(Qt::Key_G);
    moveKeys_->setStatusTip(tr("Move the selected keys with the pointer; click to keep, Esc to cancel"));
    scaleKeys_ = new QAction(tr("&Scale Keys"), this);
    scaleKeys_->setShortcut(Qt::Key_S);
    scaleKeys_->setStatusTip(tr("Scale the selected keys' times about the current frame; click to keep, Esc to cancel"));
    // On the plot alone: G and S typed into a chooser above it choose.
    for (QAction* action : {moveKeys_, scaleKeys_}) {
        action->setShortcutContext(Qt::WidgetShortcut);
        plot_->addAction(action);
    }
    connect(moveKeys_, &QAction::triggered, this, [this] { beginTransform(false); });
    connect(scaleKeys_, &QAction::triggered, this, [this] { beginTransform(true); });
    connect(frameAll_, &QAction::triggered, this, &GraphEditorPanel::frameAll);
    connect(frameSelected_, &QAction::triggered, this, &GraphEditorPanel::frameSelectedKey);

    layout->addStretch();
    layout->addWidget(orderLabel);
    layout->addWidget(orderChooser_);
    layout->addWidget(frameChooser_);
    layout->addWidget(velocityLabel);
    layout->addWidget(velocityFrameChooser_);
    for (QComboBox* chooser : {orderChooser_, frameChooser_, velocityFrameChooser_})
        connect(chooser, &QComboBox::currentIndexChanged, this, [this] {
            channels_.setConvention(chosenConvention(*orderChooser_, *frameChooser_));
            sampler_.schedule();
        });
    return row;
}

bool GraphEditorPanel::event(QEvent* event)
{
    if (event->type() == QEvent::ShortcutOverride && isFrameAllKey(*static_cast<QKeyEvent*>(event))) {
        event->accept(); // comes as a key press instead of the window's shortcut
        return true;
    }
    return QWidget::event(event);
}

void GraphEditorPanel::keyPressEvent(QKeyEvent* event)
{
    if (transform_ && event->key() == Qt::Key_Escape)
        finishTransform(false);
    else if (transform_ && (event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter))
        finishTransform(true);
    else if (isFrameAllKey(*event))
        frameAll();
    else
        QWidget::keyPressEvent(event);
}

void GraphEditorPanel::setUpPlot()
{
    plot_->setFocusPolicy(Qt::ClickFocus);
    plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    plot_->xAxis->setLabel(tr("time (s)"));
    plot_->legend->setVisible(true);
    plot_->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    for (std::size_t c = 0; c < model::kChannelCount; ++c) {
        const auto channel = static_cast<Channel>(c);
        QCPGraph* graph = plot_->addGraph();
        graph->setPen(channelPen(channel));
        graphs_[c] = graph;
        QCPGraph* keys = plot_->addGraph();
        keys->setLineStyle(QCPGraph::lsNone);
        keys->removeFromLegend();
        keyGraphs_[c] = keys;
        QCPGraph* selected = plot_->addGraph();
        selected->setLineStyle(QCPGraph::lsNone);
        selected->removeFromLegend();
        selectedKeyGraphs_[c] = selected;
        showChannel(channel, channels_.isShown(channel));
    }
    connect(plot_->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, &GraphEditorPanel::showKeyMarkers);
    showKeyMarkers();
    connect(plot_, &QCustomPlot::mousePress, this, &GraphEditorPanel::pressPlot);
    connect(plot_, &QCustomPlot::mouseMove, this, &GraphEditorPanel::movePlot);
    connect(plot_, &QCustomPlot::mouseRelease, this, &GraphEditorPanel::releasePlot);
    connect(plot_->selectionRect(), &QCPSelectionRect::accepted, this,
            [this](const QRect& box, QMouseEvent*) { selectKeysIn(box); });
    plot_->setMouseTracking(true); // G and S follow the pointer with no button held
}

model::ChannelSettings GraphEditorPanel::settings() const
{
    const model::Scene& scene = document_.scene();
    return {chosenConvention(*orderChooser_, *frameChooser_),
            static_cast<model::VelocityFrame>(velocityFrameChooser_->currentData().toInt()), scene.startTime,
            scene.endTime, kSampleCount};
}

void GraphEditorPanel::showCurves(const model::ChannelCurves& curves)
{
    curves_ = curves;
    // Another object's curves are framed whole; the same object's keep the artist's view, as a drag
    // needs.
    const bool anotherObject = shownObject_ != selection_.object();
    shownObject_ = selection_.object();
    const QVector<double> times(curves.times.begin(), curves.times.end());
    for (std::size_t c = 0; c < model::kChannelCount; ++c) {
        const auto channel = static_cast<Channel>(c);
        graphs_[c]->setName(channels_.name(channel));
        const std::vector<double>& values = curves.values[c];
        graphs_[c]->setData(times, QVector<double>(values.begin(), values.end()), true);
        QVector<double> keyTimes;
        QVector<double> keyValues;
        for (std::size_t k = 0; k < curves.keySamples.size(); ++k) {
            const std::size_t sample = curves.keySamples[k].first;
            keyTimes.push_back(curves.times[sample]);
            // The quaternion channels show each key as stored, which the Euler filter may flip.
            const bool quaternion = channel >= Channel::QuaternionW && channel <= Channel::QuaternionZ;
            keyValues.push_back(quaternion ? curves.keyQuaternions[k][c - static_cast<std::size_t>(Channel::QuaternionW)]
                                           : values[sample]);
        }
        keyGraphs_[c]->setData(keyTimes, keyValues, true);
    }
    keyTimes_.clear();
    for (const auto& [sample, key] : curves.keySamples)
        keyTimes_.push_back(curves.times[sample]);
    showKeyMarkers();
    showSelectedKeys();
    showGimbalZones(curves.gimbalZones);
    if (anotherObject)
        frameAll();
    plot_->replot();
    emit curvesUpdated();
}

void GraphEditorPanel::showKeyMarkers()
{
    const QCPRange shown = plot_->xAxis->range();
    const auto first = std::lower_bound(keyTimes_.begin(), keyTimes_.end(), shown.lower);
    const auto last = std::upper_bound(first, keyTimes_.end(), shown.upper);
    // The widget's width rather than the axis rect's, which is laid out only at the first replot.
    const bool apart = static_cast<double>(last - first) * kKeyMarkerPixels <= plot_->width();
    if (apart == keyMarkersShown_)
        return;
    keyMarkersShown_ = apart;
    for (std::size_t c = 0; c < model::kChannelCount; ++c) {
        const QColor colour = channelPen(static_cast<Channel>(c)).color();
        keyGraphs_[c]->setScatterStyle(apart ? QCPScatterStyle(QCPScatterStyle::ssDiamond, colour, Qt::white,
                                                               kKeyMarkerPixels)
                                             : QCPScatterStyle(QCPScatterStyle::ssNone));
        // Selected keys filled, and larger.
        selectedKeyGraphs_[c]->setScatterStyle(apart ? QCPScatterStyle(QCPScatterStyle::ssDiamond, colour, colour,
                                                                       kKeyMarkerPixels + 3.0)
                                                     : QCPScatterStyle(QCPScatterStyle::ssNone));
    }
}

void GraphEditorPanel::showGimbalZones(const std::vector<std::pair<double, double>>& zones)
{
    for (QCPItemRect* zone : gimbalZones_)
        plot_->removeItem(zone);
    gimbalZones_.clear();
    for (const auto& [from, to] : zones) {
        auto* zone = new QCPItemRect(plot_);
        zone->setLayer(QStringLiteral("grid")); // under the curves
        zone->setPen(Qt::NoPen);
        zone->setBrush(QColor(255, 140, 0, 50));
        // The whole height of the plot, over the zone's time.
        for (QCPItemPosition* corner : {zone->topLeft, zone->bottomRight}) {
            corner->setTypeX(QCPItemPosition::ptPlotCoords);
            corner->setTypeY(QCPItemPosition::ptAxisRectRatio);
        }
        zone->topLeft->setCoords(from, 0.0);
        zone->bottomRight->setCoords(to, 1.0);
        gimbalZones_.push_back(zone);
    }
}

void GraphEditorPanel::showChannel(Channel channel, bool shown)
{
    QCPGraph* graph = graphs_[static_cast<std::size_t>(channel)];
    graph->setVisible(shown);
    keyGraphs_[static_cast<std::size_t>(channel)]->setVisible(shown);
    selectedKeyGraphs_[static_cast<std::size_t>(channel)]->setVisible(shown);
    if (shown)
        graph->addToLegend();
    else
        graph->removeFromLegend();
    plot_->replot();
}

void GraphEditorPanel::rescaleValues(bool inTimeRange)
{
    bool first = true;
    for (QCPGraph* graph : graphs_) {
        if (!graph->visible() || graph->dataCount() == 0)
            continue;
        graph->rescaleValueAxis(!first, inTimeRange);
        first = false;
    }
    if (!first)
        plot_->yAxis->scaleRange(kFrameMargin);
}

void GraphEditorPanel::frameAll()
{
    const model::Scene& scene = document_.scene();
    plot_->xAxis->setRange(scene.startTime, scene.endTime);
    rescaleValues(false);
    plot_->replot();
}

void GraphEditorPanel::frameSelectedKey()
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr || !selection_.key() || curves_.keySamples.empty())
        return;
    const auto& keys = object->track.keys;
    const std::size_t key = *selection_.key();
    const model::Scene& scene = document_.scene();
    const double from = key > 0 ? keys[key - 1].time : std::min(scene.startTime, keys[key].time);
    const double to = key + 1 < keys.size() ? keys[key + 1].time : std::max(scene.endTime, keys[key].time);
    plot_->xAxis->setRange(from, to);
    rescaleValues(true);
    plot_->replot();
}

std::optional<std::pair<Channel, std::size_t>> GraphEditorPanel::keyAt(const QPointF& position) const
{
    std::optional<std::pair<Channel, std::size_t>> nearest;
    double nearestDistance = kKeyGrabPixels;
    for (const Channel channel : {Channel::EulerFirst, Channel::EulerSecond, Channel::EulerThird}) {
        const QCPGraph* keys = keyGraph(channel);
        if (!keys->visible() || !keyMarkersShown_)
            continue;
        for (int k = 0; k < keys->dataCount(); ++k) {
            const QPointF drawn(plot_->xAxis->coordToPixel(keys->data()->at(k)->key),
                                plot_->yAxis->coordToPixel(keys->data()->at(k)->value));
            const double distance = QLineF(drawn, position).length();
            if (distance <= nearestDistance) {
                nearestDistance = distance;
                nearest = {channel, curves_.keySamples[static_cast<std::size_t>(k)].second};
            }
        }
    }
    return nearest;
}

void GraphEditorPanel::pressPlot(QMouseEvent* event)
{
    if (transform_) {
        finishTransform(event->button() == Qt::LeftButton); // a right click cancels
        return;
    }
    // The plot draws a box for this press only if it begins a Shift+drag off the keys (selectKeysIn).
    plot_->setSelectionRectMode(QCP::srmNone);
    if (event->button() != Qt::LeftButton || shownObject_ != selection_.object())
        return;
    const auto held = keyAt(event->position());
    const model::SceneObject* object = selection_.selectedObject();
    const bool heldKey = held && object != nullptr && held->second < object->track.keys.size();
    if (event->modifiers().testFlag(Qt::ShiftModifier)) {
        if (heldKey) {
            lastAngle_ = model::eulerIndex(held->first);
            selection_.toggleKey(object->id, held->second);
        } else {
            plot_->setSelectionRectMode(QCP::srmCustom);
        }
        return;
    }
    if (!heldKey)
        return;
    const auto [channel, key] = *held;
    lastAngle_ = model::eulerIndex(channel);
    const auto sample = std::find_if(curves_.keySamples.begin(), curves_.keySamples.end(),
                                     [key](const auto& keySample) { return keySample.second == key; });
    KeyDrag drag;
    drag.object = object->id;
    drag.key = key;
    drag.angle = model::eulerIndex(channel);
    for (int angle = 0; angle < 3; ++angle)
        drag.pressAngles[angle] = curves_.values[static_cast<std::size_t>(angle)][sample->first];
    drag.pressOrientation = object->track.keys[key].pose.orientation;
    drag.pressValue = plot_->yAxis->pixelToCoord(event->position().y());
    drag.gesture = std::make_unique<model::Gesture>(document_);
    drag_ = std::move(drag);
    // The plot pans on a drag that begins off a key; this one moves the key.
    plot_->setInteraction(QCP::iRangeDrag, false);
    selection_.selectKey(drag_->object, key);
}

void GraphEditorPanel::movePlot(QMouseEvent* event)
{
    pointer_ = event->position();
    if (transform_)
        updateTransform(pointer_);
    if (!drag_ || !(event->buttons() & Qt::LeftButton))
        return;
    Eigen::Vector3d angles = drag_->pressAngles;
    angles[drag_->angle] += plot_->yAxis->pixelToCoord(event->position().y()) - drag_->pressValue;
    const EulerConvention convention = chosenConvention(*orderChooser_, *frameChooser_);
    // Kept in the stored key's hemisphere: the drag turns the key, it does not flip its sign.
    const Eigen::Quaterniond orientation =
        alignedWith(quaternionFromEulerAngles(angles * kRadiansPerDegree, convention), drag_->pressOrientation);
    drag_->gesture->push(
        new model::SetKeyframeOrientationCommand(document_, drag_->object, drag_->key, orientation));
}

void GraphEditorPanel::releasePlot()
{
    if (!drag_)
        return;
    drag_.reset(); // finishes the gesture
    plot_->setInteraction(QCP::iRangeDrag, true);
}

void GraphEditorPanel::showSelectedKeys()
{
    for (std::size_t c = 0; c < model::kChannelCount; ++c) {
        QVector<double> times;
        QVector<double> values;
        const QCPGraph* keys = keyGraphs_[c];
        for (int k = 0; k < keys->dataCount() && static_cast<std::size_t>(k) < curves_.keySamples.size(); ++k) {
            if (selection_.isKeySelected(shownObject_, curves_.keySamples[static_cast<std::size_t>(k)].second)) {
                times.push_back(keys->data()->at(k)->key);
                values.push_back(keys->data()->at(k)->value);
            }
        }
        selectedKeyGraphs_[c]->setData(times, values, true);
    }
}

void GraphEditorPanel::selectKeysIn(const QRect& box)
{
    if (shownObject_ != selection_.object() || !keyMarkersShown_)
        return;
    std::set<KeyRef> inside;
    for (std::size_t c = 0; c < model::kChannelCount; ++c) {
        const QCPGraph* keys = keyGraphs_[c];
        if (!keys->visible())
            continue;
        for (int k = 0; k < keys->dataCount() && static_cast<std::size_t>(k) < curves_.keySamples.size(); ++k) {
            const QPointF drawn(plot_->xAxis->coordToPixel(keys->data()->at(k)->key),
                                plot_->yAxis->coordToPixel(keys->data()->at(k)->value));
            if (QRectF(box.normalized()).contains(drawn))
                inside.insert({shownObject_, curves_.keySamples[static_cast<std::size_t>(k)].second});
        }
    }
    selection_.selectKeys(inside, true);
}

void GraphEditorPanel::beginTransform(bool scale)
{
    const model::SceneObject* object = selection_.selectedObject();
    if (transform_ || drag_ || object == nullptr || shownObject_ != object->id)
        return;
    KeyTransform transform;
    transform.selected = selection_.keysOf(object->id);
    if (transform.selected.empty())
        return;
    transform.scale = scale;
    transform.object = object->id;
    transform.keys = object->track.keys;
    // Each selected key's angles as drawn: the unwrapped ones at its sample.
    for (std::size_t key : transform.selected) {
        const auto sample = std::find_if(curves_.keySamples.begin(), curves_.keySamples.end(),
                                         [key](const auto& keySample) { return keySample.second == key; });
        if (sample == curves_.keySamples.end())
            return; // the curves are not those of these keys yet
        Eigen::Vector3d angles;
        for (int angle = 0; angle < 3; ++angle)
            angles[angle] = curves_.values[static_cast<std::size_t>(angle)][sample->first];
        transform.angles.push_back(angles);
    }
    transform.angle = lastAngle_;
    transform.start = pointer_;
    transform.gesture = std::make_unique<model::Gesture>(document_);
    transform_ = std::move(transform);
    plot_->setInteraction(QCP::iRangeDrag, false);
}

void GraphEditorPanel::updateTransform(const QPointF& pointer)
{
    const model::SceneObject* object = document_.object(transform_->object);
    if (object == nullptr || object->track.keys.size() != transform_->keys.size()) {
        finishTransform(true); // the keys changed under it (an undo elsewhere): nothing left to move
        return;
    }
    const model::Scene& scene = document_.scene();
    const auto frame = [&scene](double seconds) { return std::round(seconds * scene.fps) / scene.fps; };
    const double fromTime = plot_->xAxis->pixelToCoord(transform_->start.x());
    const double toTime = plot_->xAxis->pixelToCoord(pointer.x());
    std::optional<std::vector<model::Keyframe>> keys;
    if (transform_->scale) {
        // t′ = c + f·(t − c) about the current time c, f the pointer's distance from c over where it began.
        const double pivot = scene.currentTime;
        const double factor = std::abs(fromTime - pivot) > 1e-12 ? (toTime - pivot) / (fromTime - pivot) : 1.0;
        if (factor <= 0.0)
            return;
        keys = model::retimedKeys(transform_->keys, transform_->selected,
                                  [&](double time) { return frame(pivot + factor * (time - pivot)); }, 0.5 / scene.fps);
        const auto outsideScene = [&](std::size_t index) {
            const double time = (*keys)[index].time;
            return time < scene.startTime || time > scene.endTime;
        };
        // The keys would cross or meet, or leave the scene's range (as a move cannot): they stay where they were last.
        if (!keys || std::any_of(transform_->selected.begin(), transform_->selected.end(), outsideScene))
            return;
    } else {
        const auto [lower, upper] = model::shiftRange(transform_->keys, transform_->selected, 1.0 / scene.fps,
                                                      scene.startTime, scene.endTime);
        const double shift = lower <= upper ? std::clamp(frame(toTime - fromTime), lower, upper) : 0.0;
        keys = model::shiftedKeys(transform_->keys, transform_->selected, shift);
        if (transform_->angle) {
            const double raised =
                plot_->yAxis->pixelToCoord(pointer.y()) - plot_->yAxis->pixelToCoord(transform_->start.y());
            const EulerConvention convention = chosenConvention(*orderChooser_, *frameChooser_);
            for (std::size_t i = 0; i < transform_->selected.size(); ++i) {
                Eigen::Vector3d angles = transform_->angles[i];
                angles[*transform_->angle] += raised;
                Eigen::Quaterniond& orientation = (*keys)[transform_->selected[i]].pose.orientation;
                orientation = alignedWith(quaternionFromEulerAngles(angles * kRadiansPerDegree, convention), orientation);
            }
        }
    }
    using Edit = model::ReplaceKeyframesCommand::Edit;
    transform_->gesture->push(new model::ReplaceKeyframesCommand(
        document_, {{transform_->object, std::move(*keys)}}, transform_->scale ? Edit::Scale : Edit::Move));
}

void GraphEditorPanel::finishTransform(bool keep)
{
    const model::SceneObject* object = document_.object(transform_->object);
    const bool sameKeys = object != nullptr && object->track.keys.size() == transform_->keys.size();
    if (!keep && sameKeys && transform_->gesture->hasStep()) {
        // Back to the keys from before: merged into the gesture's step, which then changes nothing and goes.
        using Edit = model::ReplaceKeyframesCommand::Edit;
        transform_->gesture->push(new model::ReplaceKeyframesCommand(
            document_, {{transform_->object, transform_->keys}}, transform_->scale ? Edit::Scale : Edit::Move));
    }
    transform_.reset(); // finishes the gesture
    plot_->setInteraction(QCP::iRangeDrag, true);
}

} // namespace gyre::app
