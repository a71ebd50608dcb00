#include "app/undo_gesture.h"

namespace gyre::app {

void UndoGesture::push(QUndoCommand* command)
{
    if (!open_) {
        stack_.beginMacro(command->text());
        open_ = true;
    }
    stack_.push(command);
}

void UndoGesture::finish()
{
    if (!open_)
        return;
    open_ = false;
    stack_.endMacro();
}

void pushAlone(QUndoStack& stack, QUndoCommand* command)
{
    UndoGesture gesture(stack);
    gesture.push(command);
}

bool isMacroOpen(const QUndoStack& stack)
{
    return stack.index() < stack.count() && !stack.canRedo();
}

} // namespace gyre::app
