#pragma once
// The selected object's track, as the views of it follow it: one signal when what such a view shows
// may have changed, instead of each view filtering Document::changed for the selected object and
// remembering which object it showed (issue 18).
//
// changed(changes) comes with
// - Change::Scene: the scene was replaced; what the view shows is of another scene;
// - Change::Removed | Change::Added: another object is selected, or none (the one followed left,
//   another came); a drag or gesture of the view on the old one should end;
// - the document's changes of the selected object (Keyframes, TrackSettings, Sketch, Object);
// - Change::SceneSettings: the frame rate or time range, which a view of a track over time shows.
// Selecting another key of the same object emits nothing: views that show the key follow Selection.
// A reset that also selects another object may emit Scene and the other object's flags both.

#include "app/selection.h"
#include "model/document.h"

#include <QObject>

#include <memory>

namespace gyre::app {

class SelectedTrack : public QObject {
    Q_OBJECT

public:
    SelectedTrack(const model::Document& document, const Selection& selection, QObject* parent = nullptr);

    // The flags changed() carries when another object is selected.
    static constexpr model::Changes kAnotherObject = model::Changes(model::Change::Removed) | model::Change::Added;

    model::ObjectId object() const { return object_; }
    // The selected object, or null.
    const model::SceneObject* selectedObject() const { return document_.object(object_); }
    // The selected track's evaluated motion, shared with every other view and job until the track
    // changes (Document::motion); null without a selection.
    std::shared_ptr<const model::SharedTrackMotion> motion() const { return document_.motion(object_); }

signals:
    void changed(gyre::model::Changes changes);

private:
    void onDocumentChanged(model::ObjectId object, model::Changes changes);
    void onSelectionChanged();

    const model::Document& document_;
    const Selection& selection_;
    model::ObjectId object_ = model::kNoObject;
};

} // namespace gyre::app
