#include "app/smoothness_panel.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <cstddef>
#include <stdexcept>
#include <utility>

namespace gyre::app {

namespace {

constexpr double kLargestCoordinate = 1e6;
constexpr int kMinimumPlotWidth = 240;
constexpr int kMinimumPlotHeight = 300;
const std::array<const char*, 3> kPointBoxNames{"pointXBox", "pointYBox", "pointZBox"};
// The cursor has a buffered layer of its own, so that moving it at playback's 60 Hz repaints one
// line rather than 12 curves of 2000 points.
const char* const kCursorLayer = "cursor";

QString quantityLabel(SmoothnessPanel::Quantity quantity)
{
    switch (quantity) {
    case SmoothnessPanel::Quantity::Position:
        return SmoothnessPanel::tr("position\n(units)");
    case SmoothnessPanel::Quantity::Velocity:
        return SmoothnessPanel::tr("velocity\n(units/s)");
    case SmoothnessPanel::Quantity::Acceleration:
        return SmoothnessPanel::tr("acceleration\n(units/s²)");
    }
    return {};
}

QString componentName(SmoothnessPanel::Component component)
{
    switch (component) {
    case SmoothnessPanel::Component::X:
        return SmoothnessPanel::tr("x");
    case SmoothnessPanel::Component::Y:
        return SmoothnessPanel::tr("y");
    case SmoothnessPanel::Component::Z:
        return SmoothnessPanel::tr("z");
    case SmoothnessPanel::Component::Magnitude:
        return SmoothnessPanel::tr("magnitude");
    }
    return {};
}

QPen componentPen(SmoothnessPanel::Component component)
{
    switch (component) {
    case SmoothnessPanel::Component::X:
        return QPen(QColor(214, 39, 40), 1.5);
    case SmoothnessPanel::Component::Y:
        return QPen(QColor(44, 160, 44), 1.5);
    case SmoothnessPanel::Component::Z:
        return QPen(QColor(31, 119, 180), 1.5);
    case SmoothnessPanel::Component::Magnitude:
        return QPen(QColor(90, 90, 90), 1.5, Qt::DashLine);
    }
    return {};
}

const std::vector<Eigen::Vector3d>& samplesOf(const model::PointTrajectory& trajectory, SmoothnessPanel::Quantity quantity)
{
    switch (quantity) {
    case SmoothnessPanel::Quantity::Position:
        return trajectory.positions;
    case SmoothnessPanel::Quantity::Velocity:
        return trajectory.velocities;
    case SmoothnessPanel::Quantity::Acceleration:
        break;
    }
    return trajectory.accelerations;
}

double componentOf(const Eigen::Vector3d& value, SmoothnessPanel::Component component)
{
    return component == SmoothnessPanel::Component::Magnitude ? value.norm()
                                                              : value[static_cast<Eigen::Index>(component)];
}

} // namespace

SmoothnessPanel::SmoothnessPanel(model::Document& document, Selection& selection, QWidget* parent)
    : QWidget(parent)
    , document_(document)
    , selectedTrack_(document, selection)
    , cursorReplot_(*this, 0, [this] { plot_->layer(QString::fromLatin1(kCursorLayer))->replot(); })
    , plot_(new QCustomPlot(this))
    , sampler_(
          *this, selection, document,
          [this](const std::shared_ptr<const model::SharedTrackMotion>& motion, const model::Scene& scene) {
              return [motion, localPoint = point(), start = scene.startTime, end = scene.endTime] {
                  return model::samplePointTrajectory(motion->motion(), localPoint, start, end, kSampleCount);
              };
          },
          [this](const model::PointTrajectory& trajectory) { showTrajectory(trajectory); })
{
    auto* pointRow = new QHBoxLayout;
    pointRow->setContentsMargins(6, 2, 6, 2);
    auto* pointLabel = new QLabel(tr("Point of the object (local):"), this);
    pointRow->addWidget(pointLabel);
    const std::array<QString, 3> axisNames{tr("x"), tr("y"), tr("z")};
    for (std::size_t axis = 0; axis < pointBoxes_.size(); ++axis) {
        auto* box = new QDoubleSpinBox(this);
        box->setRange(-kLargestCoordinate, kLargestCoordinate);
        box->setDecimals(3);
        box->setPrefix(tr("%1 ").arg(axisNames[axis]));
        box->setKeyboardTracking(false);
        box->setObjectName(QString::fromLatin1(kPointBoxNames[axis]));
        box->setToolTip(tr("The %1 coordinate of the plotted point, in the object's frame").arg(axisNames[axis]));
        connect(box, &QDoubleSpinBox::valueChanged, this, [this] { sampler_.schedule(); });
        pointRow->addWidget(box);
        pointBoxes_[axis] = box;
    }
    pointLabel->setBuddy(pointBoxes_[0]);
    pointRow->addStretch();

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(pointRow);
    layout->addWidget(plot_, 1);
    // Room for three stacked plots, and never an empty size, for which QCustomPlot cannot paint.
    plot_->setMinimumSize(kMinimumPlotWidth, kMinimumPlotHeight);
    setUpPlot();

    // Any change of the track's motion (a fit included), of the time range, or another track.
    connect(&selectedTrack_, &SelectedTrack::changed, this, [this](model::Changes changes) {
        if (changes & (model::kMotionChanges | model::Change::SceneSettings))
            sampler_.schedule();
    });
    connect(&document_, &model::Document::currentTimeChanged, this, &SmoothnessPanel::moveCursor);
    sampler_.schedule();
}

Eigen::Vector3d SmoothnessPanel::point() const
{
    return {pointBoxes_[0]->value(), pointBoxes_[1]->value(), pointBoxes_[2]->value()};
}

QCPGraph* SmoothnessPanel::graph(Quantity quantity, Component component) const
{
    return graphs_[static_cast<std::size_t>(quantity)][static_cast<std::size_t>(component)];
}

void SmoothnessPanel::setUpPlot()
{
    plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    plot_->setAutoAddPlottableToLegend(false);
    plot_->plotLayout()->clear(); // drops the default axis rect and its legend: three of our own instead
    auto* margins = new QCPMarginGroup(plot_);
    for (std::size_t q = 0; q < kQuantityCount; ++q) {
        auto* rect = new QCPAxisRect(plot_);
        plot_->plotLayout()->addElement(static_cast<int>(q), 0, rect);
        rect->setMarginGroup(QCP::msLeft | QCP::msRight, margins);
        rect->axis(QCPAxis::atLeft)->setLabel(quantityLabel(static_cast<Quantity>(q)));
        // The plots share the time axis: only the bottom one says what it is.
        const bool bottomPlot = q + 1 == kQuantityCount;
        rect->axis(QCPAxis::atBottom)->setLabel(bottomPlot ? tr("time (s)") : QString());
        rect->axis(QCPAxis::atBottom)->setTickLabels(bottomPlot);
        axisRects_[q] = rect;
        for (std::size_t c = 0; c < kComponentCount; ++c) {
            QCPGraph* graph = plot_->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
            graph->setName(componentName(static_cast<Component>(c)));
            graph->setPen(componentPen(static_cast<Component>(c)));
            graphs_[q][c] = graph;
        }
    }

    // One legend, in the top plot, for the colours all three share.
    auto* legend = new QCPLegend;
    axisRects_[0]->insetLayout()->addElement(legend, Qt::AlignTop | Qt::AlignRight);
    legend->setLayer(QStringLiteral("legend"));
    legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    plot_->legend = legend;
    for (QCPGraph* graph : graphs_[0])
        graph->addToLegend(legend);

    // Panning or zooming the time of one plot moves the others' with it.
    for (QCPAxisRect* rect : axisRects_)
        for (QCPAxisRect* other : axisRects_)
            if (other != rect)
                connect(rect->axis(QCPAxis::atBottom), qOverload<const QCPRange&>(&QCPAxis::rangeChanged),
                        other->axis(QCPAxis::atBottom), qOverload<const QCPRange&>(&QCPAxis::setRange));

    plot_->addLayer(QString::fromLatin1(kCursorLayer));
    QCPLayer* cursorLayer = plot_->layer(QString::fromLatin1(kCursorLayer));
    cursorLayer->setMode(QCPLayer::lmBuffered);
    for (std::size_t q = 0; q < kQuantityCount; ++q) {
        auto* cursor = new QCPItemStraightLine(plot_);
        cursor->setLayer(cursorLayer);
        cursor->setClipAxisRect(axisRects_[q]);
        cursor->setPen(QPen(QColor(255, 140, 0), 1.5));
        for (QCPItemPosition* end : {cursor->point1, cursor->point2})
            end->setAxes(axisRects_[q]->axis(QCPAxis::atBottom), axisRects_[q]->axis(QCPAxis::atLeft));
        cursors_[q] = cursor;
    }
}

void SmoothnessPanel::showTrajectory(const model::PointTrajectory& trajectory)
{
    const QVector<double> times(trajectory.times.begin(), trajectory.times.end());
    for (std::size_t q = 0; q < kQuantityCount; ++q) {
        const std::vector<Eigen::Vector3d>& samples = samplesOf(trajectory, static_cast<Quantity>(q));
        for (std::size_t c = 0; c < kComponentCount; ++c) {
            QVector<double> values;
            values.reserve(static_cast<qsizetype>(samples.size()));
            for (const Eigen::Vector3d& sample : samples)
                values.push_back(componentOf(sample, static_cast<Component>(c)));
            graphs_[q][c]->setData(times, values, true);
        }
        // Refit the values every time; the time axis keeps the artist's zoom (showTimeRange).
        axisRects_[q]->axis(QCPAxis::atLeft)->rescale();
        axisRects_[q]->axis(QCPAxis::atLeft)->scaleRange(1.1);
    }
    showTimeRange();
    moveCursor();
    plot_->replot();
    emit curvesUpdated();
}

void SmoothnessPanel::showTimeRange()
{
    // The whole scene, when the time axis has not been zoomed yet or shows a range the scene no
    // longer has.
    const model::Scene& scene = document_.scene();
    const std::pair sceneRange(scene.startTime, scene.endTime);
    if (sceneRange != shownSceneRange_) {
        axisRects_[0]->axis(QCPAxis::atBottom)->setRange(scene.startTime, scene.endTime);
        shownSceneRange_ = sceneRange;
    }
}

void SmoothnessPanel::moveCursor()
{
    const double now = document_.scene().currentTime;
    for (QCPItemStraightLine* cursor : cursors_) {
        cursor->point1->setCoords(now, 0.0);
        cursor->point2->setCoords(now, 1.0);
    }
    cursorReplot_.request();
}

} // namespace gyre::app
