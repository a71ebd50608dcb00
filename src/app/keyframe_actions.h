#pragma once
// The Motion menu's keyframe actions on the selection: key every selected object's pose at the
// current time, delete every selected key, constrain or free the active key, run the Euler filter on
// the active object's keys; and Edit ▸ Select All Keys / Select No Keys. Each edit is one undo step
// however many objects it touches; each action is enabled only when it applies (the filter when it
// would change a key).

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
    QAction* selectAll = nullptr;        // every key of the active object
    QAction* selectNone = nullptr;
};

class KeyframeActions : public QObject {
    Q_OBJECT

public:
    // Says in `statusBar` why an action could not be done.
    KeyframeActions(model::Document& document, Selection& selection, KeyframeActionSet actions,
                    QStatusBar* statusBar, QObject* parent = nullptr);

    // Keys each selected object that has no key at the current time; selects the new keys.
    void addKeyframes();
    void removeKeyframes();
    void toggleConstraint();
    void applyEulerFilter();

private:
    void updateActions();

    model::Document& document_;
    Selection& selection_;
    SelectedTrack selectedTrack_;
    KeyframeActionSet actions_;
    QStatusBar* statusBar_;
};

} // namespace gyre::app
