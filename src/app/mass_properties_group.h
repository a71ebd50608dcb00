#pragma once
// The Inspector's Body group: the selected object's mass, centre of mass and inertia tensor, which its
// angular momentum and free flight use (model/object_mass.h). They come from the mesh unless the artist
// ticks "Type values", after which the fields edit them; each edit is one undo step, and unticking goes
// back to the mesh's. The principal moments are shown beside them, for reading which axis is which.

#include "app/number_fields.h"
#include "app/selected_track.h"
#include "app/selection.h"
#include "app/view_refresh.h"
#include "model/document.h"

#include <QGroupBox>

class QCheckBox;
class QLabel;

namespace gyre::app {

class MassPropertiesGroup : public QGroupBox {
    Q_OBJECT

public:
    MassPropertiesGroup(model::Document& document, Selection& selection, QWidget* parent = nullptr);

private:
    void showSelectedObject();
    void applyTyped(bool typed);
    void applyFields();
    // Pushes the override; a refusal (a body that cannot be) is shown under the fields.
    void setOverride(const std::optional<MassProperties>& properties);

    model::Document& document_;
    SelectedTrack selectedTrack_;
    QLabel* source_;
    QCheckBox* typed_;
    NumberFields* mass_;
    NumberFields* centre_;
    NumberFields* inertia_;
    QLabel* principal_;
    QLabel* message_;
    ViewRefresh refresh_;
};

} // namespace gyre::app
