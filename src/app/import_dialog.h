#pragma once
// The import dialog: after a scene file is first read with the options its defaults, it lists the
// file's animations (takes) with their length and the nodes each moves, those the automatic choice
// took checked, and the settings read from the file (frame rate, unit, up axis, time origin), each
// editable. File > Import Scene always shows it; a dropped or opened file only when its takes
// overlap and no default is sure (TakeRule::ChoiceNeeded). Its "Euler filter" box is Gyre's own option, applied
// to the objects read (model::putInEulerMode), not to the reading: it leaves keepsTheDefaults as it is.

#include "io/scene_import.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QStandardItemModel;
class QTreeView;

namespace gyre::app {

class ImportDialog : public QDialog {
    Q_OBJECT

public:
    // The columns of the takes list.
    enum Column { NameColumn, LengthColumn, NodesColumn, ColumnCount };

    // `firstRead` is the file read with the default options: its takes, what the file says, and the
    // automatic choice.
    // `eulerFilter` is the Euler filter box's first state.
    ImportDialog(const QString& path, const io::SceneImport& firstRead, bool eulerFilter, QWidget* parent = nullptr);

    // The options as the dialog now says them: the checked takes in the file's order, the settings.
    io::ImportOptions options() const;
    // Whether those are the defaults the first read used, so that its scene can be kept as it is.
    bool keepsTheDefaults() const;
    // Whether the rotation tracks are to be put in Euler mode with continuous angles.
    bool eulerFilter() const;

    QStandardItemModel* takes() const { return takes_; }
    QDoubleSpinBox* fps() const { return fps_; }
    QDoubleSpinBox* unit() const { return unit_; }
    QComboBox* upAxis() const { return up_; }
    QComboBox* timeOrigin() const { return origin_; }
    QCheckBox* eulerFilterBox() const { return eulerFilter_; }

private:
    std::vector<std::size_t> checkedTakes() const;
    void updateAcceptable();

    std::vector<std::size_t> defaultTakes_;
    io::ImportSettings fileSettings_;
    QStandardItemModel* takes_;
    QTreeView* takesView_;
    QDoubleSpinBox* fps_;
    QDoubleSpinBox* unit_;
    QComboBox* up_;
    QComboBox* origin_;
    QCheckBox* eulerFilter_;
    QDialogButtonBox* buttons_;
};

} // namespace gyre::app
