#pragma once
// The object a verb's --object names in a project.

#include "model/scene.h"

#include <QString>

namespace gyre::cli {

// The one object of the scene named `name` that has keyframes. Throws InputError naming the file.
const model::SceneObject& trackedObjectNamed(const model::Scene& scene, const QString& name, const QString& path);

} // namespace gyre::cli
