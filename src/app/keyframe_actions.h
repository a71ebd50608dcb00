#pragma once
// The Motion menu's keyframe actions on the selection: key every selected object's pose at the
// current time, delete every selected key, constrain or free the active key, run the Euler filter on
// the selected keys (with no key selected, on every selected object's keys), step the current span of a ballistic track through its free flights; and
// Edit ▸ Select All Keys / Select No Keys. Each edit is one undo step however many objects it touches;
// each action is enabled only when it applies (the filter when it would change a key, the flight steps
// on a ballistic track of two keys or more).

#include "app/selected_track.h"
#include "app/selection.h"
#include "model/commands/apply_euler_filter_command.h"
#include "model/document.h"

#include <QObject>

#include <unordered_map>

class QAction;
class QStatusBar;

namespace gyre::app {

struct KeyframeActionSet {
    QAction* add = nullptr;
    QAction* remove = nullptr;
    QAction* toggleConstraint = nullptr; // checkable: checked when the selected key is constrained
    QAction* eulerFilter = nullptr;      // on the selected keys, or the selected objects' (apply_euler_filter_command.h)
    QAction* nextFlight = nullptr;       // the current span's next free flight (step_ballistic_solution_command.h)
    QAction* previousFlight = nullptr;
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
    // direction +1 or −1: the selected ballistic track's span at the current time takes another flight.
    void stepFlightSolution(int direction);

private:
    void updateActions();
    // The keys of a selected object the Euler filter works on: its selected keys (none, if others have keys
    // selected and it has not), or with no key selected all of them.
    model::ApplyEulerFilterCommand::KeySubset keysToFilter(model::ObjectId object) const;
    // Whether the filter would change a key of keysToFilter(object) (ApplyEulerFilterCommand::changes),
    // remembered while the object's keys, rotation mode and keys to filter stay the same.
    bool eulerFilterChanges(model::ObjectId object) const;

    // One object's answer to eulerFilterChanges and what it was computed from. Holding the track's keys
    // shares their elements, so an edit, which copies them first (shared_vector.h), shows as a new
    // storage; a reference taken from the keys before this copy must not be written through after it.
    // A drag of one key then reads that object's keys alone, not every selected object's: with the
    // 31-joint capture all selected, 0.4 ms of the UI thread a step against 1.7 to 2.5 ms
    // (tst_view_drawing measuresAKeyEditWithEveryObjectSelected, Release).
    struct EulerFilterAnswer {
        model::SharedVector<model::Keyframe> keys;
        model::RotationMode rotationMode;
        model::ApplyEulerFilterCommand::KeySubset subset;
        bool changes = false;
    };

    model::Document& document_;
    Selection& selection_;
    SelectedTrack selectedTrack_;
    KeyframeActionSet actions_;
    QStatusBar* statusBar_;
    // The selected objects' answers; updateActions forgets the others'.
    mutable std::unordered_map<model::ObjectId, EulerFilterAnswer> eulerFilterAnswers_;
};

} // namespace gyre::app
