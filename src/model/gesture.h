#pragma once
// A gesture a view holds while the artist drags, from press to release: it begins on the
// document when made and ends when finished or destroyed, so the document must outlive it. Every
// command pushed through it joins its undo step (document.h, "Gestures").

#include "model/document.h"

#include <QUndoCommand>

namespace gyre::model {

class Gesture {
public:
    explicit Gesture(Document& document)
        : document_(document)
        , id_(document.beginGesture())
    {
    }
    ~Gesture() { finish(); }
    Gesture(const Gesture&) = delete;
    Gesture& operator=(const Gesture&) = delete;

    GestureId id() const { return id_; }
    // Pushes `command` (taking it) as part of this gesture.
    void push(QUndoCommand* command) { document_.push(command, id_); }
    // Whether the newest undo step is this gesture's: it has changed the document, and that change
    // is still what undo would take back.
    bool hasStep() const { return document_.newestStepGesture() == id_; }
    // Ends the gesture; nothing if it has ended.
    void finish() { document_.endGesture(id_); }

private:
    Document& document_;
    GestureId id_;
};

} // namespace gyre::model
