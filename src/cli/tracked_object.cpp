#include "cli/tracked_object.h"

#include "model/input_error.h"

#include <string>
#include <vector>

namespace gyre::cli {

const model::SceneObject& trackedObjectNamed(const model::Scene& scene, const QString& name, const QString& path)
{
    std::vector<const model::SceneObject*> named;
    for (const model::SceneObject& object : scene.objects)
        if (object.name == name)
            named.push_back(&object);
    const std::string quoted = "'" + name.toStdString() + "'";
    if (named.empty())
        throw InputError(path, "--object: no object is named " + quoted);
    if (named.size() > 1)
        throw InputError(path, "--object: " + std::to_string(named.size()) + " objects are named " + quoted +
                                   "; the name must single out one");
    if (named.front()->track.keys.empty())
        throw InputError(path, "--object: object " + quoted + " has no keyframes");
    return *named.front();
}

} // namespace gyre::cli
