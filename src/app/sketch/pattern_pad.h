#pragma once
// The pattern tool of the sketch-editing paper (its Fig. 3a): a small pad where the artist draws a
// wiggle once, x along the direction strokes and y across them (to their left), and how often it
// repeats along the direction curve. Drawing sets the pattern as it is drawn, one undo step per
// pattern; the Repeat box's edits merge into one step; Clear sets no pattern and repeat 0. All go
// through SetPatternCommand. A pattern drawn while the repeat count is 0 repeats kDefaultRepeat times.
//
// Pad units: the canvas's height is one unit, x runs from its left edge, y from its middle, up.

#include "app/selected_track.h"
#include "app/selection.h"
#include "model/document.h"
#include "model/gesture.h"

#include <Eigen/Core>
#include <QWidget>

#include <optional>
#include <vector>

class QPushButton;
class QSpinBox;

namespace gyre::app {

// The surface the pattern is drawn on. It shows the pattern it is given (scaled to fit when it does
// not), or the one being drawn, with the chord through its ends from which y is measured.
class PatternCanvas : public QWidget {
    Q_OBJECT

public:
    explicit PatternCanvas(QWidget* parent = nullptr);

    void setPattern(std::vector<Eigen::Vector2d> pattern);
    const std::vector<Eigen::Vector2d>& pattern() const { return pattern_; }

    QPointF toWidget(const Eigen::Vector2d& padPoint) const;
    Eigen::Vector2d toPad(const QPointF& widgetPoint) const;

    QSize sizeHint() const override { return {240, 80}; }
    QSize minimumSizeHint() const override { return {120, 48}; }

    // Pointer moves closer than this to the last point drawn add no point.
    static constexpr double kPointSpacingPixels = 2.0;

signals:
    void drawingStarted();
    // The points drawn so far, in pad units, at least two.
    void drawn(const std::vector<Eigen::Vector2d>& points);
    void drawingFinished();

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    // The pad point under a widget point kept inside the canvas.
    Eigen::Vector2d clampedPadPoint(const QPointF& widgetPoint) const;
    // The pattern as drawn: as it is if it fits the canvas, else scaled and moved to fit.
    std::vector<Eigen::Vector2d> shownPattern() const;

    std::vector<Eigen::Vector2d> pattern_;
    std::optional<std::vector<Eigen::Vector2d>> drawing_; // the points of a drag under way
};

class PatternPad : public QWidget {
    Q_OBJECT

public:
    static constexpr int kDefaultRepeat = 8;
    static constexpr int kMaxRepeat = 500;

    PatternPad(model::Document& document, Selection& selection, QWidget* parent = nullptr);

    PatternCanvas* canvas() const { return canvas_; }
    QSpinBox* repeatBox() const { return repeatBox_; }
    QPushButton* clearButton() const { return clearButton_; }

private:
    // Shows the selected object's pattern and repeat count; disabled without an object.
    void showSketch();
    void setPatternDrawn(const std::vector<Eigen::Vector2d>& points);
    void setRepeat(int repeat);
    void clearPattern();

    model::Document& document_;
    Selection& selection_;
    SelectedTrack selectedTrack_;
    PatternCanvas* canvas_;
    QSpinBox* repeatBox_;
    QPushButton* clearButton_;
    std::optional<model::Gesture> gesture_; // while a pattern is drawn
    // The Repeat box's edits, one gesture that ends at once (nothing waits for the artist to leave
    // the box) and that each edit continues: consecutive edits merge into one step.
    model::GestureId repeatEdits_;
};

} // namespace gyre::app
