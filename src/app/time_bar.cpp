#include "app/time_bar.h"

#include "model/commands/set_gravity_command.h"
#include "model/commands/set_time_range_command.h"
#include "model/value_checks.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>

#include <cmath>
#include <utility>

namespace gyre::app {

namespace {

constexpr double kLongestRangeSeconds = 1e6;
// Far past any planet's surface gravity (Jupiter's is 24.8 m/s²).
constexpr double kStrongestGravity = 1000.0;

QDoubleSpinBox* makeSecondsBox(QWidget* parent)
{
    auto* box = new QDoubleSpinBox(parent);
    box->setRange(-kLongestRangeSeconds, kLongestRangeSeconds);
    box->setDecimals(3);
    box->setSuffix(TimeBar::tr(" s"));
    // One edit when the artist is done typing, not one per keystroke.
    box->setKeyboardTracking(false);
    return box;
}

} // namespace

TimeBar::TimeBar(model::Document& document, QWidget* parent)
    : QWidget(parent)
    , document_(document)
    , currentTime_(new QLabel(this))
    , currentFrame_(new QLabel(this))
    , fps_(new QDoubleSpinBox(this))
    , startTime_(makeSecondsBox(this))
    , endTime_(makeSecondsBox(this))
    , gravity_(new QDoubleSpinBox(this))
    , up_(new QComboBox(this))
{
    fps_->setRange(1.0, model::kMaxFps);
    fps_->setDecimals(3);
    fps_->setSuffix(tr(" fps"));
    fps_->setKeyboardTracking(false);
    fps_->setObjectName(QStringLiteral("frameRateBox"));
    startTime_->setObjectName(QStringLiteral("startTimeBox"));
    endTime_->setObjectName(QStringLiteral("endTimeBox"));
    gravity_->setRange(0.0, kStrongestGravity);
    gravity_->setDecimals(3);
    gravity_->setSuffix(tr(" m/s²"));
    gravity_->setKeyboardTracking(false);
    gravity_->setObjectName(QStringLiteral("gravityBox"));
    gravity_->setToolTip(tr("How fast the centre of mass of a ballistic track falls"));
    // In the order of model::UpDirection.
    up_->addItems({tr("+X"), tr("−X"), tr("+Y"), tr("−Y"), tr("+Z"), tr("−Z")});
    up_->setObjectName(QStringLiteral("upAxisBox"));
    up_->setToolTip(tr("The scene's up axis: gravity pulls the other way"));
    currentTime_->setObjectName(QStringLiteral("currentTimeLabel"));
    currentFrame_->setObjectName(QStringLiteral("currentFrameLabel"));
    fps_->setToolTip(tr("Frames per second"));
    startTime_->setToolTip(tr("Where the scene starts"));
    endTime_->setToolTip(tr("Where the scene ends"));
    // Room for the widest text the labels show, so the bar does not jitter while playing.
    currentTime_->setMinimumWidth(fontMetrics().horizontalAdvance(tr("Time %1 s").arg(-9999.999, 0, 'f', 3)));
    currentFrame_->setMinimumWidth(fontMetrics().horizontalAdvance(tr("Frame %1").arg(-9999999)));

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(6, 2, 6, 2);
    layout->addWidget(currentTime_);
    layout->addWidget(currentFrame_);
    layout->addStretch();
    for (auto [label, box] : {std::pair<QString, QWidget*>{tr("Rate"), fps_}, std::pair<QString, QWidget*>{tr("Start"), startTime_},
                              std::pair<QString, QWidget*>{tr("End"), endTime_}, std::pair<QString, QWidget*>{tr("Gravity"), gravity_},
                              std::pair<QString, QWidget*>{tr("Up"), up_}}) {
        auto* name = new QLabel(label, this);
        name->setBuddy(box);
        layout->addWidget(name);
        layout->addWidget(box);
    }

    connect(fps_, &QDoubleSpinBox::valueChanged, this,
            [this](double fps) { applyTimeRange([fps](model::TimeRange& range) { range.fps = fps; }); });
    connect(startTime_, &QDoubleSpinBox::valueChanged, this, [this](double start) {
        applyTimeRange([start](model::TimeRange& range) { range.startTime = start; });
    });
    connect(endTime_, &QDoubleSpinBox::valueChanged, this,
            [this](double end) { applyTimeRange([end](model::TimeRange& range) { range.endTime = end; }); });
    connect(gravity_, &QDoubleSpinBox::valueChanged, this, &TimeBar::applyGravity);
    connect(up_, &QComboBox::currentIndexChanged, this, &TimeBar::applyGravity);
    connect(&document_, &model::Document::currentTimeChanged, this, &TimeBar::showCurrentTime);
    connect(&document_, &model::Document::changed, this, [this](model::ObjectId, model::Changes changes) {
        if (changes & (model::Change::SceneSettings | model::Change::Scene)) {
            showTimeRange();
            showGravity();
            showCurrentTime();
        }
    });
    showTimeRange();
    showGravity();
    showCurrentTime();
}

void TimeBar::showCurrentTime()
{
    const model::Scene& scene = document_.scene();
    currentTime_->setText(tr("Time %1 s").arg(scene.currentTime, 0, 'f', 3));
    // The frame on screen: the last one started, with a rounding error's grace for a time on a frame.
    currentFrame_->setText(tr("Frame %1").arg(static_cast<long long>(std::floor(scene.currentTime * scene.fps + 1e-9))));
}

void TimeBar::showTimeRange()
{
    const model::Scene& scene = document_.scene();
    const QSignalBlocker blockFps(fps_);
    const QSignalBlocker blockStart(startTime_);
    const QSignalBlocker blockEnd(endTime_);
    fps_->setValue(scene.fps);
    startTime_->setValue(scene.startTime);
    endTime_->setValue(scene.endTime);
}

void TimeBar::showGravity()
{
    const model::Gravity& gravity = document_.scene().gravity;
    const QSignalBlocker blockGravity(gravity_);
    const QSignalBlocker blockUp(up_);
    gravity_->setValue(gravity.acceleration);
    up_->setCurrentIndex(static_cast<int>(gravity.up));
}

void TimeBar::applyGravity()
{
    const model::Gravity gravity{gravity_->value(), static_cast<model::UpDirection>(up_->currentIndex())};
    if (gravity != document_.scene().gravity)
        document_.push(new model::SetGravityCommand(document_, gravity));
}

template <class Change>
void TimeBar::applyTimeRange(Change change)
{
    const model::Scene& scene = document_.scene();
    model::TimeRange range{scene.fps, scene.startTime, scene.endTime};
    change(range);
    if (!(range.endTime > range.startTime)) {
        showTimeRange();
        return;
    }
    document_.push(new model::SetTimeRangeCommand(document_, range));
}

} // namespace gyre::app
