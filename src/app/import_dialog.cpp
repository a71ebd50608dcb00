#include "app/import_dialog.h"

#include "model/value_checks.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QStandardItemModel>
#include <QTreeView>
#include <QVBoxLayout>

#include <algorithm>

namespace gyre::app {

namespace {

// What the dialog says about the automatic choice of takes.
QString takeChoiceText(const io::SceneImport& read)
{
    switch (read.takeRule) {
    case io::TakeRule::NoAnimation:
        return ImportDialog::tr("The file has no animation.");
    case io::TakeRule::Single:
        return ImportDialog::tr("The file has one animation.");
    case io::TakeRule::Disjoint:
        return ImportDialog::tr("Each animation moves nodes no other moves, so all are imported together.");
    case io::TakeRule::BlenderActions:
        return ImportDialog::tr("These are Blender's takes, one for every object and action: each object gets its "
                                "own action.");
    case io::TakeRule::ChoiceNeeded:
        return ImportDialog::tr("These animations move the same nodes: choose which to import. Checked ones are "
                                "merged; a node that several move takes the keys of the last one in the list.");
    case io::TakeRule::Chosen:
        break;
    }
    return {};
}

QString seconds(double value) { return ImportDialog::tr("%1 s").arg(value, 0, 'g', 4); }

// Whether the user changed a spin box from `value`, which it shows rounded to its decimals.
bool isChanged(const QDoubleSpinBox* box, double value)
{
    return box->value() != QString::number(value, 'f', box->decimals()).toDouble();
}

} // namespace

ImportDialog::ImportDialog(const QString& path, const io::SceneImport& firstRead, bool eulerFilter, QWidget* parent)
    : QDialog(parent)
    , defaultTakes_(firstRead.takes)
    , fileSettings_(firstRead.file.values)
    , takes_(new QStandardItemModel(0, ColumnCount, this))
    , takesView_(new QTreeView(this))
    , fps_(new QDoubleSpinBox(this))
    , unit_(new QDoubleSpinBox(this))
    , up_(new QComboBox(this))
    , origin_(new QComboBox(this))
    , eulerFilter_(new QCheckBox(tr("Euler filter: rotations in Euler mode (extrinsic xyz), angles continuous"), this))
    , buttons_(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
{
    setObjectName(QStringLiteral("importDialog"));
    setWindowTitle(tr("Import %1").arg(QFileInfo(path).fileName()));
    auto* layout = new QVBoxLayout(this);

    auto* choice = new QLabel(takeChoiceText(firstRead), this);
    choice->setWordWrap(true);
    layout->addWidget(choice);
    takes_->setHorizontalHeaderLabels({tr("Animation"), tr("Length"), tr("Moves")});
    for (std::size_t i = 0; i < firstRead.animations.size(); ++i) {
        const io::AnimationSummary& animation = firstRead.animations[i];
        auto* name = new QStandardItem(animation.name.isEmpty() ? tr("(unnamed %1)").arg(i) : animation.name);
        name->setCheckable(true);
        name->setEditable(false);
        const bool taken = std::find(defaultTakes_.begin(), defaultTakes_.end(), i) != defaultTakes_.end();
        name->setCheckState(taken ? Qt::Checked : Qt::Unchecked);
        auto* length = new QStandardItem(seconds(animation.durationSeconds));
        auto* nodes = new QStandardItem(animation.nodes.join(QStringLiteral(", ")));
        for (QStandardItem* item : {length, nodes})
            item->setEditable(false);
        nodes->setToolTip(animation.nodes.join(QLatin1Char('\n')));
        takes_->appendRow({name, length, nodes});
    }
    takesView_->setObjectName(QStringLiteral("importTakes"));
    takesView_->setModel(takes_);
    takesView_->setRootIsDecorated(false);
    takesView_->setAlternatingRowColors(true);
    takesView_->header()->setSectionResizeMode(NameColumn, QHeaderView::ResizeToContents);
    takesView_->setVisible(!firstRead.animations.empty());
    layout->addWidget(takesView_, 1);

    auto* form = new QFormLayout;
    const io::FileSettings& file = firstRead.file;
    fps_->setObjectName(QStringLiteral("importFps"));
    fps_->setRange(0.001, model::kMaxFps);
    fps_->setDecimals(3);
    fps_->setSuffix(tr(" fps"));
    fps_->setValue(file.values.fps);
    fps_->setToolTip(file.fpsSource);
    form->addRow(tr("Frame rate:"), fps_);
    unit_->setObjectName(QStringLiteral("importUnit"));
    unit_->setRange(1e-6, 1e6);
    unit_->setDecimals(6);
    unit_->setSuffix(tr(" m"));
    unit_->setValue(file.values.metresPerUnit);
    unit_->setToolTip(file.unitSource);
    form->addRow(tr("One unit of the file:"), unit_);
    up_->setObjectName(QStringLiteral("importUp"));
    up_->addItem(tr("Y up (turned to Z up)"), static_cast<int>(io::UpAxis::Y));
    up_->addItem(tr("Z up"), static_cast<int>(io::UpAxis::Z));
    up_->setCurrentIndex(up_->findData(static_cast<int>(file.values.up)));
    up_->setToolTip(file.upSource);
    form->addRow(tr("Up axis:"), up_);
    origin_->setObjectName(QStringLiteral("importTimeOrigin"));
    origin_->addItem(tr("First key at 0 s"), static_cast<int>(io::TimeOrigin::FirstKey));
    origin_->addItem(tr("As in the file"), static_cast<int>(io::TimeOrigin::File));
    form->addRow(tr("Time:"), origin_);
    eulerFilter_->setObjectName(QStringLiteral("importEulerFilter"));
    eulerFilter_->setChecked(eulerFilter);
    eulerFilter_->setToolTip(tr("Stores each imported rotation as Euler angles, Blender's default XYZ order, each key's "
                                "angles the nearest to the key before, so that a spin is a ramp, not a saw-tooth"));
    form->addRow(tr("Rotations:"), eulerFilter_);
    layout->addLayout(form);
    auto* sources = new QLabel(tr("From the file: %1; %2; %3.").arg(file.fpsSource, file.unitSource, file.upSource), this);
    sources->setWordWrap(true);
    layout->addWidget(sources);

    layout->addWidget(buttons_);
    connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(takes_, &QStandardItemModel::itemChanged, this, &ImportDialog::updateAcceptable);
    updateAcceptable();
    resize(620, 420);
}

std::vector<std::size_t> ImportDialog::checkedTakes() const
{
    std::vector<std::size_t> checked;
    for (int row = 0; row < takes_->rowCount(); ++row)
        if (takes_->item(row, NameColumn)->checkState() == Qt::Checked)
            checked.push_back(static_cast<std::size_t>(row));
    return checked;
}

io::ImportOptions ImportDialog::options() const
{
    io::ImportOptions options;
    if (takes_->rowCount() > 0) {
        options.takeSelection = io::TakeSelection::Listed;
        options.takes = checkedTakes();
    }
    // Unchanged, the file's own values, unrounded.
    if (isChanged(fps_, fileSettings_.fps))
        options.fps = fps_->value();
    if (isChanged(unit_, fileSettings_.metresPerUnit))
        options.metresPerUnit = unit_->value();
    options.up = static_cast<io::UpAxis>(up_->currentData().toInt());
    options.timeOrigin = static_cast<io::TimeOrigin>(origin_->currentData().toInt());
    return options;
}

bool ImportDialog::keepsTheDefaults() const
{
    std::vector<std::size_t> defaults = defaultTakes_;
    std::sort(defaults.begin(), defaults.end());
    return checkedTakes() == defaults && !isChanged(fps_, fileSettings_.fps) &&
           !isChanged(unit_, fileSettings_.metresPerUnit) &&
           static_cast<io::UpAxis>(up_->currentData().toInt()) == fileSettings_.up &&
           static_cast<io::TimeOrigin>(origin_->currentData().toInt()) == io::TimeOrigin::FirstKey;
}

bool ImportDialog::eulerFilter() const { return eulerFilter_->isChecked(); }

void ImportDialog::updateAcceptable()
{
    // A file with animations imports at least one; a file without any imports its meshes.
    buttons_->button(QDialogButtonBox::Ok)->setEnabled(takes_->rowCount() == 0 || !checkedTakes().empty());
}

} // namespace gyre::app
