// A gesture is one undo step, as the artist makes it with the real widgets on the bundled sample (keys
// at 0, 1, ..., 5 s, 30 fps): a drag of a key marker on the timeline is one step, the next drag of the
// same key another, and a drag that comes back to where it began leaves no step and the saved state
// as it was. The document knows a drag is under way while the button is held. Values typed into the
// inspector one after the other are steps of their own, even in the same field.

#include "inspected_window.h"

#include "app/timeline_widget.h"
#include "gui_test_support.h"
#include "model/project_file.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <memory>
#include <vector>

using namespace gyre;
using test::enter;
using test::InspectedWindow;

namespace {

constexpr std::size_t kDraggedKey = 2; // at 2 s, between keys at 1 s and 3 s

// Presses at `from`, moves through `through` with the left button held, and releases at the last.
void drag(QWidget* widget, const QPoint& from, const std::vector<QPoint>& through)
{
    QTest::mousePress(widget, Qt::LeftButton, {}, from);
    for (const QPoint& at : through)
        test::sendMove(widget, at, Qt::LeftButton);
    QTest::mouseRelease(widget, Qt::LeftButton, {}, through.back());
}

} // namespace

class TestUndoGesture : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }

    void init()
    {
        inspected_ = std::make_unique<InspectedWindow>(kDraggedKey);
        inspected_->window().resize(1400, 900);
        QVERIFY(QTest::qWaitForWindowExposed(&inspected_->window()));
        timeline_ = inspected_->window().findChild<app::TimelineWidget*>();
        QVERIFY(timeline_ != nullptr);
        QVERIFY(timeline_->isVisible());
        QCOMPARE(keyTime(), 2.0);
    }

    void cleanup() { inspected_.reset(); }

    void twoDragsOfTheSameKeyAreTwoSteps()
    {
        model::Document& document = inspected_->window().document();
        QUndoStack& stack = document.undoStack();
        const int stepsBefore = stack.count();
        QSignalSpy ended(&document, &model::Document::gestureEnded);

        const QPoint from = marker();
        QTest::mousePress(timeline_, Qt::LeftButton, {}, from);
        for (double seconds : {0.1, 0.3, 0.5}) {
            test::sendMove(timeline_, from + QPoint(pixelsFor(seconds), 0), Qt::LeftButton);
            QVERIFY(document.isGestureOpen());
            QCOMPARE(stack.count(), stepsBefore + 1); // every move merges into the drag's one step
        }
        QTest::mouseRelease(timeline_, Qt::LeftButton, {}, from + QPoint(pixelsFor(0.5), 0));
        QVERIFY(!document.isGestureOpen());
        QCOMPARE(ended.count(), 1);
        QCOMPARE(keyTime(), 2.5);

        const QPoint again = marker();
        drag(timeline_, again, {again - QPoint(pixelsFor(0.1), 0), again - QPoint(pixelsFor(0.2), 0)});
        QCOMPARE(keyTime(), 2.3);
        QCOMPARE(stack.count(), stepsBefore + 2);
        stack.undo();
        QCOMPARE(keyTime(), 2.5);
        stack.undo();
        QCOMPARE(keyTime(), 2.0);
    }

    void aDragBackToWhereItBeganLeavesNoStep()
    {
        model::Document& document = inspected_->window().document();
        QUndoStack& stack = document.undoStack();
        const int stepsBefore = stack.count();
        const bool cleanBefore = stack.isClean();
        const QByteArray before = model::projectBytes(document.scene());

        const QPoint from = marker();
        QTest::mousePress(timeline_, Qt::LeftButton, {}, from);
        test::sendMove(timeline_, from + QPoint(pixelsFor(0.4), 0), Qt::LeftButton);
        QCOMPARE(stack.count(), stepsBefore + 1);
        QVERIFY(!stack.isClean() || !cleanBefore);
        test::sendMove(timeline_, from + QPoint(pixelsFor(0.2), 0), Qt::LeftButton);
        test::sendMove(timeline_, from, Qt::LeftButton);
        QTest::mouseRelease(timeline_, Qt::LeftButton, {}, from);

        QCOMPARE(keyTime(), 2.0);
        QCOMPARE(stack.count(), stepsBefore);
        QCOMPARE(stack.isClean(), cleanBefore);
        QCOMPARE(document.isModified(), !cleanBefore);
        QCOMPARE(model::projectBytes(document.scene()), before);
    }

    void aDragBackToWhereItBeganAfterASaveLeavesTheDocumentSaved()
    {
        model::Document& document = inspected_->window().document();
        QUndoStack& stack = document.undoStack();
        stack.setClean();
        QVERIFY(!document.isModified());
        const int stepsBefore = stack.count();
        const QPoint from = marker();
        drag(timeline_, from, {from + QPoint(pixelsFor(0.3), 0), from + QPoint(pixelsFor(0.6), 0), from});
        QCOMPARE(keyTime(), 2.0);
        QCOMPARE(stack.count(), stepsBefore);
        QVERIFY(stack.isClean());
        QVERIFY(!document.isModified());
    }

    void valuesTypedOneAfterAnotherAreStepsOfTheirOwn()
    {
        QUndoStack& stack = inspected_->window().document().undoStack();
        const int stepsBefore = stack.count();
        enter(inspected_->field("timeEdit"), QStringLiteral("2.25"));
        enter(inspected_->field("timeEdit"), QStringLiteral("2.5")); // the same field again
        enter(inspected_->field("positionXEdit"), QStringLiteral("1.5")); // another field
        QCOMPARE(stack.count(), stepsBefore + 3);
        stack.undo();
        QCOMPARE(inspected_->key(kDraggedKey).pose.position.x(), 4.0);
        QCOMPARE(keyTime(), 2.5);
        stack.undo();
        QCOMPARE(keyTime(), 2.25);
        stack.undo();
        QCOMPARE(keyTime(), 2.0);
    }

private:
    double keyTime() const { return inspected_->key(kDraggedKey).time; }
    QPoint marker() const { return *timeline_->keyMarkerCentre(kDraggedKey); }

    // The width of `seconds` on the ruler, to the nearest pixel.
    int pixelsFor(double seconds) const
    {
        return static_cast<int>(std::lround(timeline_->xForTime(seconds) - timeline_->xForTime(0.0)));
    }

    std::unique_ptr<InspectedWindow> inspected_;
    app::TimelineWidget* timeline_ = nullptr;
};

QTEST_MAIN(TestUndoGesture)
#include "tst_undo_gesture.moc"
