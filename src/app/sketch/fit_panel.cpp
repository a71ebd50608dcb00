#include "app/sketch/fit_panel.h"

#include "model/object_mass.h"
#include "model/physics_target.h"
#include "model/sketch_fit_problem.h"
#include "model/commands/remove_fit_command.h"
#include "model/commands/set_fit_parameter_command.h"
#include "model/commands/set_fit_window_command.h"
#include "model/commands/set_physics_target_command.h"
#include "model/commands/toggle_keyframe_constraint_command.h"
#include "ui_fit_panel.h"

#include <QSignalBlocker>
#include <QStyle>

#include <stdexcept>
#include <utility>

namespace gyre::app {

namespace {

constexpr int kTimeColumn = 0;
constexpr int kConstrainedColumn = 1;

// The span of the track's keys, or nullopt for fewer than two.
std::optional<std::pair<double, double>> keySpan(const model::MotionTrack& track)
{
    if (track.keys.size() < 2)
        return std::nullopt;
    return std::pair(track.keys.front().time, track.keys.back().time);
}

} // namespace

FitPanel::FitPanel(model::Document& document, Selection& selection, FitController& controller, QWidget* parent)
    : QWidget(parent)
    , ui_(std::make_unique<Ui::FitPanel>())
    , document_(document)
    , selection_(selection)
    , selectedTrack_(document, selection)
    , controller_(controller)
    , keysRefresh_(*this, 0, [this] { showKeys(); })
{
    ui_->setupUi(this);
    const int iconSize = style()->pixelMetric(QStyle::PM_SmallIconSize, nullptr, this);
    ui_->fitProblemIcon->setPixmap(style()->standardIcon(QStyle::SP_MessageBoxWarning).pixmap(iconSize));
    ui_->fitProblemFrame->hide();

    // Without keyboard tracking a typed value arrives once, on Enter or when the focus leaves; a step
    // arrives at once. Each is an undo step of its own (push), though the model merges such edits.
    connect(ui_->alphaSpin, &QDoubleSpinBox::valueChanged, this,
            [this](double value) { setParameter(model::FitParameter::Alpha, value); });
    connect(ui_->betaSpin, &QDoubleSpinBox::valueChanged, this,
            [this](double value) { setParameter(model::FitParameter::Beta, value); });
    connect(ui_->deltaSpin, &QDoubleSpinBox::valueChanged, this,
            [this](double value) { setParameter(model::FitParameter::Delta, value); });
    // clicked comes from the artist only, never from showing the track.
    connect(ui_->wholeSketchCheck, &QCheckBox::clicked, this, &FitPanel::applyWholeSketch);
    connect(ui_->windowStartSpin, &QDoubleSpinBox::valueChanged, this, &FitPanel::applyWindowEnds);
    connect(ui_->windowEndSpin, &QDoubleSpinBox::valueChanged, this, &FitPanel::applyWindowEnds);
    connect(ui_->keyTable, &QTableWidget::itemChanged, this, &FitPanel::toggleConstraint);

    connect(ui_->fitButton, &QPushButton::clicked, &controller_, &FitController::fitSelected);
    connect(ui_->cancelButton, &QPushButton::clicked, &controller_, &FitController::cancel);
    connect(ui_->removeFitButton, &QPushButton::clicked, this, &FitPanel::removeFit);
    connect(ui_->physicsTargetButton, &QPushButton::clicked, this, &FitPanel::setPhysicsTarget);
    connect(ui_->liveCheck, &QCheckBox::clicked, &controller_, &FitController::setLive);
    connect(&controller_, &FitController::liveChanged, ui_->liveCheck, &QCheckBox::setChecked);
    connect(&controller_, &FitController::fitStarted, this, [this] {
        showStatus(tr("Fitting…"));
        updateButtons();
    });
    connect(&controller_, &FitController::fitEnded, this, [this](const QString& message) {
        showStatus(message);
        updateButtons();
    });

    connect(&selection_, &Selection::changed, this, [this] {
        showStatus({});
        showSelectedTrack();
    });
    connect(&selectedTrack_, &SelectedTrack::changed, this, [this](model::Changes changes) {
        using model::Change;
        if (changes & (Change::Scene | Change::Sketch | Change::Keyframes | Change::TrackSettings | Change::Object))
            showSelectedTrack();
    });
    ui_->liveCheck->setChecked(controller_.isLive());
    showSelectedTrack();
    showKeys();
}

FitPanel::~FitPanel() = default;

void FitPanel::showSelectedTrack()
{
    const model::SceneObject* object = selection_.selectedObject();
    ui_->noObjectLabel->setVisible(object == nullptr);
    ui_->objectTitleLabel->setVisible(object != nullptr);
    for (QWidget* group : {static_cast<QWidget*>(ui_->weightsGroup), static_cast<QWidget*>(ui_->windowGroup),
                           static_cast<QWidget*>(ui_->keysGroup)})
        group->setEnabled(object != nullptr);
    keysRefresh_.requestNow();
    if (object == nullptr) {
        ui_->fitProblemFrame->hide();
        fittable_ = false;
        updateButtons();
        return;
    }
    const model::MotionTrack& track = object->track;
    ui_->objectTitleLabel->setText(object->name);
    for (auto [spin, value] : {std::pair(ui_->alphaSpin, track.sketch.alpha), std::pair(ui_->betaSpin, track.sketch.beta),
                               std::pair(ui_->deltaSpin, track.sketch.delta)}) {
        const QSignalBlocker blocker(spin);
        spin->setValue(value);
    }
    showWindow(track);
    showFitProblem(track);
    updateButtons();
}

void FitPanel::showWindow(const model::MotionTrack& track)
{
    const std::pair<double, double> span = keySpan(track).value_or(std::pair(0.0, 0.0));
    // The sketch's own window, or the span the fit would edit without one.
    std::optional<std::pair<double, double>> shown = track.sketch.window;
    if (!shown)
        if (const std::optional<fit::TimeWindow> edited = model::editWindow(track))
            shown = std::pair(edited->start, edited->end);
    const std::pair<double, double> ends = shown.value_or(span);
    const QSignalBlocker startBlocker(ui_->windowStartSpin);
    const QSignalBlocker endBlocker(ui_->windowEndSpin);
    for (QDoubleSpinBox* spin : {ui_->windowStartSpin, ui_->windowEndSpin})
        spin->setRange(span.first, span.second);
    ui_->windowStartSpin->setValue(ends.first);
    ui_->windowEndSpin->setValue(ends.second);
    const bool whole = !track.sketch.window.has_value();
    ui_->wholeSketchCheck->setChecked(whole);
    ui_->windowStartSpin->setEnabled(!whole);
    ui_->windowEndSpin->setEnabled(!whole);
}

void FitPanel::showKeys()
{
    const model::SceneObject* object = selection_.selectedObject();
    std::vector<ShownKey> keys;
    if (object != nullptr) {
        keys.reserve(object->track.keys.size());
        for (const model::Keyframe& key : object->track.keys)
            keys.push_back({key.time, key.constrained});
    }
    // A key turned or moved in space, as at every move of a drag, changes no row.
    if (keys == shownKeys_ && ui_->keyTable->rowCount() == static_cast<int>(keys.size()))
        return;
    QTableWidget& table = *ui_->keyTable;
    const QSignalBlocker blocker(table);
    table.setRowCount(static_cast<int>(keys.size()));
    bool timesChanged = false;
    for (std::size_t key = 0; key < keys.size(); ++key) {
        const int row = static_cast<int>(key);
        QTableWidgetItem* time = table.item(row, kTimeColumn);
        if (time == nullptr) {
            time = new QTableWidgetItem;
            time->setFlags(Qt::ItemIsEnabled);
            table.setItem(row, kTimeColumn, time);
        }
        const QString timeText = QString::number(keys[key].time, 'f', 3);
        if (time->text() != timeText) {
            time->setText(timeText);
            timesChanged = true;
        }
        const Qt::CheckState check = keys[key].constrained ? Qt::Checked : Qt::Unchecked;
        QTableWidgetItem* constrained = table.item(row, kConstrainedColumn);
        if (constrained == nullptr) {
            constrained = new QTableWidgetItem;
            constrained->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
            constrained->setCheckState(check); // an item shows a check box once it has a state
            table.setItem(row, kConstrainedColumn, constrained);
        } else if (constrained->checkState() != check) {
            constrained->setCheckState(check);
        }
    }
    // Measuring the column reads every row: only when a time's text changed.
    if (timesChanged)
        table.resizeColumnToContents(kTimeColumn);
    shownKeys_ = std::move(keys);
}

void FitPanel::showFitProblem(const model::MotionTrack& track)
{
    try {
        model::checkSketchFittable(track);
        fittable_ = true;
        ui_->fitProblemFrame->hide();
    } catch (const model::SketchFitError& error) {
        fittable_ = false;
        ui_->fitProblemLabel->setText(QString::fromUtf8(error.what()));
        ui_->fitProblemFrame->show();
    }
}

void FitPanel::updateButtons()
{
    const model::SceneObject* object = selection_.selectedObject();
    ui_->fitButton->setEnabled(fittable_ && !controller_.isFitting());
    ui_->cancelButton->setEnabled(controller_.isFitting());
    ui_->removeFitButton->setEnabled(object != nullptr && !object->track.sketch.fittedCurve.empty());
    ui_->physicsTargetButton->setEnabled(object != nullptr && object->track.keys.size() >= 2);
}

void FitPanel::setParameter(model::FitParameter parameter, double value)
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr || model::sketchFitParameter(*object, static_cast<std::size_t>(parameter)) == value)
        return;
    push([&] { return new model::SetFitParameterCommand(document_, object->id, parameter, value); });
}

void FitPanel::applyWholeSketch(bool whole)
{
    setWindow(whole ? std::nullopt
                    : std::optional(std::pair(ui_->windowStartSpin->value(), ui_->windowEndSpin->value())));
}

void FitPanel::applyWindowEnds()
{
    setWindow(std::pair(ui_->windowStartSpin->value(), ui_->windowEndSpin->value()));
}

void FitPanel::setWindow(std::optional<std::pair<double, double>> window)
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr || object->track.sketch.window == window)
        return;
    push([&] { return new model::SetFitWindowCommand(document_, object->id, window); });
}

void FitPanel::toggleConstraint(QTableWidgetItem* item)
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr || item->column() != kConstrainedColumn)
        return;
    const auto key = static_cast<std::size_t>(item->row());
    if (key >= object->track.keys.size() || object->track.keys[key].constrained == (item->checkState() == Qt::Checked))
        return;
    push([&] { return new model::ToggleKeyframeConstraintCommand(document_, object->id, key); });
}

void FitPanel::removeFit()
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr)
        return;
    push([&] { return new model::RemoveFitCommand(document_, object->id); });
}

void FitPanel::setPhysicsTarget()
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr)
        return;
    push([&] {
        // From the motion as it plays now, its applied fit included.
        const model::TrackMotion& motion = document_.motion(object->id)->motion();
        model::PhysicsTarget target = model::physicsTarget(
            object->track, motion, model::objectMassProperties(*object).properties, document_.scene().fps);
        return new model::SetPhysicsTargetCommand(document_, object->id, std::move(target));
    });
}

void FitPanel::push(const std::function<QUndoCommand*()>& makeCommand)
{
    try {
        document_.push(makeCommand());
    } catch (const std::invalid_argument& error) {
        showStatus(tr("Not changed: %1.").arg(QString::fromUtf8(error.what())));
        // The widgets go back to what the track holds.
        showSelectedTrack();
    }
}

void FitPanel::showStatus(const QString& message)
{
    ui_->fitStatusLabel->setText(message);
}

} // namespace gyre::app
