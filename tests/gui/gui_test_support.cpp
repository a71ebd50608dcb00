#include "gui_test_support.h"

#include "model/commands/import_objects_command.h"
#include "model/commands/set_time_range_command.h"

#include <QAbstractButton>
#include <QApplication>
#include <QFileDialog>
#include <QMessageBox>
#include <QMouseEvent>
#include <QSettings>
#include <QStandardPaths>
#include <QStringList>
#include <QTest>
#include <QTimer>

#include <ctime>
#include <utility>

namespace gyre::test {

namespace {

// Looks for the modal dialog every few milliseconds, for at most five seconds.
void pollForDialog(std::function<void(QWidget*)> answer, int attemptsLeft)
{
    QWidget* dialog = QApplication::activeModalWidget();
    if (dialog != nullptr && dialog->isVisible()) {
        answer(dialog);
        return;
    }
    if (attemptsLeft == 0)
        qFatal("No modal dialog opened");
    QTimer::singleShot(10, [answer = std::move(answer), attemptsLeft] { pollForDialog(answer, attemptsLeft - 1); });
}

} // namespace

std::unique_ptr<app::MainWindow> showMainWindow(WindowWait wait, const std::function<void(app::MainWindow&)>& open)
{
    auto window = std::make_unique<app::MainWindow>();
    window->resize(1400, 900);
    window->show();
    open(*window);
    window->playback().pause(); // a sample opens playing
    // Xvfb has no window manager to activate the window; asking for it is enough.
    if (wait == WindowWait::Active)
        window->activateWindow();
    const bool shown = wait == WindowWait::Active ? QTest::qWaitForWindowActive(window.get())
                                                  : QTest::qWaitForWindowExposed(window.get());
    if (!shown)
        qFatal("The main window was not shown");
    return window;
}

std::vector<model::ObjectId> importAtStart(model::Document& document, std::vector<model::SceneObject> objects,
                                           const model::TimeRange& range)
{
    auto* import = new model::ImportObjectsCommand(document, std::move(objects));
    const std::vector<model::ObjectId> ids = import->ids();
    document.push(import);
    document.push(new model::SetTimeRangeCommand(document, range));
    document.undoStack().clear();
    return ids;
}

void useTestSettings()
{
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
}

void whenDialogOpens(std::function<void(QWidget*)> answer)
{
    QTimer::singleShot(0, [answer = std::move(answer)] { pollForDialog(answer, 500); });
}

void answerFileDialog(const QString& path)
{
    whenDialogOpens([path](QWidget* widget) {
        auto* dialog = qobject_cast<QFileDialog*>(widget);
        if (dialog == nullptr)
            qFatal("Expected a file dialog, got %s", widget->metaObject()->className());
        dialog->selectFile(path);
        QMetaObject::invokeMethod(dialog, "accept"); // as pressing Open or Save does
    });
}

void answerMessageBox(int standardButton, QString* text)
{
    whenDialogOpens([standardButton, text](QWidget* widget) {
        auto* box = qobject_cast<QMessageBox*>(widget);
        if (box == nullptr)
            qFatal("Expected a message box, got %s", widget->metaObject()->className());
        if (text != nullptr)
            *text = box->text() + QLatin1Char('\n') + box->informativeText();
        QAbstractButton* button = box->button(static_cast<QMessageBox::StandardButton>(standardButton));
        if (button == nullptr)
            qFatal("The message box has no such button");
        button->click();
    });
}

double threadMilliseconds()
{
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return double(now.tv_sec) * 1e3 + double(now.tv_nsec) / 1e6;
}

void sendMove(QWidget* widget, const QPointF& position, Qt::MouseButtons buttons)
{
    QMouseEvent move(QEvent::MouseMove, position, widget->mapToGlobal(position), Qt::NoButton, buttons, Qt::NoModifier);
    QApplication::sendEvent(widget, &move);
}

void dragAlong(QWidget* widget, const std::vector<QPointF>& path)
{
    QTest::mousePress(widget, Qt::LeftButton, Qt::NoModifier, path.front().toPoint());
    for (std::size_t i = 1; i < path.size(); ++i)
        sendMove(widget, path[i], Qt::LeftButton);
    QTest::mouseRelease(widget, Qt::LeftButton, Qt::NoModifier, path.back().toPoint());
}

std::vector<QPointF> straightPath(const QPointF& from, const QPointF& to, int steps)
{
    std::vector<QPointF> path;
    for (int i = 0; i <= steps; ++i)
        path.push_back(from + (to - from) * (double(i) / steps));
    return path;
}

QByteArray bvhFile(std::span<const BvhJoint> joints, double scale, int frames,
                   const std::function<Eigen::Vector3d(int frame)>& rootPosition,
                   const std::function<double(int frame, std::size_t joint, int axis)>& angle, const char* endSiteJoint)
{
    QString text = QStringLiteral("HIERARCHY\n");
    int depth = -1;
    for (const BvhJoint& joint : joints) {
        for (; depth >= joint.depth; --depth)
            text += QStringLiteral("}\n");
        depth = joint.depth;
        text += QStringLiteral("%1 %2\n{\nOFFSET %3 %4 %5\n")
                    .arg(QLatin1String(depth == 0 ? "ROOT" : "JOINT"), QLatin1String(joint.name))
                    .arg(scale * joint.x).arg(scale * joint.y).arg(scale * joint.z);
        text += depth == 0 ? QStringLiteral("CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n")
                           : QStringLiteral("CHANNELS 3 Zrotation Xrotation Yrotation\n");
        if (endSiteJoint != nullptr && QLatin1String(joint.name) == QLatin1String(endSiteJoint))
            text += QStringLiteral("End Site\n{\nOFFSET 0 %1 0\n}\n").arg(scale);
    }
    for (; depth >= 0; --depth)
        text += QStringLiteral("}\n");
    text += QStringLiteral("MOTION\nFrames: %1\nFrame Time: %2\n").arg(frames).arg(1.0 / 30.0, 0, 'g', 17);
    for (int frame = 0; frame < frames; ++frame) {
        const Eigen::Vector3d root = rootPosition(frame);
        QStringList values{QString::number(root.x()), QString::number(root.y()), QString::number(root.z())};
        for (std::size_t joint = 0; joint < joints.size(); ++joint)
            for (int axis = 0; axis < 3; ++axis)
                values << QString::number(angle(frame, joint, axis));
        text += values.join(QLatin1Char(' ')) + QLatin1Char('\n');
    }
    return text.toUtf8();
}

} // namespace gyre::test
