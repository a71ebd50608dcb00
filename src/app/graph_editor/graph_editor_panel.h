#pragma once
// The Graph Editor: the selected object's channels over time in one plot, as an animator's
// graph editor shows them. The Euler angles are in the convention the inspector shows (the choosers
// here and there are linked by the main window) and unwrapped, so a spin is a ramp; the quaternion
// components, the angular velocity in the world or the object's frame, |ω| and the position can be
// shown beside them from the channel list. Keys are drawn on their curves, and the time spans near
// the convention's gimbal lock are shaded.
//
// Dragging a key on an Euler channel up or down changes that angle of the key, the other two kept:
// one undo step, the moves of one drag merged (model/gesture.h). Shift+click on a key adds it to the
// selected keys or takes it out; Shift+drag elsewhere draws a box and adds the keys in it. As in
// Blender's graph editor, G moves the selected keys with the pointer, in time (whole frames, never
// crossing or landing on another key) and, on the Euler channel of the key pressed last, in angle;
// S scales their times about the current frame. A click or Enter keeps the change, one undo step;
// Esc or a right click puts the keys back. Home (while the plot has the focus) frames everything
// shown; F frames the selected key between its neighbours. Drag elsewhere to pan, wheel to zoom.
//
// The curves come from the document's shared motion of the track (Document::motion), sampled on a
// job (SelectedTrackSampler): at most every 50 ms while a key is dragged, not at all off screen.

#include "app/graph_editor/channel_list_model.h"
#include "app/selected_track.h"
#include "app/selected_track_sampler.h"
#include "app/selection.h"
#include "model/document.h"
#include "model/gesture.h"
#include "model/motion_channels.h"

#include <Eigen/Geometry>
#include <QWidget>

#include <array>
#include <memory>
#include <optional>
#include <vector>

class QAction;
class QComboBox;
class QCPGraph;
class QCPItemRect;
class QCustomPlot;
class QListView;
class QMouseEvent;

namespace gyre::app {

class GraphEditorPanel : public QWidget {
    Q_OBJECT

public:
    static constexpr int kSampleCount = 2000;
    // A press this near a drawn key, in pixels, takes hold of the key.
    static constexpr double kKeyGrabPixels = 8.0;

    GraphEditorPanel(model::Document& document, Selection& selection, QWidget* parent = nullptr);

    QCustomPlot* plot() const { return plot_; }
    QCPGraph* graph(model::Channel channel) const { return graphs_[static_cast<std::size_t>(channel)]; }
    // The keys drawn on the channel's curve.
    QCPGraph* keyGraph(model::Channel channel) const { return keyGraphs_[static_cast<std::size_t>(channel)]; }
    ChannelListModel& channels() { return channels_; }
    QListView* channelList() const { return channelList_; }
    QComboBox* orderChooser() const { return orderChooser_; }
    QComboBox* frameChooser() const { return frameChooser_; }
    QComboBox* velocityFrameChooser() const { return velocityFrameChooser_; }
    // The shaded spans near gimbal lock, as drawn.
    const std::vector<QCPItemRect*>& gimbalZones() const { return gimbalZones_; }
    QAction* frameAllAction() const { return frameAll_; }
    QAction* frameSelectedAction() const { return frameSelected_; }
    QAction* moveKeysAction() const { return moveKeys_; }
    QAction* scaleKeysAction() const { return scaleKeys_; }
    // The selected keys drawn apart on the channel's curve.
    QCPGraph* selectedKeyGraph(model::Channel channel) const
    {
        return selectedKeyGraphs_[static_cast<std::size_t>(channel)];
    }

    void frameAll();
    void frameSelectedKey();

protected:
    bool event(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

signals:
    // The curves now show the selected track and the choices as they were at the latest request.
    void curvesUpdated();

private:
    // A key held by the mouse on an Euler channel, from press to release.
    struct KeyDrag {
        std::unique_ptr<model::Gesture> gesture;
        model::ObjectId object = model::kNoObject;
        std::size_t key = 0;
        int angle = 0;                         // 0, 1 or 2: the Euler angle dragged
        Eigen::Vector3d pressAngles;           // the key's angles at the press, degrees, as drawn
        Eigen::Quaterniond pressOrientation;   // the key as stored at the press
        double pressValue = 0.0;               // the value under the mouse at the press, degrees
    };
    // G or S in progress: the keys as they were, the selected ones' indices and their Euler angles as
    // drawn (degrees), and where the pointer was when it began.
    struct KeyTransform {
        bool scale = false;
        std::unique_ptr<model::Gesture> gesture;
        model::ObjectId object = model::kNoObject;
        std::vector<model::Keyframe> keys;
        std::vector<std::size_t> selected;
        std::vector<Eigen::Vector3d> angles;
        std::optional<int> angle; // the Euler angle a move changes too
        QPointF start;
    };

    QWidget* makeChoosers();
    void setUpPlot();
    void showCurves(const model::ChannelCurves& curves);
    // Draws the keys only where they are at least a marker apart on average over the shown time: a
    // motion capture's key at every frame makes a solid band of markers none of which can be picked,
    // and costs their drawing at every replot. Zooming in shows them.
    void showKeyMarkers();
    void showGimbalZones(const std::vector<std::pair<double, double>>& zones);
    void showChannel(model::Channel channel, bool shown);
    // The drawn key on a shown Euler channel within kKeyGrabPixels of `position`, nearest first.
    std::optional<std::pair<model::Channel, std::size_t>> keyAt(const QPointF& position) const;
    void pressPlot(QMouseEvent* event);
    void movePlot(QMouseEvent* event);
    void releasePlot();
    void showSelectedKeys();
    void selectKeysIn(const QRect& box);
    void beginTransform(bool scale);
    void updateTransform(const QPointF& pointer);
    // Keeps the transform's change as its undo step, or puts the keys back and leaves none.
    void finishTransform(bool keep);
    void rescaleValues(bool inTimeRange);
    model::ChannelSettings settings() const;

    model::Document& document_;
    Selection& selection_;
    SelectedTrack selectedTrack_;
    ChannelListModel channels_;
    QComboBox* orderChooser_ = nullptr;
    QComboBox* frameChooser_ = nullptr;
    QComboBox* velocityFrameChooser_ = nullptr;
    QListView* channelList_ = nullptr;
    QCustomPlot* plot_ = nullptr;
    QAction* frameAll_ = nullptr;
    QAction* frameSelected_ = nullptr;
    QAction* moveKeys_ = nullptr;
    QAction* scaleKeys_ = nullptr;
    std::array<QCPGraph*, model::kChannelCount> graphs_{};
    std::array<QCPGraph*, model::kChannelCount> keyGraphs_{};
    std::array<QCPGraph*, model::kChannelCount> selectedKeyGraphs_{};
    std::vector<QCPItemRect*> gimbalZones_;
    // The curves shown, and the object whose they are.
    model::ChannelCurves curves_;
    model::ObjectId shownObject_ = model::kNoObject;
    std::vector<double> keyTimes_; // of the drawn keys, increasing
    bool keyMarkersShown_ = false;
    std::optional<KeyDrag> drag_;
    std::optional<KeyTransform> transform_;
    QPointF pointer_;          // where the pointer was last over the plot
    std::optional<int> lastAngle_; // the Euler angle of the key pressed last
    SelectedTrackSampler<model::ChannelCurves> sampler_; // last: waits for its work before the members it uses go
};

} // namespace gyre::app
