#include "app/screwbender_panel.h"

#include "core/orientation_curves.h"
#include "core/subdivision.h"
#include "model/commands/set_interpolation_command.h"
#include "model/commands/set_subdivision_command.h"
#include "model/value_checks.h"
#include "ui_screwbender_panel.h"

#include <QSignalBlocker>
#include <QStandardItemModel>
#include <QUndoCommand>

#include <memory>
#include <stdexcept>

namespace gyre::app {

namespace {

// What the method chooser shows.
QString methodLabel(InterpolationMethod method)
{
    switch (method) {
    case InterpolationMethod::Slerp:
        return ScrewBenderPanel::tr("Slerp (great arcs)");
    case InterpolationMethod::Nlerp:
        return ScrewBenderPanel::tr("Nlerp (normalised straight lines)");
    case InterpolationMethod::Squad:
        return ScrewBenderPanel::tr("Squad (smooth quaternion curve)");
    case InterpolationMethod::Hermite:
        return ScrewBenderPanel::tr("Hermite quaternion spline");
    case InterpolationMethod::Euler:
        return ScrewBenderPanel::tr("Euler angles, linearly");
    case InterpolationMethod::EulerCubic:
        return ScrewBenderPanel::tr("Euler angles, smooth (automatic tangents)");
    case InterpolationMethod::Screw:
        return ScrewBenderPanel::tr("Screw motion (ScrewBender)");
    case InterpolationMethod::Ballistic:
        return ScrewBenderPanel::tr("Ballistic (free flight between keys)");
    }
    return {};
}

// What the scheme chooser shows.
QString schemeLabel(SubdivisionScheme scheme)
{
    switch (scheme) {
    case SubdivisionScheme::FourPoint:
        return ScrewBenderPanel::tr("Four-point");
    case SubdivisionScheme::FourPointB:
        return ScrewBenderPanel::tr("Four-point B");
    case SubdivisionScheme::BSpline:
        return ScrewBenderPanel::tr("Cubic B-spline");
    case SubdivisionScheme::Jarek:
        return ScrewBenderPanel::tr("Jarek");
    }
    return {};
}

// Whether `settings` are still those every track starts with.
bool isUntouched(const SubdivisionSettings& settings)
{
    const SubdivisionSettings initial;
    return settings.scheme == initial.scheme && settings.levels == initial.levels && settings.cyclic == initial.cyclic
           && settings.decoupled == initial.decoupled;
}

} // namespace

ScrewBenderPanel::ScrewBenderPanel(model::Document& document, Selection& selection, QWidget* parent)
    : QWidget(parent)
    , ui_(std::make_unique<Ui::ScrewBenderPanel>())
    , document_(document)
    , selection_(selection)
    , selectedTrack_(document, selection)
    , refresh_(*this, 0, [this] { showSelectedTrack(); })
{
    ui_->setupUi(this);
    const int iconSize = style()->pixelMetric(QStyle::PM_SmallIconSize, nullptr, this);
    ui_->screwBenderMessageIcon->setPixmap(style()->standardIcon(QStyle::SP_MessageBoxCritical).pixmap(iconSize));
    ui_->screwBenderMessageFrame->hide();
    for (const auto& [method, name] : kInterpolationMethodNames)
        ui_->interpolationCombo->addItem(methodLabel(method), static_cast<int>(method));
    for (const auto& [scheme, name] : kSubdivisionSchemeNames)
        ui_->schemeCombo->addItem(schemeLabel(scheme), static_cast<int>(scheme));
    ui_->levelsSpin->setRange(0, model::kMaxSubdivisionLevels);

    // activated and clicked come from the artist only, never from showing the track.
    connect(ui_->interpolationCombo, &QComboBox::activated, this, &ScrewBenderPanel::applyInterpolation);
    connect(ui_->schemeCombo, &QComboBox::activated, this, &ScrewBenderPanel::applySubdivision);
    connect(ui_->cyclicRadio, &QRadioButton::clicked, this, &ScrewBenderPanel::applySubdivision);
    connect(ui_->openRadio, &QRadioButton::clicked, this, &ScrewBenderPanel::applySubdivision);
    connect(ui_->decoupledCheck, &QCheckBox::clicked, this, &ScrewBenderPanel::applySubdivision);
    // Without keyboard tracking a typed level arrives once, on Enter or when the focus leaves; an arrow
    // step arrives at once. showSelectedTrack blocks it.
    connect(ui_->levelsSpin, &QSpinBox::valueChanged, this, &ScrewBenderPanel::applySubdivision);

    connect(&selection_, &Selection::changed, this, [this] {
        ui_->screwBenderMessageFrame->hide();
        refresh_.requestNow();
    });
    // The pose count follows the number of keyframes, the title the object's name.
    connect(&selectedTrack_, &SelectedTrack::changed, this, [this](model::Changes changes) {
        using model::Change;
        if (changes & (Change::Scene | Change::TrackSettings | Change::Keyframes | Change::Object))
            refresh_.requestNow();
    });
    showSelectedTrack();
}

ScrewBenderPanel::~ScrewBenderPanel() = default;

void ScrewBenderPanel::showSelectedTrack()
{
    const model::SceneObject* object = selection_.selectedObject();
    ui_->noObjectLabel->setVisible(object == nullptr);
    ui_->objectTitleLabel->setVisible(object != nullptr);
    ui_->interpolationGroup->setEnabled(object != nullptr);
    ui_->subdivisionGroup->setEnabled(object != nullptr);
    if (object == nullptr) {
        ui_->poseCountLabel->clear();
        return;
    }
    const model::MotionTrack& track = object->track;
    const SubdivisionSettings& subdivision = track.subdivision;
    ui_->objectTitleLabel->setText(object->name);
    ui_->interpolationCombo->setCurrentIndex(ui_->interpolationCombo->findData(static_cast<int>(track.interpolation)));
    // In Euler rotation mode only the methods that interpolate the angles keep the turns they hold.
    auto* methods = qobject_cast<QStandardItemModel*>(ui_->interpolationCombo->model());
    for (int row = 0; row < methods->rowCount(); ++row) {
        const auto method = static_cast<InterpolationMethod>(ui_->interpolationCombo->itemData(row).toInt());
        methods->item(row)->setEnabled(!track.rotationMode.isEuler() || interpolatesAngles(method));
    }
    ui_->screwOnlyNote->setVisible(track.interpolation != InterpolationMethod::Screw);
    ui_->schemeCombo->setCurrentIndex(ui_->schemeCombo->findData(static_cast<int>(subdivision.scheme)));
    {
        const QSignalBlocker blocker(ui_->levelsSpin);
        ui_->levelsSpin->setValue(subdivision.levels);
    }
    (subdivision.cyclic ? ui_->cyclicRadio : ui_->openRadio)->setChecked(true);
    ui_->decoupledCheck->setChecked(subdivision.decoupled);

    const std::size_t keys = track.keys.size();
    const std::optional<std::size_t> poses = subdividedPoseCount(keys, subdivision.levels, subdivision.cyclic);
    ui_->poseCountLabel->setText(poses ? tr("%1 from %2 keyframes").arg(*poses).arg(keys)
                                       : tr("too many to hold, from %1 keyframes").arg(keys));
}

void ScrewBenderPanel::applyInterpolation()
{
    ui_->screwBenderMessageFrame->hide();
    const auto method = static_cast<InterpolationMethod>(ui_->interpolationCombo->currentData().toInt());
    if (method == selection_.selectedObject()->track.interpolation)
        return;
    try {
        document_.push(interpolationChange(method));
    } catch (const std::invalid_argument& error) {
        showError(tr("The interpolation was not changed: %1.").arg(QString::fromUtf8(error.what())));
    }
}

QUndoCommand* ScrewBenderPanel::interpolationChange(InterpolationMethod method) const
{
    const model::ObjectId object = selection_.object();
    const SubdivisionSettings& subdivision = selection_.selectedObject()->track.subdivision;
    // A track that becomes a screw track with the subdivision never set is open: most motions do
    // not return to their start, and a cyclic polyscrew would bend the last key back to the first.
    // Ticking cyclic makes it a cycle.
    if (method != InterpolationMethod::Screw || !isUntouched(subdivision))
        return new model::SetInterpolationCommand(document_, object, method);
    auto both = std::make_unique<QUndoCommand>(tr("Interpolate by Screws"));
    SubdivisionSettings open = subdivision;
    open.cyclic = false;
    // Children of `both`, which owns them; open first, so that the pose count is checked for it.
    new model::SetSubdivisionCommand(document_, object, open, both.get());
    new model::SetInterpolationCommand(document_, object, method, both.get());
    return both.release();
}

void ScrewBenderPanel::applySubdivision()
{
    ui_->screwBenderMessageFrame->hide();
    SubdivisionSettings settings;
    settings.scheme = static_cast<SubdivisionScheme>(ui_->schemeCombo->currentData().toInt());
    settings.levels = ui_->levelsSpin->value();
    settings.cyclic = ui_->cyclicRadio->isChecked();
    settings.decoupled = ui_->decoupledCheck->isChecked();
    const SubdivisionSettings& current = selection_.selectedObject()->track.subdivision;
    if (settings.scheme == current.scheme && settings.levels == current.levels && settings.cyclic == current.cyclic &&
        settings.decoupled == current.decoupled)
        return;
    try {
        document_.push(new model::SetSubdivisionCommand(document_, selection_.object(), settings));
    } catch (const std::invalid_argument& error) {
        showError(tr("The subdivision was not changed: %1.").arg(QString::fromUtf8(error.what())));
    }
}

void ScrewBenderPanel::showError(const QString& message)
{
    ui_->screwBenderMessageLabel->setText(message);
    ui_->screwBenderMessageFrame->show();
}

} // namespace gyre::app
