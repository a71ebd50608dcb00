#include "inspected_window.h"

#include "core/number_text.h"

#include <QAbstractItemView>
#include <QApplication>
#include <QStyle>
#include <QTest>

namespace gyre::test {

InspectedWindow::InspectedWindow(std::size_t key)
{
    window_.show();
    window_.openBundledSample();
    window_.playback().pause();
    object_ = window_.selection().object();
    window_.selection().selectKey(object_, key);
    // Xvfb has no window manager to activate the window; asking for it is enough.
    window_.activateWindow();
    if (!QTest::qWaitForWindowActive(&window_))
        qFatal("The main window did not become active");
}

const model::Keyframe& InspectedWindow::key(std::size_t index)
{
    return window_.document().object(object_)->track.keys.at(index);
}

void typeOver(QLineEdit* field, const QString& text)
{
    field->setFocus(Qt::TabFocusReason);
    QTest::keyClick(field, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(field, text);
}

void enter(QLineEdit* field, const QString& text)
{
    typeOver(field, text);
    QTest::keyClick(field, Qt::Key_Return);
}

double shownNumber(const QLineEdit* field)
{
    return parseFiniteNumber(field->text().toStdString());
}

void clickIndicator(QAbstractButton* button)
{
    const int indicatorWidth = button->style()->pixelMetric(QStyle::PM_IndicatorWidth, nullptr, button);
    QTest::mouseClick(button, Qt::LeftButton, {}, QPoint(indicatorWidth / 2, button->height() / 2));
}

void choose(QComboBox* combo, int index)
{
    combo->showPopup();
    QAbstractItemView* view = combo->view();
    if (!QTest::qWaitForWindowExposed(view->window()))
        qFatal("The combo box's popup did not open");
    const QRect item = view->visualRect(view->model()->index(index, 0));
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, item.center());
    // Until the popup has gone it takes the mouse clicks meant for other widgets.
    if (!QTest::qWaitFor([view] { return !view->window()->isVisible(); }))
        qFatal("The combo box's popup did not close");
}

} // namespace gyre::test
