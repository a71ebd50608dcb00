#pragma once
// The timeline: a ruler over the scene's time range, with a tick per frame (as many as fit) and labels
// in seconds and frames; the current time as a cursor line; and below the ruler the selected object's
// keyframes as markers, a filled diamond for a constrained key and a hollow one for a key the fit may
// move, the selected key highlighted.
//
// Pressing anywhere but on a marker scrubs: it pauses playback and sets the current time, which is
// not undoable (document.h). Pressing a marker selects its key; dragging it retimes the key, one undo
// step per drag, stopped before its neighbours so that it never passes them. Scrubbing and dragging
// snap to frames unless Shift is held. Left and Right step a frame, Home and End go to the range's
// ends.
//
// Everything but the cursor changes only with the keys, the selection, the time range, the size, the
// palette or the font, so it is drawn once into a pixmap (at the screen's device pixel ratio) and
// each frame of playback paints that pixmap and the cursor over it: a bone of a 31-joint capture, with
// 4,500 key markers, took about 50 ms a frame to draw, the pixmap 0.03 ms (tst_view_drawing, README.md).

#include "app/playback.h"
#include "app/selected_track.h"
#include "app/selection.h"
#include "model/document.h"
#include "model/gesture.h"

#include <QPixmap>
#include <QPoint>
#include <QRect>
#include <QWidget>

#include <cstddef>
#include <optional>
#include <vector>

namespace gyre::app {

class TimelineWidget : public QWidget {
    Q_OBJECT

public:
    TimelineWidget(model::Document& document, Selection& selection, Playback& playback, QWidget* parent = nullptr);

    // Where the scene's time range is drawn, left to right.
    double xForTime(double seconds) const;
    double timeAtX(double x) const;
    // The ruler strip across the top, and the strip of key markers below it.
    QRect rulerRect() const;
    QRect keyLaneRect() const;
    // The centre of the marker of the selected object's key at index `key`; none if there is no such key.
    std::optional<QPoint> keyMarkerCentre(std::size_t key) const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

    // How many times the ruler and the key markers have been drawn into the cached pixmap since the
    // widget was made: a change of the current time alone leaves it as it was.
    int staticLayerBuilds() const { return staticLayerBuilds_; }

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    // A key being dragged: its object and index, and how far right of its marker's centre the pointer
    // took it.
    struct KeyDrag {
        model::ObjectId object = model::kNoObject;
        std::size_t key = 0;
        double grabOffset = 0.0;
    };

    // Marks the cached ruler and key markers as stale and asks for a repaint.
    void invalidateStaticLayer();
    void rebuildStaticLayer();
    void paintRuler(QPainter& painter) const;
    void paintKeyMarkers(QPainter& painter) const;
    void paintCursor(QPainter& painter) const;

    // The selected object's key whose marker is under `point`, the nearest if several are.
    std::optional<std::size_t> keyAt(const QPoint& point) const;
    void scrubTo(double x, Qt::KeyboardModifiers modifiers);
    void dragKeyTo(double x, Qt::KeyboardModifiers modifiers);
    void endKeyDrag();
    // Where a drag of keys[key] toward `pointerTime` puts it: within the scene's range, on a frame if
    // `snap`, and strictly between its neighbours; the key's own time when there is no such place.
    double keyDragTime(const std::vector<model::Keyframe>& keys, std::size_t key, double pointerTime, bool snap) const;
    double snappedToFrame(double seconds) const;

    model::Document& document_;
    Selection& selection_;
    SelectedTrack selectedTrack_;
    Playback& playback_;
    std::optional<KeyDrag> keyDrag_;
    std::optional<model::Gesture> dragGesture_;
    bool scrubbing_ = false;
    QPixmap staticLayer_; // the ruler and the key markers, without the cursor
    bool staticLayerStale_ = true;
    int staticLayerBuilds_ = 0;
};

} // namespace gyre::app
