#include "app/playback.h"

#include <algorithm>
#include <cmath>

namespace gyre::app {

namespace {

// About 60 updates a second; the time shown comes from the clock, so a late tick skips, never slows.
constexpr int kTickMilliseconds = 16;

} // namespace

Playback::Playback(model::Document& document, QObject* parent)
    : QObject(parent)
    , document_(document)
{
    timer_.setTimerType(Qt::PreciseTimer);
    timer_.setInterval(kTickMilliseconds);
    connect(&timer_, &QTimer::timeout, this, &Playback::advance);
    connect(&document_, &model::Document::changed, this, [this](model::ObjectId, model::Changes changes) {
        if (changes.testFlag(model::Change::Scene))
            pause();
    });
}

void Playback::play()
{
    if (isPlaying())
        return;
    const model::Scene& scene = document_.scene();
    if (scene.currentTime >= scene.endTime)
        document_.setCurrentTime(scene.startTime);
    playedFrom_ = document_.scene().currentTime;
    clock_.start();
    timer_.start();
    emit playingChanged(true);
}

void Playback::pause()
{
    if (!isPlaying())
        return;
    timer_.stop();
    // Playing passes between frames; it stops on the nearest one, the frame the time bar names, so
    // that a key made now lands on it.
    const model::Scene& scene = document_.scene();
    const double frame = std::round(scene.currentTime * scene.fps);
    document_.setCurrentTime(std::clamp(frame / scene.fps, scene.startTime, scene.endTime));
    emit playingChanged(false);
}

void Playback::togglePlaying()
{
    if (isPlaying())
        pause();
    else
        play();
}

void Playback::stepForward()
{
    step(1);
}

void Playback::stepBackward()
{
    step(-1);
}

void Playback::goToStart()
{
    pause();
    document_.setCurrentTime(document_.scene().startTime);
}

void Playback::goToEnd()
{
    pause();
    document_.setCurrentTime(document_.scene().endTime);
}

void Playback::setLoops(bool loops) { loops_ = loops; }

void Playback::advance()
{
    const model::Scene& scene = document_.scene();
    const double duration = scene.endTime - scene.startTime;
    double time = playedFrom_ + static_cast<double>(clock_.elapsed()) / 1000.0;
    if (time >= scene.endTime) {
        if (!loops_) {
            document_.setCurrentTime(scene.endTime);
            pause();
            return;
        }
        time = scene.startTime + std::fmod(time - scene.startTime, duration);
    }
    document_.setCurrentTime(time);
}

void Playback::step(int frames)
{
    pause();
    const model::Scene& scene = document_.scene();
    // From the frame the current time is on (or just past), to the neighbouring frame.
    const double frame = (scene.currentTime - scene.startTime) * scene.fps;
    const double onFrame = std::abs(frame - std::round(frame)) < 1e-6 ? std::round(frame)
                                                                       : (frames > 0 ? std::floor(frame) : std::ceil(frame));
    const double time = scene.startTime + (onFrame + frames) / scene.fps;
    document_.setCurrentTime(std::clamp(time, scene.startTime, scene.endTime));
}

} // namespace gyre::app
