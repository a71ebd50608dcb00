#include "app/add_object_actions.h"

#include "model/commands/import_objects_command.h"

#include <QAction>
#include <QMenu>

#include <algorithm>
#include <memory>

namespace gyre::app {

namespace {

// `base`, or the first of base.001, base.002, … that no object of `scene` is named.
QString unusedName(const model::Scene& scene, const QString& base)
{
    const auto taken = [&](const QString& name) {
        return std::any_of(scene.objects.begin(), scene.objects.end(),
                           [&](const model::SceneObject& object) { return object.name == name; });
    };
    QString name = base;
    for (int suffix = 1; taken(name); ++suffix)
        name = QStringLiteral("%1.%2").arg(base).arg(suffix, 3, 10, QLatin1Char('0'));
    return name;
}

} // namespace

AddObjectActions::AddObjectActions(model::Document& document, Selection& selection, QMenu& menu, QObject* parent)
    : QObject(parent)
    , document_(document)
    , selection_(selection)
{
    for (const auto& [primitive, key] : model::kPrimitiveNames) {
        QAction* action = menu.addAction(model::primitiveName(primitive));
        action->setObjectName(QStringLiteral("actionAdd-") + QLatin1String(key.data(), static_cast<qsizetype>(key.size())));
        connect(action, &QAction::triggered, this, [this, primitive = primitive] { add(primitive); });
    }
    menu.addSeparator();
    QAction* empty = menu.addAction(tr("Empty"));
    empty->setObjectName(QStringLiteral("actionAdd-empty"));
    connect(empty, &QAction::triggered, this, &AddObjectActions::addEmpty);
}

void AddObjectActions::add(model::Primitive primitive)
{
    model::SceneObject object;
    object.mesh = std::make_shared<const model::Mesh>(model::primitiveMesh(primitive));
    addObject(std::move(object), model::primitiveName(primitive));
}

void AddObjectActions::addEmpty()
{
    model::SceneObject object;
    object.empty = true;
    addObject(std::move(object), tr("Empty"));
}

void AddObjectActions::addObject(model::SceneObject object, const QString& shapeName)
{
    object.id = 1; // the batch's own id; the command gives the scene's
    object.name = unusedName(document_.scene(), shapeName);
    auto* command = new model::ImportObjectsCommand(document_, {std::move(object)});
    command->setText(tr("Add %1").arg(shapeName));
    const model::ObjectId added = command->ids().front();
    document_.push(command);
    selection_.selectObject(added);
}

} // namespace gyre::app
