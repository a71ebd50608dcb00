#pragma once
// A view's refresh after the document changed, done only while the view is on screen and at most
// once per interval however many changes arrive. A view refreshes, replots or samples what it shows
// through this, not straight from the document's signals: a drag changes a key at every mouse move,
// and a view nobody sees must not spend the UI thread on it (issue 18).
//
// Off screen means hidden (its dock closed, the widget not shown) or tabbed behind another dock:
// Qt keeps such a dock visible but moves it out of the window, so its region is empty. A request
// made off screen only marks the view stale; the view's next paint, which comes when it is on screen
// again, refreshes it once. On screen, the first request starts a single-shot timer that later
// requests do not restart, so while a key is dragged the view follows every interval instead of
// waiting for the drag to end; an interval of zero refreshes once at the next turn of the event loop.
// A form, whose fields should show an edit as soon as it is made, refreshes at once (requestNow)
// while it is on screen, and like any view only once it is back when off screen.

#include <QObject>
#include <QTimer>

#include <functional>

class QWidget;

namespace gyre::app {

class ViewRefresh : public QObject {
public:
    // `view` owns this (it is a member), so the view outlives it.
    ViewRefresh(QWidget& view, int intervalMilliseconds, std::function<void()> refresh);

    // Refreshes the view within the interval if it is on screen, else once it is shown again.
    void request();
    // Refreshes the view now if it is on screen, else once it is shown again.
    void requestNow();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    bool onScreen() const;

    QWidget& view_;
    std::function<void()> refresh_;
    QTimer timer_;
    bool stale_ = false; // asked for while off screen
};

} // namespace gyre::app
