#include "model/commands/replace_keyframes_command.h"

#include "model/commands/command_checks.h"
#include "model/commands/object_fields.h"
#include "model/document_editor.h"
#include "model/value_checks.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace gyre::model {

namespace {

const char* editText(ReplaceKeyframesCommand::Edit edit)
{
    using Edit = ReplaceKeyframesCommand::Edit;
    switch (edit) {
    case Edit::Delete:
        return QT_TRANSLATE_NOOP("gyre::model::Command", "Delete Keyframes");
    case Edit::Insert:
        return QT_TRANSLATE_NOOP("gyre::model::Command", "Insert Keyframes");
    case Edit::Paste:
        return QT_TRANSLATE_NOOP("gyre::model::Command", "Paste Keyframes");
    case Edit::Move:
        return QT_TRANSLATE_NOOP("gyre::model::Command", "Move Keyframes");
    case Edit::Scale:
        break;
    }
    return QT_TRANSLATE_NOOP("gyre::model::Command", "Scale Keyframes");
}

std::vector<std::pair<ObjectId, SharedVector<Keyframe>>> checkedKeys(const Document& document, ObjectKeys keys)
{
    std::vector<std::pair<ObjectId, SharedVector<Keyframe>>> checked;
    std::vector<ObjectId> seen;
    for (auto& [object, objectKeys] : keys) {
        const MotionTrack& track = requireObject(document, object).track;
        if (std::find(seen.begin(), seen.end(), object) != seen.end())
            throw std::invalid_argument("object " + std::to_string(object) + " is given keys twice");
        seen.push_back(object);
        checkKeyframes(objectKeys);
        checkPoseBudget(objectKeys.size(), track.interpolation, track.subdivision);
        checked.emplace_back(object, std::move(objectKeys));
    }
    return checked;
}

bool sameKeys(const std::vector<Keyframe>& a, const std::vector<Keyframe>& b)
{
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const Keyframe& x, const Keyframe& y) {
        return x.time == y.time && sameValue(x.pose.orientation, y.pose.orientation) &&
               x.pose.position == y.pose.position && x.constrained == y.constrained;
    });
}

} // namespace

ReplaceKeyframesCommand::ReplaceKeyframesCommand(Document& document, ObjectKeys keys, Edit edit, QUndoCommand* parent)
    : MergeableCommand(commandText(editText(edit)), parent)
    , document_(document)
    , edit_(edit)
    , keys_(checkedKeys(document, std::move(keys)))
{
}

void ReplaceKeyframesCommand::swap()
{
    DocumentEditor editor(document_);
    for (auto& [object, keys] : keys_) {
        SharedVector<Keyframe> previous = objectIn(editor.scene(), object).track.keys;
        editor.edit(object, Change::Keyframes,
                    [&, id = object](Scene& scene) { objectIn(scene, id).track.keys = keys; });
        keys = std::move(previous);
    }
}

bool ReplaceKeyframesCommand::mergeWithin(const MergeableCommand& later)
{
    const auto* same = dynamic_cast<const ReplaceKeyframesCommand*>(&later);
    if (same == nullptr || same->edit_ != edit_ || same->keys_.size() != keys_.size())
        return false;
    for (std::size_t i = 0; i < keys_.size(); ++i)
        if (same->keys_[i].first != keys_[i].first)
            return false;
    return true; // this command keeps the keys from before both; the document holds the later ones
}

bool ReplaceKeyframesCommand::changesNothing() const
{
    return std::all_of(keys_.begin(), keys_.end(), [this](const auto& entry) {
        return sameKeys(objectIn(document_.scene(), entry.first).track.keys, entry.second);
    });
}

} // namespace gyre::model
