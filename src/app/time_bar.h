#pragma once
// The bar above the timeline: the current time in seconds and frames, the scene's frame rate and time
// range, which it edits through SetTimeRangeCommand, and the scene's gravity and up axis (what a ballistic
// track falls with), which it edits through SetGravityCommand: one undo step per edited value.

#include "model/document.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace gyre::app {

class TimeBar : public QWidget {
    Q_OBJECT

public:
    explicit TimeBar(model::Document& document, QWidget* parent = nullptr);

private:
    void showCurrentTime();
    void showTimeRange();
    void showGravity();
    void applyGravity();
    // Sets the range to the scene's with the value of the edited spin box put in by `change`, or, for
    // a range the document refuses (an end not after the start), shows the scene's range again.
    template <class Change>
    void applyTimeRange(Change change);

    model::Document& document_;
    QLabel* currentTime_;
    QLabel* currentFrame_;
    QDoubleSpinBox* fps_;
    QDoubleSpinBox* startTime_;
    QDoubleSpinBox* endTime_;
    QDoubleSpinBox* gravity_;
    QComboBox* up_;
};

} // namespace gyre::app
