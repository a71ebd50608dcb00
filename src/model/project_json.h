#pragma once
// The JSON members of the project file's header (docs/file-format.md) that are values rather than blocks:
// written here, and for the rotation mode read here too. project_file.cpp puts them together.

#include "model/json_field.h"
#include "model/scene.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>

#include <initializer_list>
#include <optional>
#include <utility>
#include <vector>

namespace gyre::model {

QJsonArray numbersJson(std::initializer_list<double> values);
QJsonArray vectorJson(const Eigen::Vector3d& v);
QJsonArray vectorJson(const Eigen::Vector2d& v);

template <class Item, class ToJson>
QJsonArray arrayJson(const std::vector<Item>& items, ToJson toJson)
{
    QJsonArray array;
    for (const Item& item : items)
        array.append(toJson(item));
    return array;
}

QJsonObject subdivisionJson(const SubdivisionSettings& settings);
QJsonObject sketchJson(const SketchState& sketch, const QJsonObject& fittedCurve, const QJsonObject& keysBeforeFit);

// `{"kind": "quaternion" | "euler", "order": "xyz", "frame": "intrinsic" | "extrinsic"}`; read back, checked
// (throws FieldError naming the member).
QJsonObject rotationModeJson(const RotationMode& mode);
RotationMode rotationModeIn(const JsonField& field);

} // namespace gyre::model
