#include "model/gravity.h"

#include "model/value_checks.h"

namespace gyre::model {

Eigen::Vector3d upVector(UpDirection up)
{
    switch (up) {
    case UpDirection::PlusX:
        return Eigen::Vector3d::UnitX();
    case UpDirection::MinusX:
        return -Eigen::Vector3d::UnitX();
    case UpDirection::PlusY:
        return Eigen::Vector3d::UnitY();
    case UpDirection::MinusY:
        return -Eigen::Vector3d::UnitY();
    case UpDirection::PlusZ:
        break;
    case UpDirection::MinusZ:
        return -Eigen::Vector3d::UnitZ();
    }
    return Eigen::Vector3d::UnitZ();
}

void checkGravity(const Gravity& gravity) { nonNegativeNumber(gravity.acceleration); }

QJsonObject gravityJson(const Gravity& gravity)
{
    return {{"acceleration", gravity.acceleration},
            {"up", QString::fromLatin1(nameOf(kUpDirectionNames, gravity.up))}};
}

Gravity gravityIn(const JsonField& field)
{
    Gravity gravity;
    const JsonField acceleration = field.member("acceleration");
    gravity.acceleration = acceleration.number();
    acceleration.checked([&] { checkGravity(gravity); });
    gravity.up = namedValue(field.member("up"), kUpDirectionNames);
    return gravity;
}

} // namespace gyre::model
