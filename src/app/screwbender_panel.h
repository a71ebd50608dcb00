#pragma once
// The ScrewBender panel: how the selected object's track interpolates between its keyframes, and,
// for screw motion, how the polyscrew is subdivided (scheme, levels, cyclic or open, and the
// decoupled alternative for comparison), with the number of poses that gives. Each change is one
// undo command on the document.

#include "app/selected_track.h"
#include "app/selection.h"
#include "app/view_refresh.h"
#include "model/document.h"

#include <QWidget>

class QUndoCommand;

#include <memory>

namespace Ui {
class ScrewBenderPanel;
}

namespace gyre::app {

class ScrewBenderPanel : public QWidget {
    Q_OBJECT

public:
    ScrewBenderPanel(model::Document& document, Selection& selection, QWidget* parent = nullptr);
    ~ScrewBenderPanel() override;

private:
    void showSelectedTrack();
    void applyInterpolation();
    // The undo step that makes the selected track interpolate by `method`; a new screw track is open.
    // Throws std::invalid_argument as the commands do.
    QUndoCommand* interpolationChange(InterpolationMethod method) const;
    // Sets the track's subdivision to what the scheme, levels, sequence and decoupled widgets show.
    void applySubdivision();
    void showError(const QString& message);

    std::unique_ptr<Ui::ScrewBenderPanel> ui_;
    model::Document& document_;
    Selection& selection_;
    SelectedTrack selectedTrack_;
    // The fields follow the selected track while the form is on screen, and catch up when it is back.
    ViewRefresh refresh_;
};

} // namespace gyre::app
