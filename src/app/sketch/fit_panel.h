#pragma once
// The fit panel (the sketch-editing paper's Fig. 1, its fitting controls) for the selected object:
// the energy's weights α and β and the error bound δ, the edited window or the whole sketch, which
// keyframes the fit keeps exactly, and Fit, Cancel, Remove fit and Live. Every edit is one undo
// command on the document; the fit itself runs through the FitController it shares with the status
// bar's progress. A track that cannot be fitted (model::sketchFitProblem) says why here, and Fit is
// disabled.

#include "app/selected_track.h"
#include "app/selection.h"
#include "app/sketch/fit_controller.h"
#include "model/commands/object_fields.h"
#include "model/document.h"

#include <QWidget>

#include <functional>
#include <memory>
#include <optional>
#include <utility>

class QTableWidgetItem;
class QUndoCommand;

namespace Ui {
class FitPanel;
}

namespace gyre::app {

class FitPanel : public QWidget {
    Q_OBJECT

public:
    // With `controller`, shared with the status bar's FitProgress.
    FitPanel(model::Document& document, Selection& selection, FitController& controller, QWidget* parent = nullptr);
    ~FitPanel() override;

    FitController& controller() const { return controller_; }

private:
    void showSelectedTrack();
    void showWindow(const model::MotionTrack& track);
    void showKeys(const model::MotionTrack& track);
    void showFitProblem(const model::MotionTrack& track);
    void updateButtons();
    void setParameter(model::FitParameter parameter, double value);
    void applyWholeSketch(bool whole);
    void applyWindowEnds();
    void setWindow(std::optional<std::pair<double, double>> window);
    void toggleConstraint(QTableWidgetItem* item);
    void removeFit();
    // Pushes `command` as one undo step; a command the document refuses is reported in the panel.
    void push(const std::function<QUndoCommand*()>& makeCommand);
    void showStatus(const QString& message);

    std::unique_ptr<Ui::FitPanel> ui_;
    model::Document& document_;
    Selection& selection_;
    SelectedTrack selectedTrack_;
    // The fields follow the selected track at once, on screen or not, so that the Fit button is
    // enabled rightly the moment the panel is raised (whether the track can be fitted is
    // sketchFitProblem's answer, quick beside a fit).
    FitController& controller_;
    bool fittable_ = false;
};

} // namespace gyre::app
