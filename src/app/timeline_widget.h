#pragma once
// The timeline: a ruler over the scene's time range, with a tick per frame (as many as fit) and labels
// in seconds and frames; the current time as a cursor line; and below the ruler a dope sheet: a row
// of key markers for each selected object (the first kMaxRows in the scene's order, the active
// object always among them), a filled diamond for a constrained key and a hollow one for a key the
// fit may move, the selected keys highlighted.
//
// Pressing the ruler, or clicking between markers, scrubs: it pauses playback and sets the current
// time, which is not undoable (document.h); a click between markers also deselects the keys. A drag
// between markers draws a box and selects the keys in it (Shift adds them). Pressing a marker selects
// its key (a click on a key already selected selects it alone); Shift+click adds it to the selected
// keys or takes it out. Dragging a marker moves every
// selected key, of every row, by the same time, one undo step per drag: the shift stops where a moved
// key would come within a frame (1 ms with Shift) of a key that is not moved, or leave the range, so
// keys never cross or land on each other. Scrubbing and dragging snap to frames unless Shift is held.
// Left and Right step a frame, Home and End go to the range's ends.
//
// Everything but the cursor changes only with the keys, the selection, the time range, the size, the
// palette or the font, so it is drawn once into a pixmap (at the screen's device pixel ratio) and
// each frame of playback paints that pixmap and the cursor over it: a bone of a 31-joint capture, with
// 4,500 key markers, took about 50 ms a frame to draw, the pixmap 0.03 ms (tst_view_drawing, README.md).

#include "app/playback.h"
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
    // At most this many objects have a row of keys.
    static constexpr std::size_t kMaxRows = 8;

    // The ruler strip across the top, and the strip of key rows below it.
    QRect rulerRect() const;
    QRect keyLaneRect() const;
    // The objects whose keys are drawn, top to bottom.
    std::vector<model::ObjectId> rows() const;
    QRect rowRect(std::size_t row, std::size_t rowCount) const;
    // The centre of the marker of the active object's key at index `key`, or of `object`'s; none if
    // there is no such key or it has no row.
    std::optional<QPoint> keyMarkerCentre(std::size_t key) const;
    std::optional<QPoint> keyMarkerCentre(model::ObjectId object, std::size_t key) const;

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
    // The selected keys being dragged: each object's keys as they were at the press and the indices
    // moved; the key pressed, whose time snaps to frames; the time under the pointer at the press.
    struct KeyDrag {
        struct Moved {
            model::ObjectId object = model::kNoObject;
            std::vector<model::Keyframe> keys;
            std::vector<std::size_t> indices;
        };
        std::vector<Moved> objects;
        double pressedKeyTime = 0.0;
        double pressTime = 0.0;
        double shift = 0.0; // the shift pushed last
        // The pressed key, if it was selected already: a click (no move) then selects it alone.
        std::optional<KeyRef> selectsOnClick;
    };
    // A press between markers: a box while it is dragged, a click (scrub) if it is not.
    struct BoxPress {
        QPoint from;
        QPoint to;
        bool dragged = false;
    };

    // Marks the cached ruler and key markers as stale and asks for a repaint.
    void invalidateStaticLayer();
    void rebuildStaticLayer();
    void paintRuler(QPainter& painter) const;
    void paintKeyMarkers(QPainter& painter) const;
    void paintCursor(QPainter& painter) const;

    // The key whose marker is under `point`, in the row under it, the nearest if several are.
    std::optional<KeyRef> keyAt(const QPoint& point) const;
    void pressKey(const KeyRef& key, const QMouseEvent& event);
    void startKeyDrag(const KeyRef& pressed, double pressTime, bool selectsOnClick);
    void scrubTo(double x, Qt::KeyboardModifiers modifiers);
    void dragKeysTo(double x, Qt::KeyboardModifiers modifiers);
    void endKeyDrag();
    void finishBox(Qt::KeyboardModifiers modifiers);
    void paintBox(QPainter& painter) const;
    double snappedToFrame(double seconds) const;

    model::Document& document_;
    Selection& selection_;
    Playback& playback_;
    std::optional<KeyDrag> keyDrag_;
    // A Shift+press on a marker: a toggle of its key if released unmoved, else a drag of the keys.
    std::optional<std::pair<KeyRef, QPoint>> shiftPress_;
    std::optional<BoxPress> box_;
    std::optional<model::Gesture> dragGesture_;
    bool scrubbing_ = false;
    QPixmap staticLayer_; // the ruler and the key markers, without the cursor
    bool staticLayerStale_ = true;
    int staticLayerBuilds_ = 0;
};

} // namespace gyre::app
