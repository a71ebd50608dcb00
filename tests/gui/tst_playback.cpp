// Playback moves the current time, a frame at a time or at wall-clock speed, and never edits: the
// undo stack stays empty.

#include "app/playback.h"
#include "model/commands/set_time_range_command.h"
#include "model/document.h"

#include <QSignalSpy>
#include <QTest>

using namespace gyre;

namespace {

// A document whose scene runs from 1 s to 1.5 s at 10 frames a second.
void useShortRange(model::Document& document)
{
    document.undoStack().push(new model::SetTimeRangeCommand(document, {10.0, 1.0, 1.5}));
    document.undoStack().clear();
    document.setCurrentTime(1.0);
}

} // namespace

class TestPlayback : public QObject {
    Q_OBJECT

private slots:
    void stepsMoveOneFrameAndStopAtTheEnds()
    {
        model::Document document;
        useShortRange(document);
        app::Playback playback(document);
        playback.stepForward();
        QCOMPARE(document.scene().currentTime, 1.1);
        playback.stepForward();
        QCOMPARE(document.scene().currentTime, 1.2);
        playback.stepBackward();
        QCOMPARE(document.scene().currentTime, 1.1);
        // From between frames, a step lands on the neighbouring frame.
        document.setCurrentTime(1.25);
        playback.stepForward();
        QCOMPARE(document.scene().currentTime, 1.3);
        document.setCurrentTime(1.25);
        playback.stepBackward();
        QCOMPARE(document.scene().currentTime, 1.2);
        playback.goToEnd();
        playback.stepForward();
        QCOMPARE(document.scene().currentTime, 1.5);
        playback.goToStart();
        playback.stepBackward();
        QCOMPARE(document.scene().currentTime, 1.0);
        QCOMPARE(document.undoStack().count(), 0);
    }

    void playingWithoutLoopStopsAtTheEnd()
    {
        model::Document document;
        useShortRange(document);
        app::Playback playback(document);
        playback.setLoops(false);
        QSignalSpy playing(&playback, &app::Playback::playingChanged);
        playback.play();
        QVERIFY(playback.isPlaying());
        QTRY_VERIFY_WITH_TIMEOUT(!playback.isPlaying(), 5000);
        QCOMPARE(document.scene().currentTime, 1.5);
        QCOMPARE(playing.count(), 2);
        QVERIFY(!document.isModified());
    }

    void playingWithLoopWrapsToTheStart()
    {
        model::Document document;
        useShortRange(document);
        app::Playback playback(document);
        playback.setLoops(true);
        document.setCurrentTime(1.4);
        double latest = document.scene().currentTime;
        bool wrapped = false;
        connect(&document, &model::Document::currentTimeChanged, this, [&](double seconds) {
            QVERIFY(seconds >= 1.0 && seconds < 1.5);
            wrapped = wrapped || seconds < latest;
            latest = seconds;
        });
        playback.play();
        QTRY_VERIFY_WITH_TIMEOUT(wrapped, 5000);
        QVERIFY(playback.isPlaying());
        playback.pause();
        QVERIFY(!playback.isPlaying());
    }
};

QTEST_MAIN(TestPlayback)
#include "tst_playback.moc"
