#pragma once
// What the GUI tests share: answering the modal dialogs the real code paths open, and settings kept
// apart from the user's.

#include <QPointF>
#include <QString>
#include <QWidget>

#include <functional>
#include <vector>

namespace gyre::test {

// Keeps QSettings and QStandardPaths in a test location and starts with empty settings; call at the
// start of initTestCase.
void useTestSettings();

// Calls `answer` on the next modal dialog as soon as it is shown, from within its event loop: the way
// a test fills in and closes a dialog that the code under test opens with exec().
void whenDialogOpens(std::function<void(QWidget* dialog)> answer);

// Answers the next file dialog with `path`, as if the user had typed it and pressed Open or Save.
void answerFileDialog(const QString& path);

// Presses the button with this role (QMessageBox::StandardButton) on the next message box, and keeps
// its text in `text` if given.
void answerMessageBox(int standardButton, QString* text = nullptr);

// Sends a mouse move to `widget` with `buttons` held: QTest::mouseMove does not say which buttons are
// held, and a drag needs them.
void sendMove(QWidget* widget, const QPointF& position, Qt::MouseButtons buttons);

// Presses at `path[0]`, moves through the rest with the left button held, and releases at the end.
void dragAlong(QWidget* widget, const std::vector<QPointF>& path);

// `steps` + 1 points from `from` to `to`, evenly spaced.
std::vector<QPointF> straightPath(const QPointF& from, const QPointF& to, int steps);

} // namespace gyre::test
