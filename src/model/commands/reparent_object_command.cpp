#include "model/commands/reparent_object_command.h"

#include "model/commands/command_checks.h"
#include "model/scene_queries.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace gyre::model {

ParentField::Value reparented(const Document& document, ObjectId object, ObjectId newParent)
{
    requireObject(document, object);
    const Scene& scene = document.scene();
    std::vector<ObjectId> order = objectOrder(scene);
    if (newParent == kNoObject)
        return {newParent, order};
    requireObject(document, newParent);
    if (newParent == object || isAncestor(scene, object, newParent))
        throw std::invalid_argument("object " + std::to_string(newParent) + " cannot be the parent of object " +
                                    std::to_string(object) + ", which is itself or its ancestor");
    if (*objectIndex(scene, newParent) < *objectIndex(scene, object))
        return {newParent, order};
    const std::vector<ObjectId> subtree = subtreeOf(scene, object);
    std::erase_if(order, [&subtree](ObjectId id) { return std::find(subtree.begin(), subtree.end(), id) != subtree.end(); });
    order.insert(std::find(order.begin(), order.end(), newParent) + 1, subtree.begin(), subtree.end());
    return {newParent, order};
}

ReparentObjectCommand::ReparentObjectCommand(Document& document, ObjectId object, ObjectId newParent,
                                             QUndoCommand* parent)
    : ChangeValueCommand(document, {object, 0}, reparented(document, object, newParent),
                         commandText(QT_TRANSLATE_NOOP("gyre::model::Command", "Reparent Object")), parent)
{
}

} // namespace gyre::model
