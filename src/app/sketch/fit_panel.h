#pragma once
// The fit panel (the sketch-editing paper's Fig. 1, its fitting controls) for the selected object:
// the energy's weights α and β and the error bound δ, the edited window or the whole sketch, which
// keyframes the fit keeps exactly, and Fit, Cancel, Remove fit and Live. Every edit is one undo
// command on the document; the fit itself runs through the FitController it shares with the status
// bar's progress. A track that cannot be fitted (model::checkSketchFittable) says why here, and Fit is
// disabled; what only building the fit finds (a stroke the fit cannot follow) is said when Fit runs.
//
// A drag changes the selected track at every mouse move, and the panel follows it on the UI thread:
// the fields and the Fit button at once, on screen or not, so that the Fit button is right the moment
// the panel is raised (each is a few numbers and checkSketchFittable, which reads no motion); the key
// table, a row per key, only while on screen (ViewRefresh), and by changing the rows' texts and check
// marks where they differ rather than making its items anew.

#include "app/selected_track.h"
#include "app/selection.h"
#include "app/sketch/fit_controller.h"
#include "app/view_refresh.h"
#include "model/commands/object_fields.h"
#include "model/document.h"

#include <QWidget>

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

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
    // The selected object's keys in the table.
    void showKeys();
    void showFitProblem(const model::MotionTrack& track);
    void updateButtons();
    void setParameter(model::FitParameter parameter, double value);
    void applyWholeSketch(bool whole);
    void applyWindowEnds();
    void setWindow(std::optional<std::pair<double, double>> window);
    void toggleConstraint(QTableWidgetItem* item);
    void removeFit();
    void setPhysicsTarget();
    // Pushes `command` as one undo step; a command the document refuses is reported in the panel.
    void push(const std::function<QUndoCommand*()>& makeCommand);
    void showStatus(const QString& message);

    std::unique_ptr<Ui::FitPanel> ui_;
    model::Document& document_;
    Selection& selection_;
    SelectedTrack selectedTrack_;
    FitController& controller_;
    bool fittable_ = false;
    // What the key table shows of each key: its time and whether it is constrained.
    struct ShownKey {
        double time = 0.0;
        bool constrained = false;
        bool operator==(const ShownKey&) const = default;
    };
    std::vector<ShownKey> shownKeys_;
    ViewRefresh keysRefresh_;
};

} // namespace gyre::app
