#pragma once
// One step of the undo history: the commands of one gesture, done in order and undone in reverse.
// Document::push wraps every command it pushes in one; a command pushed with no gesture is a step of
// its own.
//
// Why a step command rather than a QUndoStack macro or the gesture's first command taking the rest
// as children: a macro's state can only be inferred from the stack (Qt has no query for an open
// macro), an open macro swallows every push from elsewhere, and a macro that ends empty stays in the
// history as a step that does nothing. A first command cannot adopt later ones (QUndoCommand takes
// children only when they are built), and a gesture mixes kinds: the sphere view adds a stroke, then
// edits it; erasing edits, erases and adds. A step of its own carries the gesture id, so QUndoStack
// merges consecutive pushes of one gesture into it (id() and mergeWith, the documented way), never
// pushes of two gestures; and when its commands bring the document back to where the gesture began
// it marks itself obsolete, and the stack deletes it (QUndoCommand::setObsolete, Qt 5.9), as Tiled
// does with its merged ChangeValue.

#include "model/document.h"

#include <QUndoCommand>

#include <memory>
#include <vector>

namespace gyre::model {

class PerformGestureCommand final : public QUndoCommand {
public:
    // Takes `command`; the step is named after it.
    PerformGestureCommand(GestureId gesture, QUndoCommand* command);

    GestureId gesture() const { return gesture_; }

    void redo() override;
    void undo() override;
    // Steps of a gesture share one id; a step of no gesture has -1 and never merges.
    int id() const override;
    // Takes in the commands of `other`, a later step, if it belongs to the same gesture. Each merges
    // with the command before it where both are MergeableCommands that change the same thing; one
    // that then changes nothing goes, and a step left with no commands is obsolete.
    bool mergeWith(const QUndoCommand* other) override;

private:
    void append(const std::shared_ptr<QUndoCommand>& command);

    GestureId gesture_;
    // Shared so that mergeWith can take them from the step it merges, which the stack then deletes.
    std::vector<std::shared_ptr<QUndoCommand>> commands_;
    bool pushed_ = false; // the first redo is the push
};

} // namespace gyre::model
