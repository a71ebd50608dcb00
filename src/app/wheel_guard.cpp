#include "app/wheel_guard.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QEvent>

namespace gyre::app {

namespace {

bool isGuarded(const QObject* object)
{
    return qobject_cast<const QAbstractSpinBox*>(object) != nullptr || qobject_cast<const QComboBox*>(object) != nullptr;
}

} // namespace

void WheelGuard::install(QObject* owner)
{
    QApplication::instance()->installEventFilter(new WheelGuard(owner));
}

bool WheelGuard::eventFilter(QObject* watched, QEvent* event)
{
    switch (event->type()) {
    case QEvent::Polish:
        // Before the box is first shown, and so before the first wheel over it.
        if (isGuarded(watched))
            static_cast<QWidget*>(watched)->setFocusPolicy(Qt::StrongFocus);
        break;
    case QEvent::Wheel:
        if (isGuarded(watched) && !static_cast<QWidget*>(watched)->hasFocus()) {
            // Filtered and not accepted: QApplication offers the event to the parent, as for a
            // widget that ignores the wheel.
            event->ignore();
            return true;
        }
        break;
    default:
        break;
    }
    return false;
}

} // namespace gyre::app
