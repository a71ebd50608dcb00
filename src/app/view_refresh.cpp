#include "app/view_refresh.h"

#include <QEvent>
#include <QWidget>

#include <utility>

namespace gyre::app {

ViewRefresh::ViewRefresh(QWidget& view, int intervalMilliseconds, std::function<void()> refresh)
    : view_(view)
    , refresh_(std::move(refresh))
{
    timer_.setSingleShot(true);
    timer_.setInterval(intervalMilliseconds);
    connect(&timer_, &QTimer::timeout, this, [this] {
        // The view may have left the screen since the request.
        if (onScreen())
            refresh_();
        else
            stale_ = true;
    });
    view_.installEventFilter(this);
}

void ViewRefresh::request()
{
    if (!onScreen())
        stale_ = true;
    else if (!timer_.isActive())
        timer_.start();
}

void ViewRefresh::requestNow()
{
    if (!onScreen()) {
        stale_ = true;
        return;
    }
    timer_.stop();
    refresh_();
}

bool ViewRefresh::onScreen() const
{
    return view_.isVisible() && !view_.visibleRegion().isEmpty();
}

bool ViewRefresh::eventFilter(QObject* watched, QEvent* event)
{
    // A view coming back on screen is painted: that paint shows what it had, and the refresh follows.
    if (watched == &view_ && event->type() == QEvent::Paint && stale_) {
        stale_ = false;
        request();
    }
    return QObject::eventFilter(watched, event);
}

} // namespace gyre::app
