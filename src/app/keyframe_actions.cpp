#include "app/keyframe_actions.h"

#include "model/commands/add_keyframe_command.h"
#include "model/commands/apply_euler_filter_command.h"
#include "model/commands/remove_keyframe_command.h"
#include "model/commands/step_ballistic_solution_command.h"
#include "model/commands/toggle_keyframe_constraint_command.h"
#include "model/track_evaluation.h"

#include <QAction>
#include <QStatusBar>

#include <algorithm>
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
    connect(actions_.add, &QAction::triggered, this, &KeyframeActions::addKeyframe);
    connect(actions_.remove, &QAction::triggered, this, &KeyframeActions::removeKeyframe);
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
    updateActions();
}

void KeyframeActions::addKeyframe()
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object == nullptr)
        return;
    const double time = document_.scene().currentTime;
    // The key holds the pose the object has now, so keying changes nothing but the keys.
    const model::Keyframe key{time, document_.motion(object->id)->motion().at(time), true};
    const model::ObjectId id = object->id;
    try {
        document_.push(new model::AddKeyframeCommand(document_, id, key));
    } catch (const std::invalid_argument& error) {
        statusBar_->showMessage(tr("Cannot add a keyframe: %1").arg(QString::fromUtf8(error.what())),
                                kMessageMilliseconds);
        return;
    }
    const auto& keys = document_.object(id)->track.keys;
    const auto added = std::find_if(keys.begin(), keys.end(), [time](const model::Keyframe& k) { return k.time == time; });
    if (added != keys.end())
        selection_.selectKey(id, static_cast<std::size_t>(added - keys.begin()));
}

void KeyframeActions::removeKeyframe()
{
    if (selection_.selectedKey() == nullptr)
        return;
    const model::ObjectId object = selection_.object();
    document_.push(new model::RemoveKeyframeCommand(document_, object, *selection_.key()));
    selection_.selectObject(object); // the key is gone; its index now names its neighbour
}

void KeyframeActions::toggleConstraint()
{
    if (selection_.selectedKey() != nullptr)
        document_.push(new model::ToggleKeyframeConstraintCommand(document_, selection_.object(), *selection_.key()));
    updateActions();
}

void KeyframeActions::applyEulerFilter()
{
    const model::SceneObject* object = selection_.selectedObject();
    if (object != nullptr && model::ApplyEulerFilterCommand::changes(object->track))
        document_.push(new model::ApplyEulerFilterCommand(document_, object->id));
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
    actions_.eulerFilter->setEnabled(object != nullptr && model::ApplyEulerFilterCommand::changes(object->track));
    const bool flies = object != nullptr && object->track.interpolation == InterpolationMethod::Ballistic &&
                       object->track.keys.size() >= 2;
    actions_.nextFlight->setEnabled(flies);
    actions_.previousFlight->setEnabled(flies);
    actions_.add->setEnabled(selection_.selectedObject() != nullptr);
    actions_.remove->setEnabled(key != nullptr);
    actions_.toggleConstraint->setEnabled(key != nullptr);
    actions_.toggleConstraint->setChecked(key != nullptr && key->constrained);
}

} // namespace gyre::app
