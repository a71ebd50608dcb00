#pragma once
// What gyre-cli info and import say about a scene file's animations and the settings of its import.

#include "io/scene_import.h"

#include <string>

namespace gyre::cli {

// One line a take: "  2: 'Quat|QuatAction', 0.667 s, moves Quat (imported)".
std::string animationList(const io::SceneImport& imported);

// Which takes the import used and why, for gyre-cli info: "imported: ...".
std::string takeChoiceLine(const io::SceneImport& imported);

// "30 fps (the FBX time mode), 1 unit = 0.01 m (the FBX UnitScaleFactor, 1 cm), Y-up (the FBX UpAxis)",
// with the time shift when there is one.
std::string settingsLine(const io::SceneImport& imported);

} // namespace gyre::cli
