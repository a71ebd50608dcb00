#pragma once
// A command whose consecutive edits within one gesture combine into one, as a drag that pushes a
// command at every mouse move needs. Only PerformGestureCommand merges them, and only within its
// gesture: these commands keep QUndoCommand::id() at -1, so QUndoStack itself never merges them and
// two edits pushed outside a gesture stay two steps.

#include <QUndoCommand>

namespace gyre::model {

class MergeableCommand : public QUndoCommand {
public:
    using QUndoCommand::QUndoCommand;

    // Takes in `later`, pushed right after this command within the same gesture and already done,
    // if it changes the same thing: undoing this command then undoes both. Whether it did.
    virtual bool mergeWithin(const MergeableCommand& later) = 0;
    // Whether this command, done, leaves the document as undo would restore it: it changes nothing,
    // or the edits it merged came back to where it began.
    virtual bool changesNothing() const = 0;
};

} // namespace gyre::model
