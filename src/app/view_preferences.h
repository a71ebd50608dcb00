#pragma once
// The viewport's preferences that outlive the window, kept in QSettings: View ▸ Show Trail, the trail's
// copies and spacing (View ▸ Trail, sampled_trail.h), and View ▸ Y Up (the Z-up scene shown Y-up,
// OrbitCamera::setUpAxis). It adds the Trail submenu and Y Up to the View menu, reads the settings into
// the actions and the viewport, and writes each change back.

#include "app/viewport/sampled_trail.h"

#include <QObject>

#include <array>

class QAction;
class QActionGroup;
class QMenu;

namespace gyre::app {

class Viewport;

class ViewPreferences : public QObject {
    Q_OBJECT

public:
    // The copies View ▸ Trail offers; each the object name actionTrailCopies-N.
    static constexpr std::array kCopyChoices{8, 16, 32, 64, 128, TrailSpacing::kMaxCopies};
    // The spacings it offers, in frames, 0 for over the whole range; each actionTrailEvery-N.
    static constexpr std::array kFrameChoices{0, 1, 2, 5, 10};

    // `showTrail` is View ▸ Show Trail; the Trail submenu goes after it, Y Up after `orthographic`.
    // `viewport` is null when the display has no OpenGL 3.3: the actions are then disabled.
    ViewPreferences(QMenu& viewMenu, QAction& showTrail, QAction& orthographic, Viewport* viewport, QObject* parent);

private:
    // The trail's spacing as the actions have it, to the viewport and QSettings.
    void applyTrailSpacing();

    Viewport* viewport_;
    QActionGroup* copies_;
    QActionGroup* spacing_;
};

} // namespace gyre::app
