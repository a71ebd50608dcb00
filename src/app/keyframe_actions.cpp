#include "app/keyframe_actions.h"

#include "model/commands/replace_keyframes_command.h"
#include "model/commands/step_ballistic_solution_command.h"
#include "model/commands/toggle_keyframe_constraint_command.h"
#include "model/key_edits.h"
#include "model/track_evaluation.h"

#include <QAction>
#include <QUndoCommand>
#include <QStatusBar>

#include <algorithm>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>

namespace gyre::app {

namespace {

constexpr int kMessageMilliseconds = 5000;

} // namespace

KeyframeActions::KeyframeActions(model::Document& document, Selection& selection, KeyframeActionSet actions,
                                 QStatusBar* statusBar, QObject* parent)
    : QObject(parent)
    , document_(document)
    , selection_(selection)
    , selectedTrack_(document, selection)
    , actions_(actions)
    , statusBar_(statusBar)
{
    connect(actions_.add, &QAction::triggered, this, &KeyframeActions::addKeyframes);
    connect(actions_.remove, &QAction::triggered, this, &KeyframeActions::removeKeyframes);
    connect(actions_.selectAll, &QAction::triggered, &selection_, &Selection::selectAllKeys);
    connect(actions_.selectNone, &QAction::triggered, &selection_, &Selection::deselectKeys);
    // triggered, not toggled: the action's check mark follows the key, and setChecked from
    // updateActions must not toggle the key back.
    connect(actions_.toggleConstraint, &QAction::triggered, this, &KeyframeActions::toggleConstraint);
    connect(actions_.eulerFilter, &QAction::triggered, this, &KeyframeActions::applyEulerFilter);
    connect(actions_.nextFlight, &QAction::triggered, this, [this] { stepFlightSolution(1); });
    connect(actions_.previousFlight, &QAction::triggered, this, [this] { stepFlightSolution(-1); });
    connect(&selection_, &Selection::changed, this, &KeyframeActions::updateActions);
    connect(&selectedTrack_, &SelectedTrack::changed, this, [this](model::Changes changes) {
        if (changes & (model::Change::Keyframes | model::Change::TrackSettings | model::Change::Scene))
            updateActions();
    });
    // The other selected objects' keys decide whether the Euler filter has work too.
    connect(&document_, &model::Document::changed, this, [this](model::ObjectId object, model::Changes changes) {
        if (object != selection_.object() && selection_.isObjectSelected(object) &&
            (changes & (model::Change::Keyframes | model::Change::TrackSettings)))
            updateActions();
    });
    updateActions();
}

void KeyframeActions::addKeyframes()
{
    const double time = document_.scene().currentTime;
    model::ObjectKeys keys;
    try {
        for (model::ObjectId id : selection_.objects()) {
            const auto& existing = document_.object(id)->track.keys;
            if (std::any_of(existing.begin(), existing.end(), [time](const model::Keyframe& key) { return key.time == time; }))
                continue;
            // The key holds the pose the object has now, so keying changes nothing but the keys. A motion that
            // cannot be built (a free flight with no solution) throws here.
            const model::Keyframe key{time, document_.motion(id)->motion().at(time), true};
            keys.emplace_back(id, model::withKeys(existing, {key}));
        }
        if (keys.empty())
            return;
        document_.push(new model::ReplaceKeyframesCommand(document_, keys, model::ReplaceKeyframesCommand::Edit::Insert));
    } catch (const std::invalid_argument& error) {
        statusBar_->showMessage(tr("Cannot add a keyframe: %1").arg(QString::fromUtf8(error.what())),
                                kMessageMilliseconds);
        return;
    }
    std::set<KeyRef> added;
    std::optional<KeyRef> active;
    for (const auto& [id, objectKeys] : keys) {
        const auto at = std::find_if(objectKeys.begin(), objectKeys.end(),
                                     [time](const model::Keyframe& key) { return key.time == time; });
        const KeyRef key{id, static_cast<std::size_t>(at - objectKeys.begin())};
        added.insert(key);
        if (id == selection_.object())
            active = key;
    }
    selection_.selectKeys(added, false, active);
}

void KeyframeActions::removeKeyframes()
{
    model::ObjectKeys keys;
    for (model::ObjectId id : selection_.objects())
        if (const std::vector<std::size_t> removed = selection_.keysOf(id); !removed.empty())
            keys.emplace_back(id, model::withoutKeys(document_.object(id)->track.keys, removed));
    if (keys.empty())
        return;
    document_.push(new model::ReplaceKeyframesCommand(document_, std::move(keys), model::ReplaceKeyframesCommand::Edit::Delete));
    selection_.deselectKeys(); // the keys are gone; their indices now name their neighbours
}

void KeyframeActions::toggleConstraint()
{
    if (selection_.selectedKey() != nullptr)
        document_.push(new model::ToggleKeyframeConstraintCommand(document_, selection_.object(), *selection_.key()));
    updateActions();
}

model::ApplyEulerFilterCommand::KeySubset KeyframeActions::keysToFilter(model::ObjectId object) const
{
    if (selection_.keys().empty())
        return std::nullopt;
    return selection_.keysOf(object);
}

bool KeyframeActions::eulerFilterChanges(model::ObjectId object) const
{
    const model::MotionTrack& track = document_.object(object)->track;
    model::ApplyEulerFilterCommand::KeySubset subset = keysToFilter(object);
    const auto known = eulerFilterAnswers_.find(object);
    if (known != eulerFilterAnswers_.end() && known->second.keys.sharesElementsWith(track.keys) &&
        known->second.rotationMode == track.rotationMode && known->second.subset == subset)
        return known->second.changes;
    const bool changes = model::ApplyEulerFilterCommand::changes(track, subset);
    eulerFilterAnswers_.insert_or_assign(object, EulerFilterAnswer{track.keys, track.rotationMode, std::move(subset), changes});
    return changes;
}

void KeyframeActions::applyEulerFilter()
{
    // One undo step for all of them, named as one object's.
    auto step = std::make_unique<QUndoCommand>(tr("Apply Euler Filter"));
    for (model::ObjectId id : selection_.objects())
        if (eulerFilterChanges(id))
            new model::ApplyEulerFilterCommand(document_, id, keysToFilter(id), step.get());
    if (step->childCount() > 0)
        document_.push(step.release());
}

void KeyframeActions::stepFlightSolution(int direction)
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr)
        return;
    try {
        if (const auto solutions = model::StepBallisticSolutionCommand::stepped(document_, object->id,
                                                                                document_.scene().currentTime, direction))
            document_.push(new model::StepBallisticSolutionCommand(document_, object->id, *solutions));
        else
            statusBar_->showMessage(tr("This span has a single free flight"), kMessageMilliseconds);
    } catch (const std::invalid_argument& error) {
        statusBar_->showMessage(tr("Cannot step the flight: %1").arg(QString::fromUtf8(error.what())),
                                kMessageMilliseconds);
    }
}

void KeyframeActions::updateActions()
{
    const model::Keyframe* key = selection_.selectedKey();
    const model::SceneObject* object = selection_.selectedObject();
    // On every Keyframes change, each step of a drag included: stops at the first object, and in it at the first
    // key, the filter would change.
    const std::vector<model::ObjectId> objects = selection_.objects();
    std::erase_if(eulerFilterAnswers_, [&objects](const auto& answer) { return std::ranges::find(objects, answer.first) == objects.end(); });
    actions_.eulerFilter->setEnabled(
        std::ranges::any_of(objects, [this](model::ObjectId id) { return eulerFilterChanges(id); }));
    const bool flies = object != nullptr && object->track.interpolation == InterpolationMethod::Ballistic &&
                       object->track.keys.size() >= 2;
    actions_.nextFlight->setEnabled(flies);
    actions_.previousFlight->setEnabled(flies);
    actions_.add->setEnabled(object != nullptr);
    actions_.remove->setEnabled(!selection_.keys().empty());
    actions_.selectAll->setEnabled(object != nullptr && !object->track.keys.empty());
    actions_.selectNone->setEnabled(!selection_.keys().empty());
    actions_.toggleConstraint->setEnabled(key != nullptr);
    actions_.toggleConstraint->setChecked(key != nullptr && key->constrained);
}

} // namespace gyre::app
