#include "app/selected_track.h"

namespace gyre::app {

using model::Change;

SelectedTrack::SelectedTrack(const model::Document& document, const Selection& selection, QObject* parent)
    : QObject(parent)
    , document_(document)
    , selection_(selection)
    , object_(selection.object())
{
    // The selection was made first, so it follows each change before this does: a removed
    // selected object is already unselected here.
    connect(&document_, &model::Document::changed, this, &SelectedTrack::onDocumentChanged);
    connect(&selection_, &Selection::changed, this, &SelectedTrack::onSelectionChanged);
}

void SelectedTrack::onDocumentChanged(model::ObjectId object, model::Changes changes)
{
    if (changes.testFlag(Change::Scene)) {
        object_ = selection_.object();
        emit changed(changes);
    } else if (changes.testFlag(Change::SceneSettings)) {
        emit changed(Change::SceneSettings);
    } else if (object == object_ && object_ != model::kNoObject && !(changes & kAnotherObject)) {
        emit changed(changes);
    }
}

void SelectedTrack::onSelectionChanged()
{
    if (selection_.object() == object_)
        return;
    object_ = selection_.object();
    emit changed(kAnotherObject);
}

} // namespace gyre::app
