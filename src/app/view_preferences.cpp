#include "app/view_preferences.h"

#include "app/viewport/viewport.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>
#include <QSettings>

#include <functional>

namespace gyre::app {

namespace {

const char* const kShowTrailKey = "view/showTrail";
const char* const kTrailCopiesKey = "view/trailCopies";
const char* const kTrailEveryFramesKey = "view/trailEveryFrames";
const char* const kYUpKey = "view/yUp";

// The group's checked action's number, or `fallback` when none is checked.
int checkedNumber(const QActionGroup& group, int fallback)
{
    const QAction* checked = group.checkedAction();
    return checked != nullptr ? checked->data().toInt() : fallback;
}

// A checkable action per number, exclusive, in `menu`; the one equal to `current` checked.
template <std::size_t N>
QActionGroup* numberChoices(QMenu& menu, const std::array<int, N>& numbers, int current, const QString& objectPrefix,
                            const std::function<QString(int)>& text)
{
    auto* group = new QActionGroup(&menu);
    for (const int number : numbers) {
        QAction* action = menu.addAction(text(number));
        action->setObjectName(objectPrefix + QString::number(number));
        action->setCheckable(true);
        action->setChecked(number == current);
        action->setData(number);
        group->addAction(action);
    }
    return group;
}

} // namespace

ViewPreferences::ViewPreferences(QMenu& viewMenu, QAction& showTrail, QAction& orthographic, Viewport* viewport, QObject* parent)
    : QObject(parent)
    , viewport_(viewport)
{
    QSettings settings;
    // A value edited by hand is held to the budget up front.
    const TrailSpacing stored = TrailSpacing{settings.value(kTrailCopiesKey, TrailSpacing{}.copies).toInt(),
                                             settings.value(kTrailEveryFramesKey, 0).toInt()}
                                    .clamped();

    // After Show Trail: the actions after it in the menu, the submenu inserted before the first of them.
    const QList<QAction*> actions = viewMenu.actions();
    const qsizetype trailIndex = actions.indexOf(&showTrail);
    QAction* afterTrail = trailIndex + 1 < actions.size() ? actions[trailIndex + 1] : nullptr;
    auto* trailMenu = new QMenu(tr("Trail"), &viewMenu);
    trailMenu->setObjectName(QStringLiteral("menuTrail"));
    viewMenu.insertMenu(afterTrail, trailMenu);
    copies_ = numberChoices(*trailMenu, kCopyChoices, stored.copies, QStringLiteral("actionTrailCopies-"),
                            [](int copies) { return tr("%n Copies", nullptr, copies); });
    trailMenu->addSeparator();
    spacing_ = numberChoices(*trailMenu, kFrameChoices, stored.everyFrames, QStringLiteral("actionTrailEvery-"), [](int frames) {
        return frames == 0 ? tr("Over the Whole Range") : tr("Every %n Frame(s) About the Current Frame", nullptr, frames);
    });

    auto* yUp = new QAction(tr("Y Up"), &viewMenu);
    yUp->setObjectName(QStringLiteral("actionYUp"));
    yUp->setCheckable(true);
    yUp->setToolTip(tr("Show the scene with y up, as Maya does: orbit about y, the grid across it, the front view along −z"));
    yUp->setChecked(settings.value(kYUpKey, false).toBool());
    const qsizetype orthographicIndex = viewMenu.actions().indexOf(&orthographic);
    viewMenu.insertAction(orthographicIndex + 1 < viewMenu.actions().size() ? viewMenu.actions()[orthographicIndex + 1] : nullptr, yUp);

    showTrail.setChecked(settings.value(kShowTrailKey, showTrail.isChecked()).toBool());
    connect(&showTrail, &QAction::toggled, this, [](bool show) { QSettings().setValue(kShowTrailKey, show); });
    connect(yUp, &QAction::toggled, this, [this](bool up) {
        QSettings().setValue(kYUpKey, up);
        if (viewport_ != nullptr)
            viewport_->setUpAxis(up ? UpAxis::Y : UpAxis::Z);
    });
    connect(copies_, &QActionGroup::triggered, this, &ViewPreferences::applyTrailSpacing);
    connect(spacing_, &QActionGroup::triggered, this, &ViewPreferences::applyTrailSpacing);

    if (viewport_ == nullptr) {
        for (QAction* action : trailMenu->actions())
            action->setEnabled(false);
        yUp->setEnabled(false);
        return;
    }
    viewport_->setTrailSpacing(stored);
    viewport_->setUpAxis(yUp->isChecked() ? UpAxis::Y : UpAxis::Z);
}

void ViewPreferences::applyTrailSpacing()
{
    const TrailSpacing spacing{checkedNumber(*copies_, TrailSpacing{}.copies), checkedNumber(*spacing_, 0)};
    QSettings settings;
    settings.setValue(kTrailCopiesKey, spacing.copies);
    settings.setValue(kTrailEveryFramesKey, spacing.everyFrames);
    if (viewport_ != nullptr)
        viewport_->setTrailSpacing(spacing);
}

} // namespace gyre::app
