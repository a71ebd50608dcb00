#pragma once
// What the GUI tests share: the main window set up for a test, answering the modal dialogs the real
// code paths open, and settings kept apart from the user's.

#include "app/main_window.h"
#include "model/commands/object_fields.h"
#include "model/document.h"
#include "model/scene.h"

#include <QPointF>
#include <QString>
#include <QWidget>

#include <QByteArray>

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace gyre::test {

// How a test waits for the main window it shows: until it is on screen, or until it is also active, so
// that shortcuts and the keyboard focus work as they do for the artist.
enum class WindowWait { Exposed, Active };

// The main window at 1400 × 900, shown, with `open` called on it to load what the test works on (a
// sample, a project, imported objects), playback paused after that, and waited for as `wait` says.
// Ends the test program if the window never shows.
std::unique_ptr<app::MainWindow> showMainWindow(WindowWait wait, const std::function<void(app::MainWindow&)>& open);

// Imports `objects` (batch ids 1..n, as ImportObjectsCommand takes them) into `document` and sets the
// scene's time range, as the start of a test: the undo stack is empty after. Returns the objects' ids.
std::vector<model::ObjectId> importAtStart(model::Document& document, std::vector<model::SceneObject> objects,
                                           const model::TimeRange& range);

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

// CPU time of the calling thread, ms: what the UI thread spends itself, not the job threads or
// llvmpipe's rasterising threads.
double threadMilliseconds();

// Sends a mouse move to `widget` with `buttons` held: QTest::mouseMove does not say which buttons are
// held, and a drag needs them.
void sendMove(QWidget* widget, const QPointF& position, Qt::MouseButtons buttons);

// Presses at `path[0]`, moves through the rest with the left button held, and releases at the end.
void dragAlong(QWidget* widget, const std::vector<QPointF>& path);

// `steps` + 1 points from `from` to `to`, evenly spaced.
std::vector<QPointF> straightPath(const QPointF& from, const QPointF& to, int steps);

// A joint of a BVH skeleton written by bvhFile: its depth in the hierarchy (0 for the root) and its
// offset from its parent, in the file's units.
struct BvhJoint {
    const char* name;
    int depth;
    double x, y, z;
};

// A motion capture as a BVH file (Y-up, as BVH files are): `joints` depth first, their offsets times
// `scale`, an end site of one `scale` up on `endSiteJoint` if given; `frames` frames at 30 a second,
// the root at rootPosition(frame) and each joint turned by angle(frame, joint, axis) degrees about
// z, x and y in turn.
QByteArray bvhFile(std::span<const BvhJoint> joints, double scale, int frames,
                   const std::function<Eigen::Vector3d(int frame)>& rootPosition,
                   const std::function<double(int frame, std::size_t joint, int axis)>& angle,
                   const char* endSiteJoint = nullptr);

} // namespace gyre::test
