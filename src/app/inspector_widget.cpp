#include "app/inspector_widget.h"

#include "app/euler_convention_choosers.h"
#include "app/mass_properties_group.h"
#include "core/rotation.h"
#include "model/commands/set_keyframe_time_command.h"
#include "model/commands/set_keyframe_orientation_command.h"
#include "model/commands/set_keyframe_position_command.h"
#include "model/commands/set_rotation_mode_command.h"
#include "model/commands/toggle_keyframe_constraint_command.h"
#include "model/value_checks.h"
#include "ui_inspector_widget.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace gyre::app {

namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

// Places shown: unit quaternions, matrices and axes change visibly in the sixth; angles and times are
// read in degrees and seconds, where four places are finer than any frame or handle drag.
constexpr int kUnitDecimals = 6;
constexpr int kDegreeDecimals = 4;
constexpr int kPositionDecimals = 6;
constexpr int kTimeDecimals = 4;

// Within this distance of gimbal lock a change δ of the rotation can move the first and third angles
// by δ / sin(5°), more than eleven times as much: they no longer say much on their own.
constexpr double kGimbalWarningDegrees = 5.0;

// How far typed numbers may be from an exact rotation and still count as one: a quaternion or matrix
// typed with 16 significant digits is within 1e-15 of unit length or orthonormality.
constexpr double kTypedRoundingTolerance = 1e-12;

std::vector<double> quaternionValues(const Eigen::Quaterniond& q)
{
    return {q.w(), q.x(), q.y(), q.z()};
}

// Row by row, as the matrix is laid out in the panel.
std::vector<double> matrixValues(const Eigen::Matrix3d& m)
{
    return {m(0, 0), m(0, 1), m(0, 2), m(1, 0), m(1, 1), m(1, 2), m(2, 0), m(2, 1), m(2, 2)};
}

std::vector<double> axisAngleValues(const AxisAngle& axisAngle)
{
    const Eigen::Vector3d& axis = axisAngle.axis;
    return {axis.x(), axis.y(), axis.z(), axisAngle.angle * kDegreesPerRadian};
}

QChar axisLetter(int axis)
{
    return QLatin1Char("xyz"[axis]);
}

} // namespace

InspectorWidget::InspectorWidget(model::Document& document, Selection& selection, QWidget* parent)
    : QWidget(parent)
    , ui_(std::make_unique<Ui::InspectorWidget>())
    , document_(document)
    , selection_(selection)
    , selectedTrack_(document, selection)
    , refresh_(*this, 0, [this] { showSelectedKey(); })
{
    ui_->setupUi(this);
    const int iconSize = style()->pixelMetric(QStyle::PM_SmallIconSize, nullptr, this);
    ui_->gimbalWarningIcon->setPixmap(style()->standardIcon(QStyle::SP_MessageBoxWarning).pixmap(iconSize));
    ui_->gimbalWarningFrame->hide();
    ui_->inspectorMessageFrame->hide();

    time_ = new NumberFields({ui_->timeEdit}, {tr("time")}, kTimeDecimals, this);
    position_ = new NumberFields({ui_->positionXEdit, ui_->positionYEdit, ui_->positionZEdit},
                                 {tr("position x"), tr("position y"), tr("position z")}, kPositionDecimals, this);
    quaternion_ = new NumberFields(
        {ui_->quaternionWEdit, ui_->quaternionXEdit, ui_->quaternionYEdit, ui_->quaternionZEdit},
        {tr("quaternion w"), tr("quaternion x"), tr("quaternion y"), tr("quaternion z")}, kUnitDecimals, this);
    std::vector<QLineEdit*> matrixEdits{ui_->matrix00Edit, ui_->matrix01Edit, ui_->matrix02Edit,
                                        ui_->matrix10Edit, ui_->matrix11Edit, ui_->matrix12Edit,
                                        ui_->matrix20Edit, ui_->matrix21Edit, ui_->matrix22Edit};
    QStringList matrixNames;
    for (int row = 1; row <= 3; ++row)
        for (int column = 1; column <= 3; ++column)
            matrixNames << tr("matrix row %1, column %2").arg(row).arg(column);
    matrix_ = new NumberFields(std::move(matrixEdits), matrixNames, kUnitDecimals, this);
    axisAngle_ = new NumberFields({ui_->axisXEdit, ui_->axisYEdit, ui_->axisZEdit, ui_->angleEdit},
                                  {tr("axis x"), tr("axis y"), tr("axis z"), tr("angle")}, kUnitDecimals, this);
    eulerAngles_ = new NumberFields({ui_->euler1Edit, ui_->euler2Edit, ui_->euler3Edit},
                                    {tr("first angle"), tr("second angle"), tr("third angle")}, kDegreeDecimals, this);

    connect(time_, &NumberFields::editingFinished, this, &InspectorWidget::applyTime);
    connect(position_, &NumberFields::editingFinished, this, &InspectorWidget::applyPosition);
    connect(quaternion_, &NumberFields::editingFinished, this, &InspectorWidget::applyQuaternion);
    connect(matrix_, &NumberFields::editingFinished, this, &InspectorWidget::applyMatrix);
    connect(axisAngle_, &NumberFields::editingFinished, this, &InspectorWidget::applyAxisAngle);
    connect(eulerAngles_, &NumberFields::editingFinished, this, &InspectorWidget::applyEulerAngles);
    connect(ui_->constrainedCheck, &QCheckBox::clicked, this, &InspectorWidget::applyConstraint);
    setUpConventionChoosers();
    // Below the key's groups, scrolling with them; it shows the object, so it stays enabled without a key.
    ui_->fieldsLayout->insertWidget(ui_->fieldsLayout->count() - 1, new MassPropertiesGroup(document, selection, this));

    connect(&selection_, &Selection::changed, this, [this] {
        clearMessage();
        refresh_.requestNow();
    });
    // Another selected object comes through Selection::changed as well; a shown object that is not
    // the selected one is shown no longer once a refresh is pending.
    connect(&selectedTrack_, &SelectedTrack::changed, this, [this](model::Changes changes) {
        using model::Change;
        if (changes.testFlag(Change::Scene)) {
            typedRotation_.reset();
            clearMessage();
        }
        if (changes & (Change::Scene | Change::Keyframes | Change::Object))
            refresh_.requestNow();
    });
    showSelectedKey();
}

InspectorWidget::~InspectorWidget() = default;

void InspectorWidget::setUpConventionChoosers()
{
    fillConventionChoosers(*ui_->eulerOrderCombo, *ui_->eulerFrameCombo);
    ui_->rotationModeCombo->addItem(tr("Quaternions"), static_cast<int>(model::RotationMode::Kind::Quaternion));
    ui_->rotationModeCombo->addItem(tr("Euler angles"), static_cast<int>(model::RotationMode::Kind::Euler));
    // The choosers show the selected object's mode and convention; the graph editor's, linked to them (main
    // window), may show another convention for a while, which the fields then follow.
    const auto conventionChanged = [this] {
        updateEulerLabels();
        showSelectedKey();
    };
    connect(ui_->eulerOrderCombo, &QComboBox::currentIndexChanged, this, conventionChanged);
    connect(ui_->eulerFrameCombo, &QComboBox::currentIndexChanged, this, conventionChanged);
    // activated comes from the artist alone, never from showing the object.
    for (QComboBox* chooser : {ui_->rotationModeCombo, ui_->eulerOrderCombo, ui_->eulerFrameCombo})
        connect(chooser, &QComboBox::activated, this, &InspectorWidget::applyRotationMode);
    updateEulerLabels();
}

EulerConvention InspectorWidget::chosenConvention() const
{
    return app::chosenConvention(*ui_->eulerOrderCombo, *ui_->eulerFrameCombo);
}

void InspectorWidget::updateEulerLabels()
{
    const EulerConvention convention = chosenConvention();
    const QList<QLabel*> labels{ui_->euler1Label, ui_->euler2Label, ui_->euler3Label};
    for (int i = 0; i < 3; ++i)
        labels[i]->setText(tr("about %1 (°)").arg(axisLetter(convention.axes[static_cast<std::size_t>(i)])));
}

void InspectorWidget::showRotationMode(const model::SceneObject* object)
{
    ui_->rotationModeGroup->setEnabled(object != nullptr);
    const bool euler = object != nullptr && object->track.rotationMode.isEuler();
    // Set when another object or mode is shown, not at every refresh: the graph editor's linked choosers may
    // show another convention meanwhile, which the fields follow (showOrientation).
    if (object != nullptr && (object->id != modeShown_.first || object->track.rotationMode != modeShown_.second)) {
        const model::RotationMode& mode = object->track.rotationMode;
        modeShown_ = {object->id, mode};
        ui_->rotationModeCombo->setCurrentIndex(ui_->rotationModeCombo->findData(static_cast<int>(mode.kind)));
        showConvention(*ui_->eulerOrderCombo, *ui_->eulerFrameCombo, mode.convention);
    }
    // In Euler mode the angles the keys store come first, after the key's time; else after the axis-angle.
    QWidget* before = euler ? ui_->keyframeGroup : ui_->axisAngleGroup;
    if (ui_->fieldsLayout->indexOf(ui_->eulerGroup) != ui_->fieldsLayout->indexOf(before) + 1) {
        ui_->fieldsLayout->removeWidget(ui_->eulerGroup);
        ui_->fieldsLayout->insertWidget(ui_->fieldsLayout->indexOf(before) + 1, ui_->eulerGroup);
    }
}

void InspectorWidget::applyRotationMode()
{
    tryEdit(tr("The rotation mode was not changed: %1."), [this] {
        const model::SceneObject* object = selection_.selectedObject();
        if (object == nullptr)
            return;
        model::RotationMode mode;
        mode.kind = static_cast<model::RotationMode::Kind>(ui_->rotationModeCombo->currentData().toInt());
        mode.convention = chosenConvention();
        if (mode != object->track.rotationMode)
            document_.push(new model::SetRotationModeCommand(document_, object->id, mode));
    });
}

void InspectorWidget::showSelectedKey()
{
    const model::SceneObject* object = selection_.selectedObject();
    showRotationMode(object);
    const model::Keyframe* key = selection_.selectedKey();
    if (key == nullptr) {
        showNoKey();
        return;
    }
    shownObject_ = object->id;
    shownKey_ = selection_.key();
    ui_->noKeyLabel->hide();
    ui_->keyTitleLabel->setText(tr("%1, keyframe %2 of %3")
                                    .arg(object->name)
                                    .arg(*shownKey_ + 1)
                                    .arg(object->track.keys.size()));
    ui_->keyTitleLabel->show();
    setKeyFieldsEnabled(true);
    time_->show({key->time});
    const Eigen::Vector3d& position = key->pose.position;
    position_->show({position.x(), position.y(), position.z()});
    ui_->constrainedCheck->setChecked(key->constrained);
    showOrientation(*object, *shownKey_);
}

void InspectorWidget::showOrientation(const model::SceneObject& object, std::size_t keyIndex)
{
    const model::Keyframe& key = object.track.keys[keyIndex];
    const Eigen::Quaterniond& q = key.pose.orientation;
    const EulerConvention convention = chosenConvention();
    const auto showFields = [&, this](NumberFields& fields, const std::vector<double>& converted) {
        const bool showTyped = typedRotation_ && typedRotation_->object == object.id &&
                               typedRotation_->key == keyIndex && typedRotation_->fields == &fields &&
                               (&fields != eulerAngles_ || typedRotation_->convention == convention) &&
                               typedRotation_->stored.coeffs() == q.coeffs();
        fields.show(showTyped ? typedRotation_->values : converted);
    };
    showFields(*quaternion_, quaternionValues(q));
    showFields(*matrix_, matrixValues(q.toRotationMatrix()));
    showFields(*axisAngle_, axisAngleValues(axisAngleFromQuaternion(q)));
    const EulerAngles euler = eulerAnglesFromQuaternion(q, convention);
    // In Euler mode the angles as stored (720° stays 720°), while the chooser shows the object's convention.
    const bool stored = key.eulerAngles && convention == object.track.rotationMode.convention;
    const Eigen::Vector3d degrees = (stored ? *key.eulerAngles : euler.angles) * kDegreesPerRadian;
    showFields(*eulerAngles_, {degrees.x(), degrees.y(), degrees.z()});

    const double lockDistance = euler.gimbalLockDistance * kDegreesPerRadian;
    ui_->gimbalWarningFrame->setVisible(lockDistance < kGimbalWarningDegrees);
    ui_->gimbalWarningLabel->setText(
        tr("Near gimbal lock (%1° from it): the first and third angles turn about almost the same axis, so only "
           "their sum (or difference) is determined. Small changes of the rotation can swing them widely.")
            .arg(roundedNumberText(lockDistance, 2)));
}

void InspectorWidget::setKeyFieldsEnabled(bool enabled)
{
    for (QWidget* group : {ui_->keyframeGroup, ui_->positionGroup, ui_->quaternionGroup, ui_->matrixGroup,
                           ui_->axisAngleGroup, ui_->eulerGroup})
        group->setEnabled(enabled);
}

void InspectorWidget::showNoKey()
{
    shownObject_ = model::kNoObject;
    shownKey_.reset();
    ui_->noKeyLabel->show();
    ui_->keyTitleLabel->hide();
    setKeyFieldsEnabled(false);
    for (NumberFields* fields : {time_, position_, quaternion_, matrix_, axisAngle_, eulerAngles_})
        fields->clear();
    ui_->constrainedCheck->setChecked(false);
    ui_->gimbalWarningFrame->hide();
}

void InspectorWidget::tryEdit(const QString& refusal, const std::function<void()>& edit)
{
    clearMessage();
    try {
        edit();
    } catch (const std::invalid_argument& error) {
        showError(refusal.arg(QString::fromUtf8(error.what())));
    }
}

const model::Keyframe& InspectorWidget::shownKeyframe() const
{
    return document_.object(shownObject_)->track.keys[*shownKey_];
}

void InspectorWidget::applyTime()
{
    tryEdit(tr("The keyframe was not moved: %1."), [this] {
        const double time = time_->values().front();
        if (time == shownKeyframe().time)
            showSelectedKey();
        else
            document_.push(new model::SetKeyframeTimeCommand(document_, shownObject_, *shownKey_, time));
    });
}

void InspectorWidget::applyConstraint(bool constrained)
{
    tryEdit(tr("The constraint was not changed: %1."), [this, constrained] {
        if (constrained != shownKeyframe().constrained)
            document_.push(new model::ToggleKeyframeConstraintCommand(document_, shownObject_, *shownKey_));
    });
}

void InspectorWidget::applyPosition()
{
    tryEdit(tr("The position was not changed: %1."), [this] {
        const std::vector<double> values = position_->values();
        const Eigen::Vector3d position(values[0], values[1], values[2]);
        if (position == shownKeyframe().pose.position)
            showSelectedKey();
        else
            document_.push(new model::SetKeyframePositionCommand(document_, shownObject_, *shownKey_, position));
    });
}

void InspectorWidget::applyQuaternion()
{
    tryEdit(tr("The rotation was not changed: %1."), [this] {
        const std::vector<double> typed = quaternion_->values();
        Eigen::Quaterniond q(typed[0], typed[1], typed[2], typed[3]);
        const double length = q.norm();
        if (length == 0.0) {
            showError(tr("The rotation was not changed: the zero quaternion is no rotation."));
            return;
        }
        // Within the document's tolerance the command normalises quietly; beyond it, the artist meant a
        // direction in 4D, which is scaled to length 1 and said so.
        QString adjustment;
        if (std::abs(length - 1.0) > model::kUnitLengthTolerance) {
            q.coeffs() /= length;
            adjustment = tr("The quaternion had length %1; it was scaled to length 1.")
                             .arg(roundedNumberText(length, kUnitDecimals));
        }
        const bool exact = std::abs(length - 1.0) <= kTypedRoundingTolerance;
        setOrientation(*quaternion_, exact ? std::optional(typed) : std::nullopt, q, adjustment);
    });
}

void InspectorWidget::applyMatrix()
{
    tryEdit(tr("The rotation was not changed: %1."), [this] {
        const std::vector<double> typed = matrix_->values();
        const Eigen::Matrix3d m = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(typed.data());
        const double determinant = m.determinant();
        // A rotation has determinant 1. One of 0 or less flattens or mirrors space, and the nearest
        // rotation to it would be a guess; anything else is taken to be a rotation typed imprecisely.
        if (!(determinant > 0.0)) {
            showError(tr("The rotation was not changed: the matrix has determinant %1, so it flattens or mirrors "
                         "space and is not a rotation.")
                          .arg(roundedNumberText(determinant, kUnitDecimals)));
            return;
        }
        const double error = rotationMatrixError(m);
        QString adjustment;
        if (error > model::kUnitLengthTolerance)
            adjustment = tr("The matrix was not a rotation (its rows were up to %1 from orthonormal); the nearest "
                            "rotation was used.")
                             .arg(roundedNumberText(error, kUnitDecimals));
        const Eigen::Quaterniond q(nearestRotation(m));
        setOrientation(*matrix_, error <= kTypedRoundingTolerance ? std::optional(typed) : std::nullopt, q,
                       adjustment);
    });
}

void InspectorWidget::applyAxisAngle()
{
    tryEdit(tr("The rotation was not changed: %1."), [this] {
        const std::vector<double> typed = axisAngle_->values();
        const Eigen::Vector3d axis(typed[0], typed[1], typed[2]);
        const double angle = typed[3] / kDegreesPerRadian;
        const double length = axis.norm();
        if (length == 0.0 && angle != 0.0) {
            showError(tr("The rotation was not changed: a zero axis names no direction to turn about."));
            return;
        }
        QString adjustment;
        if (length != 0.0 && std::abs(length - 1.0) > model::kUnitLengthTolerance)
            adjustment = tr("The axis had length %1; it was scaled to length 1.")
                             .arg(roundedNumberText(length, kUnitDecimals));
        // quaternionFromAxisAngle normalises the axis itself, and takes a zero axis with a zero angle as
        // the identity.
        const Eigen::Quaterniond q = quaternionFromAxisAngle({axis, angle});
        const bool exact = std::abs(length - 1.0) <= kTypedRoundingTolerance;
        setOrientation(*axisAngle_, exact ? std::optional(typed) : std::nullopt, q, adjustment);
    });
}

void InspectorWidget::applyEulerAngles()
{
    tryEdit(tr("The rotation was not changed: %1."), [this] {
        const std::vector<double> typed = eulerAngles_->values();
        const Eigen::Vector3d radians = Eigen::Vector3d(typed[0], typed[1], typed[2]) / kDegreesPerRadian;
        const model::Keyframe& key = shownKeyframe();
        const model::RotationMode& mode = document_.object(shownObject_)->track.rotationMode;
        if (!key.eulerAngles || mode.convention != chosenConvention()) {
            setOrientation(*eulerAngles_, typed, quaternionFromEulerAngles(radians, chosenConvention()), QString());
            return;
        }
        // Euler mode: the angles themselves are the key's, so typing 360 stores a full turn.
        if (radians != *key.eulerAngles)
            document_.push(new model::SetKeyframeOrientationCommand(document_, shownObject_, *shownKey_, radians));
        typedRotation_ = TypedRotation{shownObject_, *shownKey_, eulerAngles_, chosenConvention(), typed,
                                       shownKeyframe().pose.orientation};
        showSelectedKey();
    });
}

void InspectorWidget::setOrientation(const NumberFields& fields, const std::optional<std::vector<double>>& exactlyTyped,
                                     const Eigen::Quaterniond& orientation, const QString& adjustment)
{
    if (orientation.coeffs() != shownKeyframe().pose.orientation.coeffs())
        document_.push(new model::SetKeyframeOrientationCommand(document_, shownObject_, *shownKey_, orientation));
    if (exactlyTyped)
        typedRotation_ = TypedRotation{shownObject_, *shownKey_, &fields, chosenConvention(), *exactlyTyped,
                                       shownKeyframe().pose.orientation};
    else
        typedRotation_.reset();
    showSelectedKey();
    if (!adjustment.isEmpty())
        showNotice(adjustment);
}

void InspectorWidget::showMessage(QStyle::StandardPixmap icon, const QString& message)
{
    const int iconSize = style()->pixelMetric(QStyle::PM_SmallIconSize, nullptr, this);
    ui_->inspectorMessageIcon->setPixmap(style()->standardIcon(icon).pixmap(iconSize));
    ui_->inspectorMessageLabel->setText(message);
    ui_->inspectorMessageFrame->show();
}

void InspectorWidget::clearMessage()
{
    ui_->inspectorMessageFrame->hide();
    ui_->inspectorMessageLabel->clear();
}

} // namespace gyre::app
