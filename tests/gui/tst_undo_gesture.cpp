// A gesture is one undo step: its commands merge, and the next gesture is a step of its own even
// where the model's commands would merge with it.

#include "app/undo_gesture.h"
#include "model/commands/set_keyframe_position_command.h"
#include "model/document.h"
#include "model/commands/import_objects_command.h"

#include <QTest>

using namespace gyre;

namespace {

// A document with one object and one key at the origin.
model::ObjectId addObjectWithKey(model::Document& document)
{
    model::SceneObject object;
    object.id = 1;
    object.name = QStringLiteral("block");
    object.track.keys.push_back(model::Keyframe{});
    auto* command = new model::ImportObjectsCommand(document, {object});
    document.undoStack().push(command);
    const model::ObjectId id = command->ids().front();
    document.undoStack().clear();
    return id;
}

double keyX(const model::Document& document, model::ObjectId id)
{
    return document.object(id)->track.keys.front().pose.position.x();
}

} // namespace

class TestUndoGesture : public QObject {
    Q_OBJECT

private slots:
    void aGestureIsOneStepAndTheNextIsAnother()
    {
        model::Document document;
        const model::ObjectId id = addObjectWithKey(document);
        QUndoStack& stack = document.undoStack();
        {
            app::UndoGesture drag(stack);
            for (int step = 1; step <= 5; ++step)
                drag.push(new model::SetKeyframePositionCommand(document, id, 0, Eigen::Vector3d(step, 0, 0)));
        }
        app::UndoGesture second(stack);
        second.push(new model::SetKeyframePositionCommand(document, id, 0, Eigen::Vector3d(7, 0, 0)));
        QVERIFY(second.isOpen());
        second.finish();
        QCOMPARE(stack.count(), 2);
        QCOMPARE(keyX(document, id), 7.0);
        stack.undo();
        QCOMPARE(keyX(document, id), 5.0);
        stack.undo();
        QCOMPARE(keyX(document, id), 0.0);
    }

    void pushAloneNeverMerges()
    {
        model::Document document;
        const model::ObjectId id = addObjectWithKey(document);
        app::pushAlone(document.undoStack(), new model::SetKeyframePositionCommand(document, id, 0, Eigen::Vector3d(1, 0, 0)));
        app::pushAlone(document.undoStack(), new model::SetKeyframePositionCommand(document, id, 0, Eigen::Vector3d(2, 0, 0)));
        QCOMPARE(document.undoStack().count(), 2);
        QCOMPARE(document.undoStack().text(1), document.undoStack().text(0));
    }
};

QTEST_MAIN(TestUndoGesture)
#include "tst_undo_gesture.moc"
