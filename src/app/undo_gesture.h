#pragma once
// One gesture of the artist, one undo step. The model's commands merge consecutive edits of the same
// field (a drag sends hundreds), which would also merge two separate drags of the same key, or two
// fields typed one after the other. A gesture wraps its commands in a macro of their own: they still
// merge with each other inside it, but the next gesture starts a new step.

#include <QUndoStack>

namespace gyre::app {

class UndoGesture {
public:
    explicit UndoGesture(QUndoStack& stack)
        : stack_(stack)
    {
    }
    ~UndoGesture() { finish(); }
    UndoGesture(const UndoGesture&) = delete;
    UndoGesture& operator=(const UndoGesture&) = delete;

    // Pushes `command` (taking it) as part of this gesture; the first push opens the gesture's
    // undo step, named as that command.
    void push(QUndoCommand* command);
    // Ends the gesture: its step is complete, and the next push starts another.
    void finish();
    bool isOpen() const { return open_; }

private:
    QUndoStack& stack_;
    bool open_ = false;
};

// Pushes `command` as an undo step of its own, never merged with the step before it.
void pushAlone(QUndoStack& stack, QUndoCommand* command);

// Whether a gesture, or any macro, is open on `stack`. QUndoStack has no query for it, but an open
// macro is already in its command list, at index(), while canRedo() says false until it ends;
// otherwise a command at index() is one to redo.
bool isMacroOpen(const QUndoStack& stack);

} // namespace gyre::app
