#pragma once
// The magnitude-time plane of the sketch-editing paper (Fig. 1, left) for the selected object: time
// across over the scene's range, the angular speed |ω| up in rad/s (the right axis in °/s).
//
// - The current curve |ω(t)| of the track's motion, sampled by a job of the plot's own (a
//   screw track with many subdivision levels is slow to build), at most every
//   SelectedTrackSampler::kIntervalMilliseconds while the track changes and not while the plot is off
//   screen. Only a curve that changed is set again, and the plot replots only then: a key moved but
//   not turned, at every move of a drag, left the speed as it was yet cost a quarter of the UI
//   thread's time (issue 18). The keys on it, filled where constrained and hollow where the fit may
//   move them, as the timeline draws them.
// - The current time as a vertical line.
// - The edit window as a shaded band: the sketch's own window solid; the one the fit would take
//   without it (model::editWindow, else the keys' span) dashed and lighter. Dragging an edge resizes
//   it, dragging the grip strip along its top moves it at the same length; each drag is one undo
//   step, clamped to the keys' span and at least a frame long.
// - The sketched magnitude in blue. In the Draw tool a left drag draws it: time only goes forward,
//   and going back erases what this drag drew past the pen, as a pen going back would. The drawn span
//   replaces the curve's points inside it and keeps those outside; the curve follows every move
//   (so a live fit can follow the pen), one undo step per drag. Values below zero become zero.
// - After a fit, |ω| of the fitted motion over the fit's span in red, and in grey dashed the motion
//   without its fit, to compare before and after.
//
// The window's edges and grip take the press in the Pan tool, and in the Draw tool when the window is
// the sketch's own: the dashed window of a track without one spans the keys, where strokes start, and
// the pen draws over it. In the Pan tool a left drag pans; in both the wheel zooms time. Double-click
// or Fit view shows the scene's range and the curves' height. The height follows the curves when the
// motion changes (an edit, a fit), but not while a drag on the plot is open, so the pen's scale never
// moves under it, nor once the artist has zoomed or panned, until Fit view; another object, scene or
// time range refits both axes.

#include "app/selection.h"
#include "app/selected_track.h"
#include "app/selected_track_sampler.h"
#include "app/view_refresh.h"
#include "model/document.h"
#include "model/gesture.h"

#include <QPointF>
#include <QRect>
#include <QTimer>
#include <QWidget>

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

class QAction;
class QCPGraph;
class QCPItemRect;
class QCPItemStraightLine;
class QCustomPlot;
class QLabel;
class QStackedLayout;

namespace gyre::app {

class MagnitudePlot : public QWidget {
    Q_OBJECT

public:
    // Samples of the current curve over the scene's range, and of the fitted curves over the fit's span.
    static constexpr int kSampleCount = 2000;
    static constexpr int kFittedSampleCount = 600;
    // The grip strip along the top of the window band, and how near an edge a press takes it, pixels.
    static constexpr int kGripHeight = 16;
    static constexpr int kEdgeReach = 5;

    enum class Curve { Current, Sketched, Fitted, BeforeFit, ConstrainedKeys, FreeKeys };

    MagnitudePlot(model::Document& document, Selection& selection, QWidget* parent = nullptr);

    QCustomPlot* plot() const { return plot_; }
    QCPGraph* graph(Curve curve) const;
    // Where (time s, |ω| rad/s) is drawn, in the plot's pixels; and back.
    QPointF pixelFor(double time, double magnitude) const;
    std::pair<double, double> valueAt(const QPointF& pixel) const;
    // The axis rectangle, in the plot's pixels.
    QRect plotArea() const;
    // Whether the artist zoomed or panned the view since it was last fitted: then it stays as it is.
    bool viewMovedByHand() const { return viewMovedByHand_; }
    // The window the band shows, and whether it is the sketch's own rather than implied.
    std::optional<std::pair<double, double>> shownWindow() const { return shownWindow_; }
    bool shownWindowIsOwn() const { return shownWindowIsOwn_; }
    // The text shown instead of the plot when no object is selected; visible only then.
    QLabel* placeholder() const { return placeholder_; }

    QAction* drawAction() const { return drawAction_; }
    QAction* panAction() const { return panAction_; }
    QAction* clearMagnitudeAction() const { return clearMagnitudeAction_; }

public slots:
    // Shows the scene's time range and the curves' height.
    void fitView();
    // Empties the selected object's magnitude curve, one undo step.
    void clearMagnitude();

signals:
    // The sampled curves now show the track as it was at the latest request.
    void curvesUpdated();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    struct SampledCurves;
    enum class WindowPart { Start, End, Grip };
    struct WindowDrag {
        WindowPart part = WindowPart::Grip;
        std::pair<double, double> original;
        double pressTime = 0.0;
    };
    struct Stroke {
        std::vector<model::MagnitudePoint> before; // the curve when the pen went down
        std::vector<model::MagnitudePoint> drawn;  // time increasing
    };

    void setUpToolBar();
    void setUpPlot();
    void addCursor();
    void addWindowBand();
    void followDocument();

    // Throws std::invalid_argument for a track TrackMotion refuses.
    static SampledCurves sampleTrack(const model::SharedTrackMotion& shared, double start, double end);
    void showCurves(const SampledCurves& curves);
    void showSketch();
    void showKeys(const SampledCurves& curves);
    void showWindow();
    void moveCursor();
    // The value axis from zero to above the highest curve, unless the artist zoomed or panned.
    void followCurvesHeight();
    void showSelection();
    void setTool(bool drawing);
    void showToolCursor();

    // The mouse on the plot; true when the press is this widget's own rather than QCustomPlot's.
    bool pressed(const QMouseEvent& event);
    bool moved(const QMouseEvent& event);
    bool released(const QMouseEvent& event);
    std::optional<WindowPart> windowPartAt(const QPointF& pixel) const;
    void updateHoverCursor(const QPointF& pixel);
    void dragWindow(const QPointF& pixel);
    void extendStroke(const QPointF& pixel);
    void endGesture();

    model::Document& document_;
    Selection& selection_;
    SelectedTrack selectedTrack_;
    QStackedLayout* stack_;
    QLabel* placeholder_;
    QCustomPlot* plot_;
    QAction* drawAction_ = nullptr;
    QAction* panAction_ = nullptr;
    QAction* fitViewAction_ = nullptr;
    QAction* clearMagnitudeAction_ = nullptr;
    QCPGraph* currentGraph_ = nullptr;
    QCPGraph* sketchedGraph_ = nullptr;
    QCPGraph* fittedGraph_ = nullptr;
    QCPGraph* beforeFitGraph_ = nullptr;
    QCPGraph* constrainedKeysGraph_ = nullptr;
    QCPGraph* freeKeysGraph_ = nullptr;
    QCPItemStraightLine* cursor_ = nullptr;
    QCPItemRect* windowBand_ = nullptr;
    QCPItemRect* windowGrip_ = nullptr;

    std::optional<std::pair<double, double>> shownWindow_;
    bool shownWindowIsOwn_ = false;
    bool fitViewOnNextCurves_ = true;
    bool viewMovedByHand_ = false; // zoomed or panned since the last Fit view

    std::optional<model::Gesture> gesture_; // open while a drag edits the document
    model::ObjectId gestureObject_ = model::kNoObject;
    std::optional<WindowDrag> windowDrag_;
    std::optional<Stroke> stroke_;

    // Replots for changes made on the UI thread (the sketch, the window): one per turn of the event
    // loop, none while the plot is off screen.
    ViewRefresh replot_;
    ViewRefresh cursorReplot_; // the cursor's layer alone, as the current time moves
    SelectedTrackSampler<SampledCurves> sampler_; // last: waits for its work before the members it uses go
};

} // namespace gyre::app
