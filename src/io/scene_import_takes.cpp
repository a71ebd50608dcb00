// planTakes (scene_import.h): which of a file's animations make the motion when the import options do
// not say.

#include "io/scene_import.h"

#include <QSet>

#include <algorithm>
#include <map>

namespace gyre::io {

namespace {

bool movesDisjointNodes(const std::vector<AnimationSummary>& animations)
{
    QSet<QString> moved;
    for (const AnimationSummary& animation : animations)
        for (const QString& node : animation.nodes) {
            if (moved.contains(node))
                return false;
            moved.insert(node);
        }
    return true;
}

// A take of Blender's FBX exporter: "Object|Action", moving the object alone.
struct BlenderTake {
    std::size_t index;
    QString object;
    QString action;
};

std::optional<std::vector<BlenderTake>> blenderTakes(const std::vector<AnimationSummary>& animations)
{
    std::vector<BlenderTake> takes;
    for (std::size_t i = 0; i < animations.size(); ++i) {
        const AnimationSummary& animation = animations[i];
        const qsizetype bar = animation.name.indexOf(QLatin1Char('|'));
        if (bar <= 0)
            return std::nullopt;
        BlenderTake take{i, animation.name.left(bar), animation.name.mid(bar + 1)};
        if (animation.nodes != QStringList{take.object})
            return std::nullopt;
        takes.push_back(std::move(take));
    }
    return takes;
}

// Blender names an object's first action "<object>Action", a later one "<object>Action.001".
bool isNamedAfter(const QString& action, const QString& object)
{
    const QString stem = object + QLatin1String("Action");
    return action == stem || (action.startsWith(stem + QLatin1Char('.')) && action.size() > stem.size() + 1);
}

TakePlan planBlenderTakes(const std::vector<AnimationSummary>& animations, const std::vector<BlenderTake>& takes)
{
    // The objects in the order of their first take; each object's takes in the file's order.
    std::vector<QString> objects;
    std::map<QString, std::vector<const BlenderTake*>> takesOf;
    for (const BlenderTake& take : takes) {
        auto [entry, isNew] = takesOf.try_emplace(take.object);
        if (isNew)
            objects.push_back(take.object);
        entry->second.push_back(&take);
    }
    const auto namedAfterAnotherObject = [&](const BlenderTake& take) {
        return std::any_of(objects.begin(), objects.end(), [&](const QString& object) {
            return object != take.object && isNamedAfter(take.action, object);
        });
    };
    TakePlan plan{{}, TakeRule::BlenderActions, {}};
    QStringList chosen;
    for (const QString& object : objects) {
        const std::vector<const BlenderTake*>& candidates = takesOf.at(object);
        const auto pick = [&](auto predicate) {
            const auto found = std::find_if(candidates.begin(), candidates.end(),
                                            [&](const BlenderTake* take) { return predicate(*take); });
            return found == candidates.end() ? nullptr : *found;
        };
        const BlenderTake* take = pick([&](const BlenderTake& t) { return t.action == object + QLatin1String("Action"); });
        if (!take)
            take = pick([&](const BlenderTake& t) { return isNamedAfter(t.action, object); });
        if (!take)
            take = pick([&](const BlenderTake& t) { return !namedAfterAnotherObject(t); });
        if (!take)
            take = candidates.front();
        plan.takes.push_back(take->index);
        chosen << FileError::tr("'%1' plays take %2 '%3'").arg(object).arg(take->index).arg(animations[take->index].name);
    }
    plan.warnings << FileError::tr("the file's %1 takes are Blender's, one for every object and action; each object "
                                   "gets its own action: %2")
                         .arg(animations.size())
                         .arg(chosen.join(QLatin1String(", ")));
    return plan;
}

} // namespace

TakePlan planTakes(const std::vector<AnimationSummary>& animations)
{
    if (animations.empty())
        return {{}, TakeRule::NoAnimation, {}};
    if (animations.size() == 1)
        return {{0}, TakeRule::Single, {}};
    if (movesDisjointNodes(animations)) {
        TakePlan plan{{}, TakeRule::Disjoint, {}};
        for (std::size_t i = 0; i < animations.size(); ++i)
            plan.takes.push_back(i);
        return plan;
    }
    if (const std::optional<std::vector<BlenderTake>> takes = blenderTakes(animations))
        return planBlenderTakes(animations, *takes);
    return {{0}, TakeRule::ChoiceNeeded, {}};
}

} // namespace gyre::io
