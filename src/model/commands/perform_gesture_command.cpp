#include "model/commands/perform_gesture_command.h"

#include "model/commands/mergeable_command.h"

namespace gyre::model {

namespace {

// Unique among the ids of commands on the stack: no other command overrides QUndoCommand::id().
constexpr int kGestureStepId = 1;

bool changesNothing(const QUndoCommand& command)
{
    const auto* mergeable = dynamic_cast<const MergeableCommand*>(&command);
    return mergeable != nullptr && mergeable->changesNothing();
}

} // namespace

PerformGestureCommand::PerformGestureCommand(GestureId gesture, QUndoCommand* command)
    : QUndoCommand(command->text())
    , gesture_(gesture)
    , commands_{std::shared_ptr<QUndoCommand>(command)}
{
}

void PerformGestureCommand::redo()
{
    for (const std::shared_ptr<QUndoCommand>& command : commands_)
        command->redo();
    // The push of a gesture's first edit: if it changed nothing (a drag that has not moved yet),
    // the gesture has no step so far.
    if (!pushed_ && gesture_ != kNoGesture && !commands_.empty() && changesNothing(*commands_.front())) {
        commands_.clear();
        setObsolete(true);
    }
    pushed_ = true;
}

void PerformGestureCommand::undo()
{
    for (auto command = commands_.rbegin(); command != commands_.rend(); ++command)
        (*command)->undo();
}

int PerformGestureCommand::id() const { return gesture_ == kNoGesture ? -1 : kGestureStepId; }

bool PerformGestureCommand::mergeWith(const QUndoCommand* other)
{
    // The stack asks only when other->id() == id(), which only steps of a gesture have.
    const auto& later = static_cast<const PerformGestureCommand&>(*other);
    if (later.gesture_ != gesture_)
        return false;
    for (const std::shared_ptr<QUndoCommand>& command : later.commands_)
        append(command);
    if (commands_.empty())
        setObsolete(true);
    return true;
}

void PerformGestureCommand::append(const std::shared_ptr<QUndoCommand>& command)
{
    // Only with the last command: merging with an earlier one would reorder edits, and a later edit
    // may depend on those between (a stroke's index after another was erased).
    auto* last = commands_.empty() ? nullptr : dynamic_cast<MergeableCommand*>(commands_.back().get());
    const auto* incoming = dynamic_cast<const MergeableCommand*>(command.get());
    if (last != nullptr && incoming != nullptr && last->mergeWithin(*incoming)) {
        if (last->changesNothing())
            commands_.pop_back();
        return;
    }
    commands_.push_back(command);
}

} // namespace gyre::model
