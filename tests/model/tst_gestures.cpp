// Gestures in the model (document.h): the commands of one gesture are one undo step, merging where
// they edit the same field; two gestures are two steps even where their edits would merge; a command
// pushed alone never merges; a gesture that ends where it began leaves no step. "Where it began" is
// the serialised project, byte for byte.

#include "model/commands/add_stroke_command.h"
#include "model/commands/edit_stroke_command.h"
#include "model/commands/erase_stroke_command.h"
#include "model/commands/import_objects_command.h"
#include "model/commands/set_fit_parameter_command.h"
#include "model/commands/set_fit_window_command.h"
#include "model/commands/set_keyframe_orientation_command.h"
#include "model/commands/set_keyframe_position_command.h"
#include "model/commands/set_keyframe_time_command.h"
#include "model/commands/set_magnitude_curve_command.h"
#include "model/commands/toggle_keyframe_constraint_command.h"
#include "model/gesture.h"
#include "model/project_file.h"

#include <QSignalSpy>
#include <QTest>

#include <optional>
#include <utility>

using namespace gyre;
using namespace gyre::model;

namespace {

// A document with one object, keys at 0, 1 and 2 s and two strokes, imported and saved: its undo
// stack holds the import, and it is clean.
struct Fixture {
    Fixture()
    {
        SceneObject object;
        object.id = 1;
        object.name = QStringLiteral("top");
        for (double time : {0.0, 1.0, 2.0})
            object.track.keys.push_back({time, {Eigen::Quaterniond::Identity(), {time, 0, 0}}, true});
        object.track.sketch.directionStrokes = {{{Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()}, {}},
                                                {{Eigen::Vector3d::UnitZ()}, {}}};
        auto* command = new ImportObjectsCommand(document, {object});
        id = command->ids().front();
        document.push(command);
        document.undoStack().setClean();
    }

    double keyTime(std::size_t key) const { return document.object(id)->track.keys[key].time; }
    QByteArray json() const { return projectBytes(document.scene()); }
    QUndoStack& stack() { return document.undoStack(); }

    Document document;
    ObjectId id = kNoObject;
};

Eigen::Quaterniond aboutZ(double angle) { return Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ())); }

} // namespace

class TstGestures : public QObject {
    Q_OBJECT

private slots:
    void editsWithinAGestureMerge()
    {
        Fixture f;
        {
            Gesture drag(f.document);
            for (double time : {1.1, 1.2, 1.3, 1.4})
                drag.push(new SetKeyframeTimeCommand(f.document, f.id, 1, time));
            QCOMPARE(f.stack().count(), 2);
            QVERIFY(drag.hasStep());
        }
        QCOMPARE(f.keyTime(1), 1.4);
        QCOMPARE(f.stack().undoText(), QStringLiteral("Move Keyframe"));
        f.stack().undo();
        QCOMPARE(f.keyTime(1), 1.0);
        QVERIFY(f.stack().isClean());
        f.stack().redo();
        QCOMPARE(f.keyTime(1), 1.4);
    }

    void twoGesturesOfTheSameFieldAreTwoSteps()
    {
        Fixture f;
        for (double end : {1.3, 1.6}) {
            Gesture drag(f.document);
            drag.push(new SetKeyframeTimeCommand(f.document, f.id, 1, end - 0.1));
            drag.push(new SetKeyframeTimeCommand(f.document, f.id, 1, end));
        }
        QCOMPARE(f.stack().count(), 3);
        f.stack().undo();
        QCOMPARE(f.keyTime(1), 1.3);
        f.stack().undo();
        QCOMPARE(f.keyTime(1), 1.0);
    }

    void dragsMergeIntoOneStep()
    {
        Fixture f;
        Document& document = f.document;
        const ObjectId id = f.id;
        QUndoStack& stack = f.stack();
        {
            Gesture drag(document);
            for (double time : {1.1, 1.2, 1.3})
                drag.push(new SetKeyframeTimeCommand(document, id, 1, time));
        }
        QCOMPARE(stack.count(), 2);
        QCOMPARE(f.keyTime(1), 1.3);
        stack.undo();
        QCOMPARE(f.keyTime(1), 1.0);
        stack.redo();
        QCOMPARE(f.keyTime(1), 1.3);

        const Eigen::Quaterniond before = document.object(id)->track.keys[0].pose.orientation;
        {
            Gesture turn(document);
            for (double angle : {0.1, 0.2, 0.3})
                turn.push(new SetKeyframeOrientationCommand(
                    document, id, 0, Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX()))));
        }
        QCOMPARE(stack.count(), 3);
        stack.undo();
        QCOMPARE(document.object(id)->track.keys[0].pose.orientation.coeffs(), before.coeffs());
        stack.redo();

        // A drag saved halfway goes on in a new step: the saved state stays reachable.
        Gesture drag(document);
        drag.push(new SetKeyframePositionCommand(document, id, 0, {1, 0, 0}));
        stack.setClean();
        drag.push(new SetKeyframePositionCommand(document, id, 0, {2, 0, 0}));
        QCOMPARE(stack.count(), 5);
        stack.undo();
        QVERIFY(stack.isClean());
    }

    void differentEditsDoNotMerge()
    {
        Fixture f;
        Document& document = f.document;
        const ObjectId id = f.id;
        QUndoStack& stack = f.stack();
        const QByteArray before = f.json();
        const auto pushEdits = [&](GestureId gesture) {
            document.push(new SetKeyframeTimeCommand(document, id, 1, 1.5), gesture);
            document.push(new SetKeyframeTimeCommand(document, id, 2, 2.5), gesture); // another key
            document.push(new SetKeyframePositionCommand(document, id, 2, {1, 2, 3}), gesture); // another field
            document.push(new SetFitParameterCommand(document, id, FitParameter::Alpha, 0.5), gesture);
            document.push(new SetFitParameterCommand(document, id, FitParameter::Beta, 0.5), gesture); // another parameter
            document.push(new SetFitParameterCommand(document, id, FitParameter::Beta, 0.7), gesture);
        };
        // Within a gesture they are one step; undoing it restores every field, so none merged into another.
        {
            Gesture gesture(document);
            pushEdits(gesture.id());
        }
        QCOMPARE(stack.count(), 2);
        const QByteArray edited = f.json();
        QCOMPARE(document.object(id)->track.sketch.beta, 0.7);
        stack.undo();
        QCOMPARE(f.json(), before);
        stack.redo();
        QCOMPARE(f.json(), edited);

        // Outside a gesture nothing merges, not even the same parameter set twice.
        stack.undo();
        pushEdits(kNoGesture);
        QCOMPARE(stack.count(), 7);
        stack.undo();
        QCOMPARE(document.object(id)->track.sketch.beta, 0.5);
        stack.redo();
        stack.push(new ToggleKeyframeConstraintCommand(document, id, 0));
        stack.push(new ToggleKeyframeConstraintCommand(document, id, 0)); // toggles never merge
        QCOMPARE(stack.count(), 9);
    }

    void commandsPushedAloneNeverMerge()
    {
        Fixture f;
        // The same key moved twice, then two fields typed one after the other.
        f.document.push(new SetKeyframeTimeCommand(f.document, f.id, 1, 1.2));
        f.document.push(new SetKeyframeTimeCommand(f.document, f.id, 1, 1.4));
        f.document.push(new SetKeyframePositionCommand(f.document, f.id, 1, {5, 0, 0}));
        f.document.push(new SetKeyframeTimeCommand(f.document, f.id, 1, 1.5));
        QCOMPARE(f.stack().count(), 5);
        QCOMPARE(f.document.newestStepGesture(), kNoGesture);
        f.stack().undo();
        f.stack().undo();
        QCOMPARE(f.keyTime(1), 1.4);
        f.stack().undo();
        QCOMPARE(f.keyTime(1), 1.2);
    }

    void aGestureThatEndsWhereItBeganLeavesNoStep()
    {
        Fixture f;
        const QByteArray before = f.json();
        QSignalSpy cleanChanged(&f.stack(), &QUndoStack::cleanChanged);
        {
            Gesture drag(f.document);
            for (double time : {1.2, 1.5, 1.1})
                drag.push(new SetKeyframeTimeCommand(f.document, f.id, 1, time));
            QCOMPARE(f.stack().count(), 2);
            QVERIFY(!f.stack().isClean());
            drag.push(new SetKeyframeTimeCommand(f.document, f.id, 1, 1.0));
            QVERIFY(!drag.hasStep());
        }
        QCOMPARE(f.stack().count(), 1);
        QVERIFY(f.stack().isClean());
        QVERIFY(!f.document.isModified());
        QCOMPARE(f.json(), before);
        // It went modified and back: the last word is clean.
        QVERIFY(!cleanChanged.isEmpty());
        QCOMPARE(cleanChanged.last().at(0).toBool(), true);

        // A turn away and back, exactly: quaternions are compared component by component.
        {
            Gesture turn(f.document);
            turn.push(new SetKeyframeOrientationCommand(f.document, f.id, 0, aboutZ(0.4)));
            turn.push(new SetKeyframeOrientationCommand(f.document, f.id, 0, Eigen::Quaterniond::Identity()));
        }
        QCOMPARE(f.stack().count(), 1);
        QCOMPARE(f.json(), before);

        // A drag that has not moved yet: its first edit sets the value the key has.
        {
            Gesture still(f.document);
            still.push(new SetKeyframePositionCommand(f.document, f.id, 2, {2, 0, 0}));
            QVERIFY(!still.hasStep());
        }
        QCOMPARE(f.stack().count(), 1);
        QVERIFY(f.stack().isClean());
    }

    void aGestureBackAtItsStartGoesOnFromThere()
    {
        Fixture f;
        Gesture drag(f.document);
        drag.push(new SetKeyframeTimeCommand(f.document, f.id, 1, 1.3));
        drag.push(new SetKeyframeTimeCommand(f.document, f.id, 1, 1.0));
        QCOMPARE(f.stack().count(), 1);
        drag.push(new SetKeyframeTimeCommand(f.document, f.id, 1, 0.7));
        drag.finish();
        QCOMPARE(f.stack().count(), 2);
        f.stack().undo();
        QCOMPARE(f.keyTime(1), 1.0);
        QVERIFY(f.stack().isClean());
    }

    // The sphere view's erasing and drawing: strokes added, edited and erased, and the magnitude
    // plot's curve and window, all in one gesture. One step; undo gives back the document exactly.
    void aGestureOfManyKindsIsOneStep()
    {
        Fixture f;
        const QByteArray before = f.json();
        const DirectionStroke drawn{{Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()}, {}};
        {
            Gesture gesture(f.document);
            gesture.push(new AddStrokeCommand(f.document, f.id, drawn));
            gesture.push(new EditStrokeCommand(f.document, f.id, 2, {{Eigen::Vector3d::UnitX()}, {}}));
            gesture.push(new EditStrokeCommand(f.document, f.id, 2, {{-Eigen::Vector3d::UnitX()}, {}}));
            gesture.push(new EraseStrokeCommand(f.document, f.id, 0));
            gesture.push(new EditStrokeCommand(f.document, f.id, 0, {{-Eigen::Vector3d::UnitZ()}, {}}));
            gesture.push(new SetMagnitudeCurveCommand(f.document, f.id, {{0, 1}, {2, 3}}));
            gesture.push(new SetMagnitudeCurveCommand(f.document, f.id, {{0, 2}, {2, 4}}));
            gesture.push(new SetFitWindowCommand(f.document, f.id, std::pair(0.5, 1.5)));
            gesture.push(new SetFitWindowCommand(f.document, f.id, std::pair(0.25, 1.5)));
        }
        QCOMPARE(f.stack().count(), 2);
        QCOMPARE(f.stack().undoText(), QStringLiteral("Add Stroke"));
        const QByteArray after = f.json();
        const SketchState& sketch = f.document.object(f.id)->track.sketch;
        QCOMPARE(sketch.directionStrokes.size(), std::size_t{2});
        QCOMPARE(sketch.directionStrokes[0].points.front(), -Eigen::Vector3d::UnitZ());
        QCOMPARE(sketch.directionStrokes[1].points.front(), -Eigen::Vector3d::UnitX());
        QCOMPARE(sketch.magnitude.back().magnitude, 4.0);
        QCOMPARE(*sketch.window, std::pair(0.25, 1.5));

        f.stack().undo();
        QCOMPARE(f.json(), before);
        QVERIFY(f.stack().isClean());
        f.stack().redo();
        QCOMPARE(f.json(), after);
        f.stack().undo();
        QCOMPARE(f.json(), before);
    }

    // Edits of several kinds that each come back: the step goes, as each of its commands did.
    void aGestureOfManyKindsBackAtItsStartLeavesNoStep()
    {
        Fixture f;
        const QByteArray before = f.json();
        {
            Gesture gesture(f.document);
            gesture.push(new SetFitWindowCommand(f.document, f.id, std::pair(0.5, 1.5)));
            gesture.push(new SetFitWindowCommand(f.document, f.id, std::nullopt));
            gesture.push(new SetMagnitudeCurveCommand(f.document, f.id, {{0, 1}, {2, 3}}));
            gesture.push(new SetMagnitudeCurveCommand(f.document, f.id, {}));
        }
        QCOMPARE(f.stack().count(), 1);
        QCOMPARE(f.json(), before);
        QVERIFY(f.stack().isClean());
    }

    void theDocumentKnowsWhichGesturesAreOpen()
    {
        Fixture f;
        QSignalSpy ended(&f.document, &Document::gestureEnded);
        QVERIFY(!f.document.isGestureOpen());
        std::optional<Gesture> first(std::in_place, f.document);
        QVERIFY(f.document.isGestureOpen());
        const GestureId firstId = first->id();
        {
            Gesture second(f.document);
            QVERIFY(second.id() != firstId);
            QVERIFY(second.id() != kNoGesture);
        }
        QCOMPARE(ended.count(), 1);
        QVERIFY(f.document.isGestureOpen()); // the first is still open
        first->push(new SetKeyframeTimeCommand(f.document, f.id, 1, 1.5));
        QCOMPARE(f.document.newestStepGesture(), firstId);
        first->finish();
        QVERIFY(!f.document.isGestureOpen());
        QCOMPARE(ended.count(), 2);
        QCOMPARE(ended.last().at(0).value<GestureId>(), firstId);
        first.reset(); // finishing again emits nothing
        QCOMPARE(ended.count(), 2);
    }

    // A gesture that has ended can be continued, as the pattern pad's repeat box does: the push
    // joins its step while that step is the newest, and begins another once something came between.
    void anEndedGestureContinuesOnlyWhileItsStepIsNewest()
    {
        Fixture f;
        const GestureId edits = Gesture(f.document).id();
        f.document.push(new SetKeyframeTimeCommand(f.document, f.id, 1, 1.2), edits);
        f.document.push(new SetKeyframeTimeCommand(f.document, f.id, 1, 1.4), edits);
        QCOMPARE(f.stack().count(), 2);
        f.document.push(new SetKeyframePositionCommand(f.document, f.id, 0, {0, 1, 0}));
        f.document.push(new SetKeyframeTimeCommand(f.document, f.id, 1, 1.6), edits);
        QCOMPARE(f.stack().count(), 4);
        f.stack().undo();
        QCOMPARE(f.keyTime(1), 1.4);
        // Undone, the step is no longer the newest: the next push is a step of its own.
        f.stack().undo();
        f.stack().undo();
        QCOMPARE(f.keyTime(1), 1.0);
        f.document.push(new SetKeyframeTimeCommand(f.document, f.id, 1, 1.1), edits);
        QCOMPARE(f.stack().count(), 2);
        QCOMPARE(f.stack().index(), 2);
    }
};

QTEST_GUILESS_MAIN(TstGestures)
#include "tst_gestures.moc"
