// The main window driven as the artist drives it: files through the File menu, the title and its
// unsaved-changes mark, asking before unsaved work is lost.

#include "app/main_window.h"
#include "gui_test_support.h"
#include "model/commands/set_keyframe_position_command.h"

#include <QAction>
#include <QMessageBox>
#include <QTemporaryDir>
#include <QTest>

using namespace gyre;

class TestMainWindow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }

    void startsOnTheBundledSampleUntitledAndUnmodified()
    {
        app::MainWindow window;
        window.show();
        window.openBundledSample();
        QCOMPARE(window.document().scene().objects.size(), std::size_t{1});
        QCOMPARE(window.document().scene().objects.front().track.keys.size(), std::size_t{6});
        QVERIFY(window.document().filePath().isEmpty());
        QVERIFY(!window.document().isModified());
        QVERIFY(window.windowTitle().startsWith(QStringLiteral("Untitled")));
        QVERIFY(window.selection().object() != model::kNoObject);
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_main_window.moc"
