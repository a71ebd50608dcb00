#pragma once
// The Motion menu's keyframe actions on the selection: key the selected object's pose at the current
// time, delete the selected key, constrain or free it, run the Euler filter on the object's keys, step the
// current span of a ballistic track through its free flights. Each is one undo step; each is enabled only when
// it applies (the filter when it would change a key, the flight steps on a ballistic track of two keys or more).

#include "app/selected_track.h"
#include "app/selection.h"
#include "model/document.h"

#include <QObject>

class QAction;
class QStatusBar;

namespace gyre::app {

struct KeyframeActionSet {
    QAction* add = nullptr;
    QAction* remove = nullptr;
    QAction* toggleConstraint = nullptr; // checkable: checked when the selected key is constrained
    QAction* eulerFilter = nullptr;      // on the selected object's keys (apply_euler_filter_command.h)
    QAction* nextFlight = nullptr;       // the current span's next free flight (step_ballistic_solution_command.h)
    QAction* previousFlight = nullptr;
};

class KeyframeActions : public QObject {
    Q_OBJECT

public:
    // Says in `statusBar` why an action could not be done.
    KeyframeActions(model::Document& document, Selection& selection, KeyframeActionSet actions,
                    QStatusBar* statusBar, QObject* parent = nullptr);

    void addKeyframe();
    void removeKeyframe();
    void toggleConstraint();
    void applyEulerFilter();
    // direction +1 or −1: the selected ballistic track's span at the current time takes another flight.
    void stepFlightSolution(int direction);

private:
    void updateActions();

    model::Document& document_;
    Selection& selection_;
    SelectedTrack selectedTrack_;
    KeyframeActionSet actions_;
    QStatusBar* statusBar_;
};

} // namespace gyre::app
