#include "app/mass_properties_group.h"

#include "model/commands/set_mass_override_command.h"
#include "model/object_mass.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>

#include <stdexcept>

namespace gyre::app {

namespace {

// Masses and moments of hand-sized to human-sized bodies in six places: to the milligram and the 10 g·cm².
constexpr int kMassDecimals = 6;
// A computed inertia tensor's entries that are zero in truth come out as rounding noise of about 1e-16 of
// its largest entry (a box turned a quarter turn: (Ixx − Iyy)·sin·cos with cos ≈ 6e-17). Entries and principal
// moments below the largest entry × this read as 0; at a large body's scale the noise would show in six places.
constexpr double kInertiaNoise = 1e-9;

std::vector<QLineEdit*> lineEdits(int count, QWidget* parent)
{
    std::vector<QLineEdit*> edits;
    for (int i = 0; i < count; ++i)
        edits.push_back(new QLineEdit(parent));
    return edits;
}

QWidget* row(const std::vector<QLineEdit*>& edits, int columns, QWidget* parent)
{
    auto* holder = new QWidget(parent);
    auto* grid = new QGridLayout(holder);
    grid->setContentsMargins(0, 0, 0, 0);
    for (std::size_t i = 0; i < edits.size(); ++i)
        grid->addWidget(edits[i], static_cast<int>(i) / columns, static_cast<int>(i) % columns);
    return holder;
}

} // namespace

MassPropertiesGroup::MassPropertiesGroup(model::Document& document, Selection& selection, QWidget* parent)
    : QGroupBox(tr("Body"), parent)
    , document_(document)
    , selectedTrack_(document, selection)
    , source_(new QLabel(this))
    , typed_(new QCheckBox(tr("Type values"), this))
    , principal_(new QLabel(this))
    , message_(new QLabel(this))
    , refresh_(*this, 0, [this] { showSelectedObject(); })
{
    setObjectName(QStringLiteral("massPropertiesGroup"));
    typed_->setObjectName(QStringLiteral("massTypedCheck"));
    message_->setObjectName(QStringLiteral("massMessageLabel"));
    source_->setWordWrap(true);
    message_->setWordWrap(true);
    message_->hide();
    const std::vector<QLineEdit*> massEdit = lineEdits(1, this);
    const std::vector<QLineEdit*> centreEdits = lineEdits(3, this);
    const std::vector<QLineEdit*> inertiaEdits = lineEdits(6, this);
    massEdit[0]->setObjectName(QStringLiteral("massEdit"));
    for (int i = 0; i < 6; ++i)
        inertiaEdits[static_cast<std::size_t>(i)]->setObjectName(QStringLiteral("inertiaEdit%1").arg(i));
    const QStringList inertiaNames{tr("Ixx"), tr("Iyy"), tr("Izz"), tr("Ixy"), tr("Ixz"), tr("Iyz")};
    for (int i = 0; i < 6; ++i)
        inertiaEdits[static_cast<std::size_t>(i)]->setPlaceholderText(inertiaNames[i]);
    mass_ = new NumberFields(massEdit, {tr("mass")}, kMassDecimals, this);
    centre_ = new NumberFields(centreEdits, {tr("centre x"), tr("centre y"), tr("centre z")}, kMassDecimals, this);
    inertia_ = new NumberFields(inertiaEdits, inertiaNames, kMassDecimals, this);

    auto* form = new QFormLayout(this);
    form->addRow(source_);
    form->addRow(typed_);
    form->addRow(tr("Mass (kg)"), row(massEdit, 1, this));
    form->addRow(tr("Centre (m)"), row(centreEdits, 3, this));
    form->addRow(tr("Inertia (kg·m²)"), row(inertiaEdits, 3, this));
    form->addRow(tr("Principal"), principal_);
    form->addRow(message_);

    connect(typed_, &QCheckBox::clicked, this, &MassPropertiesGroup::applyTyped);
    for (NumberFields* fields : {mass_, centre_, inertia_})
        connect(fields, &NumberFields::editingFinished, this, &MassPropertiesGroup::applyFields);
    connect(&selectedTrack_, &SelectedTrack::changed, this, [this](model::Changes changes) {
        message_->hide();
        if (changes & (model::Change::Scene | model::Change::Object | SelectedTrack::kAnotherObject))
            refresh_.requestNow();
    });
    showSelectedObject();
}

void MassPropertiesGroup::showSelectedObject()
{
    const model::SceneObject* object = selectedTrack_.selectedObject();
    setEnabled(object != nullptr);
    const bool typed = object && object->massOverride;
    for (NumberFields* fields : {mass_, centre_, inertia_})
        for (QLineEdit* edit : fields->fields())
            edit->setReadOnly(!typed);
    if (!object) {
        for (NumberFields* fields : {mass_, centre_, inertia_})
            fields->clear();
        source_->clear();
        principal_->clear();
        typed_->setChecked(false);
        return;
    }
    const model::ObjectMass mass = model::objectMassProperties(*object);
    const MassProperties& properties = mass.properties;
    source_->setText(model::massSourceText(mass.source));
    typed_->setChecked(typed);
    mass_->show({properties.mass});
    centre_->show({properties.centre.x(), properties.centre.y(), properties.centre.z()});
    const InertiaComponents inertia = inertiaComponents(properties.inertia);
    const double noise = kInertiaNoise * properties.inertia.cwiseAbs().maxCoeff();
    inertia_->show(std::vector<double>(inertia.begin(), inertia.end()), noise);
    const Eigen::Vector3d moments = principalAxes(properties.inertia).moments;
    const auto momentText = [noise](double moment) { return roundedNumberText(moment, kMassDecimals, noise); };
    principal_->setText(tr("%1, %2, %3 kg·m²").arg(momentText(moments[0]), momentText(moments[1]), momentText(moments[2])));
}

void MassPropertiesGroup::applyTyped(bool typed)
{
    const model::SceneObject* object = selectedTrack_.selectedObject();
    if (!object)
        return;
    // Typing starts from the mesh's values, so ticking the box alone changes no motion.
    setOverride(typed ? std::optional(model::objectMassProperties(*object).properties) : std::nullopt);
}

void MassPropertiesGroup::applyFields()
{
    const model::SceneObject* object = selectedTrack_.selectedObject();
    if (!object || !object->massOverride)
        return;
    try {
        const MassProperties& before = *object->massOverride;
        MassProperties typed;
        typed.mass = mass_->values()[0];
        const std::vector<double> centre = centre_->values();
        typed.centre = Eigen::Vector3d(centre[0], centre[1], centre[2]);
        const std::vector<double> moments = inertia_->values();
        InertiaComponents components;
        std::copy(moments.begin(), moments.end(), components.begin());
        typed.inertia = inertiaTensor(components);
        // A new mass alone is the same shape, denser or lighter: the inertia scales with it, I ∝ m. Without this the
        // mass would change nothing the motion uses, which only the inertia and the centre do.
        if (typed.mass != before.mass && !inertia_->isEdited() && before.mass > 0.0 && typed.mass > 0.0)
            typed.inertia = before.inertia * (typed.mass / before.mass);
        setOverride(typed);
    } catch (const std::invalid_argument& error) {
        showSelectedObject();
        message_->setText(tr("Not changed: %1").arg(QString::fromUtf8(error.what())));
        message_->show();
    }
}

void MassPropertiesGroup::setOverride(const std::optional<MassProperties>& properties)
{
    message_->hide();
    try {
        document_.push(new model::SetMassOverrideCommand(document_, selectedTrack_.object(), properties));
    } catch (const std::invalid_argument& error) {
        showSelectedObject();
        message_->setText(tr("Not changed: %1").arg(QString::fromUtf8(error.what())));
        message_->show();
    }
}

} // namespace gyre::app
