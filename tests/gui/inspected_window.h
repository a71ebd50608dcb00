#pragma once
// The main window on the bundled sample, with one keyframe selected and paused, active so that the
// keyboard focus moves as it does for the artist; and the typing the panel tests share.

#include "app/main_window.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QLineEdit>
#include <QString>

#include <cstddef>

namespace gyre::test {

class InspectedWindow {
public:
    // Selects keyframe `key` of the sample's object; the window is shown and active.
    explicit InspectedWindow(std::size_t key);

    app::MainWindow& window() { return window_; }
    model::ObjectId object() const { return object_; }
    const model::Keyframe& key(std::size_t index);
    int undoSteps() { return window_.document().undoStack().count(); }

    // The child of the main window with this object name; fails the test if it is missing.
    template <class Widget>
    Widget* child(const char* name) const
    {
        auto* widget = window_.findChild<Widget*>(QString::fromLatin1(name));
        if (widget == nullptr)
            qFatal("The main window has no %s", name);
        return widget;
    }
    QLineEdit* field(const char* name) const { return child<QLineEdit>(name); }

private:
    app::MainWindow window_;
    model::ObjectId object_ = model::kNoObject;
};

// Focuses `field`, selects its text and types `text` over it, as the artist does; no Enter.
void typeOver(QLineEdit* field, const QString& text);
// Types `text` over `field` and presses Enter.
void enter(QLineEdit* field, const QString& text);
// The number a field shows.
double shownNumber(const QLineEdit* field);
// Clicks the check box's or radio button's indicator, which takes clicks where the middle of a wide
// button, past its text, does not.
void clickIndicator(QAbstractButton* button);
// Chooses the entry at `index` from the combo box's popup with the mouse.
void choose(QComboBox* combo, int index);

} // namespace gyre::test
