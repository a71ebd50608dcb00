#pragma once
// The scene's gravity (Scene::gravity): what a ballistic track's centre of mass falls with, as the project
// file stores it and the free flight uses it.

#include "core/name_table.h"
#include "model/json_field.h"
#include "model/scene.h"

#include <Eigen/Core>
#include <QJsonObject>

namespace gyre::model {

inline constexpr NameTable<UpDirection, 6> kUpDirectionNames{{{UpDirection::PlusX, "+x"},
                                                              {UpDirection::MinusX, "-x"},
                                                              {UpDirection::PlusY, "+y"},
                                                              {UpDirection::MinusY, "-y"},
                                                              {UpDirection::PlusZ, "+z"},
                                                              {UpDirection::MinusZ, "-z"}}};

// The unit vector of the direction in the world frame.
Eigen::Vector3d upVector(UpDirection up);

// Throws std::invalid_argument, with a translated message, unless the acceleration is finite and ≥ 0.
void checkGravity(const Gravity& gravity);

// The project file's optional `gravity` member: {"acceleration": m/s², "up": one of kUpDirectionNames}.
QJsonObject gravityJson(const Gravity& gravity);
// Throws FieldError naming the member at fault.
Gravity gravityIn(const JsonField& field);

} // namespace gyre::model
