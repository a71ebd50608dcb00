#pragma once
// The sphere view of the sketch-editing paper (its Fig. 1, right; Figs. 2b and 3): the direction of
// the selected object's angular velocity, ω(t)/|ω(t)|, as a curve on the unit sphere over the scene's
// time range, and the direction strokes the artist draws on it.
//
// Shown: the sphere, shaded, with latitude and longitude lines and the x, y and z axes, its front
// drawn strong and its back faint through it. The motion's direction curve, ticked every second
// (labelled sparsely) and every quarter second, with the current time as a dot; where a fit is
// applied, the curve inside the fit's span is what the fit achieved, in red, and the motion before
// the fit is drawn in grey beside it. The strokes, thin blue as drawn, and thick blue as the fit will
// read them: timed, with the pattern applied (model::timedStrokes).
//
// Tools (the QActions, each with a shortcut):
// - Draw: left-drag on the sphere draws a stroke on its front hemisphere (a pointer off the disc draws
//   on the rim). The stroke is in the document while it is drawn, so the fit can follow the pen: the
//   first move adds it (AddStrokeCommand), every later move replaces its points (EditStrokeCommand),
//   one undo step per stroke. A point closer than kStrokeStepRadians to the previous one is dropped.
//   The stroke is timed by strokeTimes (direction_curves.h) against the motion's curve as shown: its
//   ends take the times of the nearest samples of the motion, the points between are spread by arc
//   length, and a stroke whose end times are less than a frame apart or run backwards stays untimed.
// - Erase: left-drag takes out the strokes' points within kEraseRadiusPixels of the pointer on the
//   front of the sphere. A stroke cut in the middle splits: its first part stays (EditStrokeCommand)
//   and the rest becomes new strokes after the others (AddStrokeCommand); a stroke left with no run of
//   two points goes (EraseStrokeCommand). Remaining points keep their times. One undo step per drag.
// - Pattern: the pattern pad (pattern_pad.h) draws the pattern; on the sphere the left button turns it.
// Right- or middle-drag turns the sphere (an arcball) with every tool; this changes no document state.
// Escape during a stroke or an erasing drag undoes what it did so far.
//
// The curves follow the selection, the track and the scene's range, recomputed at most every
// SelectedTrackSampler::kIntervalMilliseconds by a job of the view's own (jobs/job.h). They are not
// cheap: the bundled spinning top's (14 s at kSamplesPerSecond, with its fit and its patterned sketch) took 0.22 s in a Debug
// build, the L-cycle's screw motion 0.04 s, and a screw track's motion grows with 2^levels
// (smoothness_panel.h). A stroke being drawn asks again at every move. A hidden view (its dock closed
// or tabbed away) asks for nothing: it samples once when it is shown again.
//
// All but the current-time dot changes only with the curves, the strokes, the turn of the sphere, the
// range and the size, so it is drawn once, with the raster engine's antialiasing, into two images: what
// lies behind the disc, and the disc with what lies in front. Each frame paints the two images with the
// dot, itself an image, between and over them. Drawing it all every frame, with 4× multisampling in
// OpenGL, took 190 to 220 ms a frame on llvmpipe for a bone of a 31-joint capture, the cached images
// under 4 ms (tst_view_drawing, README.md). The view is a raster widget: painting three images needs no
// OpenGL, and an OpenGL widget would have Qt compose the whole window through OpenGL at every frame
// (offscreen_gl_widget.h).

#include "app/selected_track.h"
#include "app/selected_track_sampler.h"
#include "app/selection.h"
#include "app/sketch/direction_curves.h"
#include "app/sketch/sphere_projection.h"
#include "model/document.h"
#include "model/gesture.h"

#include <Eigen/Core>
#include <QImage>
#include <QPointF>
#include <QTimer>
#include <QWidget>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

class QAction;
class QActionGroup;
class QPainter;
class QPen;

namespace gyre::app {

class SphereView final : public QWidget {
    Q_OBJECT

public:
    enum class Tool { Draw, Erase, Pattern };

    static constexpr double kStrokeStepRadians = 0.008; // about half a degree
    static constexpr double kEraseRadiusPixels = 10.0;

    SphereView(model::Document& document, Selection& selection, QWidget* parent = nullptr);
    ~SphereView() override;

    Tool tool() const { return tool_; }
    void setTool(Tool tool);
    // Checkable and exclusive; shortcuts D, E and P while the view or its panel has the focus.
    QAction* drawAction() const { return drawAction_; }
    QAction* eraseAction() const { return eraseAction_; }
    QAction* patternAction() const { return patternAction_; }
    // Turns the sphere back to its first view; shortcut R.
    QAction* resetViewAction() const { return resetViewAction_; }

    // Where a point of the sphere is drawn, in widget pixels; facesViewer says whether it is in front.
    QPointF projectToWidget(const Eigen::Vector3d& direction) const;
    bool facesViewer(const Eigen::Vector3d& direction) const;
    // The sphere's radius on screen, pixels.
    double sphereRadius() const;
    // The point of the sphere's front under a widget point, as the pen draws it.
    Eigen::Vector3d sphereAt(const QPointF& widgetPoint) const;
    // The curves drawn, as the newest sampling gave them.
    const SphereCurves& curves() const { return curves_; }
    // The line of text the view shows when there is nothing to sketch on, else empty.
    QString message() const;

    // How many times the images behind and in front of the current-time dot have been drawn since the
    // view was made: a change of the current time alone leaves them as they were.
    int layerBuilds() const { return layerBuilds_; }

    QSize sizeHint() const override { return {460, 460}; }
    QSize minimumSizeHint() const override { return {200, 200}; }

signals:
    void toolChanged(gyre::app::SphereView::Tool tool);
    // The curves now show the selection and track as they were at the latest request.
    void curvesUpdated();

protected:
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    enum class DragKind { None, Turn, Draw, Erase };
    enum class Side { Back, Front };

    void createActions();
    void showCurves(SphereCurves curves);
    void forgetCurves();

    // Gestures.
    void extendStroke(const QPointF& position);
    void eraseAt(const QPointF& position);
    void endDrag();
    void cancelDrag();

    // Drawing, back side first, then the shaded disc, then the front.
    void invalidateLayers();
    void rebuildLayers();
    // An image of the widget's size at its device pixel ratio, transparent.
    QImage layerImage() const;
    void drawSphereLayers(QPainter& painter, Side side) const;
    void drawDisc(QPainter& painter) const;
    void drawGrid(QPainter& painter, Side side) const;
    void drawAxes(QPainter& painter, Side side) const;
    void drawMotion(QPainter& painter, Side side) const;
    void drawTimeTicks(QPainter& painter, Side side) const;
    void drawStrokes(QPainter& painter, Side side) const;
    void drawCurrentTime(QPainter& painter, Side side) const;
    void drawLegend(QPainter& painter) const;
    void drawMessage(QPainter& painter, const QString& text) const;
    // The curve through `points` along the sphere: the parts on `side`, with `pen` (faded at the back).
    void drawCurve(QPainter& painter, const std::vector<Eigen::Vector3d>& points, const QPen& pen, Side side) const;
    void drawRuns(QPainter& painter, const std::vector<DirectionRun>& runs, const QPen& pen, Side side,
                  double from, double to) const;

    model::Document& document_;
    Selection& selection_;
    SelectedTrack selectedTrack_;
    SphereProjection projection_;
    Tool tool_ = Tool::Draw;
    QActionGroup* toolGroup_;
    QAction* drawAction_;
    QAction* eraseAction_;
    QAction* patternAction_;
    QAction* resetViewAction_;

    SphereCurves curves_;
    bool curvesShown_ = false; // curves_ answer a request for the selected object

    QImage backLayer_;  // the background and all behind the disc
    QImage frontLayer_; // the disc, all in front of it, the legend and the message
    std::array<QImage, 2> currentTimeDots_; // indexed by Side, drawn at the layers' pixel ratio
    bool layersStale_ = true;
    int layerBuilds_ = 0;

    DragKind drag_ = DragKind::None;
    model::ObjectId dragObject_ = model::kNoObject;
    std::vector<Eigen::Vector3d> strokePoints_;
    std::optional<std::size_t> strokeIndex_; // of the stroke being drawn, once it is in the document
    std::optional<model::Gesture> gesture_;

    SelectedTrackSampler<SphereCurves> sampler_; // last: waits for its work before the members it uses go
};

} // namespace gyre::app
