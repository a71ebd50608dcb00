#pragma once
// Playing the scene: moves the document's current time at wall-clock speed between the scene's start
// and end, stepping a frame at a time, looping or stopping at the end; paused, it rests on a frame
// (a multiple of 1/fps, as keys snap to). Scrubbing and playing change
// only the current time, which is not undoable (document.h).

#include "model/document.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace gyre::app {

class Playback : public QObject {
    Q_OBJECT

public:
    explicit Playback(model::Document& document, QObject* parent = nullptr);

    bool isPlaying() const { return timer_.isActive(); }
    bool loops() const { return loops_; }

    void play();
    void pause();
    void togglePlaying();
    // One frame (1/fps) later or earlier, within the scene's range; pauses playback.
    void stepForward();
    void stepBackward();
    void goToStart();
    void goToEnd();
    void setLoops(bool loops);

signals:
    void playingChanged(bool playing);

private:
    void advance();
    void step(int frames);

    model::Document& document_;
    QTimer timer_;
    QElapsedTimer clock_;
    double playedFrom_ = 0.0; // the current time when clock_ started
    bool loops_ = true;
};

} // namespace gyre::app
