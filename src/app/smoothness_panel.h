#pragma once
// ScrewBender's smoothness plots (Fig. 10) for the selected object: the position, velocity and
// acceleration of a point of the object, chosen in its local coordinates, over the scene's time
// range, in three stacked plots that share the time axis. Each plot shows the x, y and z components
// and the magnitude; a kink in the velocity or a jump in the acceleration shows where the motion is
// only C⁰ or C¹. A vertical line marks the current time. Drag to pan, wheel to zoom.
//
// The curves follow the selection and the track's keys and settings, asked for at most every
// SelectedTrackSampler::kIntervalMilliseconds while they change (a dragged key changes them at every
// mouse move), and not at all while the panel is off screen, as it is when the window opens, tabbed
// behind the inspector: replotting it there took 37% of the UI thread's time in a drag (issue 18).
// They are sampled by a job of the panel's own: 2000 samples of the bundled sample's screw
// motion took 20–40 ms in a Debug build, and building a TrackMotion grows with 2^levels (0.2 s at 8
// subdivision levels, seconds at 12 and more), far beyond what the UI thread can spare.

#include "model/point_trajectory.h"
#include "app/selection.h"
#include "app/selected_track.h"
#include "app/selected_track_sampler.h"
#include "app/view_refresh.h"
#include "model/document.h"

#include <Eigen/Core>
#include <QTimer>
#include <QWidget>

#include <array>
#include <cstdint>
#include <utility>

class QCPAxisRect;
class QCPGraph;
class QCPItemStraightLine;
class QCustomPlot;
class QDoubleSpinBox;

namespace gyre::app {

class SmoothnessPanel : public QWidget {
    Q_OBJECT

public:
    enum class Quantity { Position, Velocity, Acceleration };
    enum class Component { X, Y, Z, Magnitude };
    // Samples over the scene's range: smooth curves at any zoom a dock allows.
    static constexpr int kSampleCount = 2000;

    SmoothnessPanel(model::Document& document, Selection& selection, QWidget* parent = nullptr);

    // The point whose motion is plotted, in the object's local frame, as its spin boxes give it.
    Eigen::Vector3d point() const;

    QCustomPlot* plot() const { return plot_; }
    // Whether curves asked for are still on their way (SelectedTrackSampler::isSampling).
    bool isSampling() const { return sampler_.isSampling(); }
    QCPGraph* graph(Quantity quantity, Component component) const;

signals:
    // The curves now show the selection, keys and point as they were at the latest request.
    void curvesUpdated();

private:
    static constexpr int kQuantityCount = 3;
    static constexpr int kComponentCount = 4;

    void setUpPlot();
    void showTrajectory(const model::PointTrajectory& trajectory);
    void showTimeRange();
    void moveCursor();

    model::Document& document_;
    SelectedTrack selectedTrack_;
    // The cursor's layer, redrawn once per turn of the event loop at most, and not while hidden.
    ViewRefresh cursorReplot_;
    std::array<QDoubleSpinBox*, 3> pointBoxes_{};
    QCustomPlot* plot_;
    std::array<QCPAxisRect*, kQuantityCount> axisRects_{};
    std::array<std::array<QCPGraph*, kComponentCount>, kQuantityCount> graphs_{};
    std::array<QCPItemStraightLine*, kQuantityCount> cursors_{};
    // The scene's range the time axis was last set to, start and end in seconds.
    std::pair<double, double> shownSceneRange_{0.0, 0.0};
    // The curves of the selection, keys and point as they are at the newest request.
    SelectedTrackSampler<model::PointTrajectory> sampler_; // last: waits for its work before the members it uses go
};

} // namespace gyre::app
