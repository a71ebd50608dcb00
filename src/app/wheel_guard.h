#pragma once
// Scrolling a panel never changes a setting: a spin box or combo box takes the mouse wheel only once
// it has the keyboard focus (clicked or tabbed into). Without focus the wheel goes on to the widget
// behind, a scroll area scrolling the panel; and the wheel no longer gives such a box the focus
// (Qt::StrongFocus in place of Qt::WheelFocus), which would let it take the next step of the scroll.
//
// One filter on the application covers every box, those a panel builds later included.

#include <QObject>

namespace gyre::app {

class WheelGuard : public QObject {
    Q_OBJECT

public:
    using QObject::QObject;

    // Guards every spin box and combo box of the application while `owner` lives.
    static void install(QObject* owner);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
};

} // namespace gyre::app
