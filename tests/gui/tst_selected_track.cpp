// SelectedTrack (selected_track.h): one signal for what a view of the selected object shows, so that
// no view filters the document's changes for its object itself.

#include "app/selected_track.h"
#include "app/selection.h"
#include "model/commands/delete_object_command.h"
#include "model/commands/import_objects_command.h"
#include "model/commands/rename_object_command.h"
#include "model/commands/set_interpolation_command.h"
#include "model/commands/set_keyframe_time_command.h"
#include "model/commands/set_time_range_command.h"

#include <QSignalSpy>
#include <QTest>

#include <vector>

using namespace gyre;
using model::Change;
using model::Changes;

namespace {

model::SceneObject objectWithKeys(model::ObjectId id)
{
    model::SceneObject object;
    object.id = id;
    for (double time : {0.0, 1.0, 2.0})
        object.track.keys.push_back({time, {}, true});
    return object;
}

// A document with two objects, the first selected, and what a SelectedTrack says.
struct Fixture {
    Fixture()
    {
        auto* command = new model::ImportObjectsCommand(document, {objectWithKeys(1), objectWithKeys(2)});
        ids = command->ids();
        document.push(command);
        selection.selectObject(ids[0]);
        QObject::connect(&track, &app::SelectedTrack::changed, &track, [this](Changes changes) { said.push_back(changes); });
    }

    model::Document document;
    app::Selection selection{document};
    app::SelectedTrack track{document, selection};
    std::vector<model::ObjectId> ids;
    std::vector<Changes> said;
};

} // namespace

class TestSelectedTrack : public QObject {
    Q_OBJECT

private slots:
    void saysTheSelectedObjectsChangesOnly()
    {
        Fixture f;
        f.document.push(new model::SetKeyframeTimeCommand(f.document, f.ids[1], 1, 1.5));
        f.document.push(new model::RenameObjectCommand(f.document, f.ids[1], QStringLiteral("other")));
        QVERIFY(f.said.empty());
        f.document.push(new model::SetKeyframeTimeCommand(f.document, f.ids[0], 1, 1.5));
        f.document.push(new model::SetInterpolationCommand(f.document, f.ids[0], InterpolationMethod::Squad));
        f.document.push(new model::RenameObjectCommand(f.document, f.ids[0], QStringLiteral("selected")));
        QCOMPARE(f.said, (std::vector<Changes>{Change::Keyframes, Change::TrackSettings, Change::Object}));
        f.said.clear();
        f.document.undoStack().undo();
        QCOMPARE(f.said, std::vector<Changes>{Change::Object});
    }

    void anotherKeyIsNoChangeAnotherObjectIs()
    {
        Fixture f;
        f.selection.selectKey(f.ids[0], 2);
        QVERIFY(f.said.empty());
        f.selection.selectKey(f.ids[1], 0);
        QCOMPARE(f.said, std::vector<Changes>{app::SelectedTrack::kAnotherObject});
        QCOMPARE(f.track.object(), f.ids[1]);
        f.selection.clear();
        QCOMPARE(f.said.size(), std::size_t(2));
        QCOMPARE(f.track.object(), model::kNoObject);
        QVERIFY(f.track.selectedObject() == nullptr);
        QVERIFY(f.track.motion() == nullptr);
        // With nothing selected, no object's change is the selected one's.
        f.document.push(new model::SetKeyframeTimeCommand(f.document, f.ids[0], 1, 1.5));
        QCOMPARE(f.said.size(), std::size_t(2));
    }

    void theSelectedObjectRemovedIsAnotherObject()
    {
        Fixture f;
        f.document.push(new model::DeleteObjectCommand(f.document, f.ids[0]));
        QCOMPARE(f.said, std::vector<Changes>{app::SelectedTrack::kAnotherObject});
        QCOMPARE(f.track.object(), model::kNoObject);
    }

    void theSceneAndItsSettings()
    {
        Fixture f;
        f.document.push(new model::SetTimeRangeCommand(f.document, {25, 0, 4}));
        QCOMPARE(f.said, std::vector<Changes>{Change::SceneSettings});
        f.said.clear();
        f.document.startNewProject();
        QVERIFY(!f.said.empty());
        QVERIFY(f.said.back().testFlag(Change::Scene));
        // The selection moves to the new project's block.
        QCOMPARE(f.track.object(), f.document.scene().objects.front().id);
    }

    // Every SelectedTrack of the same selection hands out the document's one motion of the track.
    void sharesTheDocumentsMotion()
    {
        Fixture f;
        const app::SelectedTrack other(f.document, f.selection);
        QCOMPARE(f.track.motion().get(), f.document.motion(f.ids[0]).get());
        QCOMPARE(other.motion().get(), f.track.motion().get());
        f.track.motion()->motion();
        other.motion()->motion();
        QCOMPARE(f.document.motionBuilds(), std::size_t(1));
        f.document.push(new model::SetKeyframeTimeCommand(f.document, f.ids[0], 1, 1.5));
        QCOMPARE(other.motion()->track().keys[1].time, 1.5);
        QCOMPARE(f.track.motion().get(), other.motion().get());
    }
};

QTEST_GUILESS_MAIN(TestSelectedTrack)
#include "tst_selected_track.moc"
