#include "model/project_json.h"

#include "model/input_error.h"

namespace gyre::model {

namespace {

QJsonObject strokeJson(const DirectionStroke& stroke)
{
    return {{"points", arrayJson(stroke.points, [](const Eigen::Vector3d& point) { return vectorJson(point); })},
            {"times", arrayJson(stroke.times, [](double time) { return QJsonValue(time); })}};
}

QJsonValue windowJson(const std::optional<std::pair<double, double>>& window)
{
    return window ? QJsonValue(numbersJson({window->first, window->second})) : QJsonValue(QJsonValue::Null);
}

} // namespace

QJsonArray numbersJson(std::initializer_list<double> values)
{
    QJsonArray array;
    for (double value : values)
        array.append(value);
    return array;
}

QJsonArray vectorJson(const Eigen::Vector3d& v) { return numbersJson({v.x(), v.y(), v.z()}); }
QJsonArray vectorJson(const Eigen::Vector2d& v) { return numbersJson({v.x(), v.y()}); }

QJsonObject subdivisionJson(const SubdivisionSettings& settings)
{
    return {{"scheme", QString::fromLatin1(subdivisionSchemeName(settings.scheme))},
            {"levels", settings.levels},
            {"cyclic", settings.cyclic},
            {"decoupled", settings.decoupled}};
}

QJsonObject sketchJson(const SketchState& sketch, const QJsonObject& fittedCurve, const QJsonObject& keysBeforeFit)
{
    return {
        {"directionStrokes", arrayJson(sketch.directionStrokes, strokeJson)},
        {"magnitude", arrayJson(sketch.magnitude,
                                [](const MagnitudePoint& point) {
                                    return QJsonObject{{"time", point.time}, {"magnitude", point.magnitude}};
                                })},
        {"pattern", arrayJson(sketch.pattern, [](const Eigen::Vector2d& point) { return vectorJson(point); })},
        {"patternRepeat", sketch.patternRepeat},
        {"window", windowJson(sketch.window)},
        {"alpha", sketch.alpha},
        {"beta", sketch.beta},
        {"relativeDelta", sketch.delta},
        {"fittedCurve", fittedCurve},
        {"keysBeforeFit", keysBeforeFit},
    };
}

QJsonObject rotationModeJson(const RotationMode& mode)
{
    return {{"kind", mode.isEuler() ? QStringLiteral("euler") : QStringLiteral("quaternion")},
            {"order", QString::fromStdString(mode.convention.order())},
            {"frame", mode.convention.frame == AngleFrame::Intrinsic ? QStringLiteral("intrinsic")
                                                                     : QStringLiteral("extrinsic")}};
}

RotationMode rotationModeIn(const JsonField& field)
{
    RotationMode mode;
    const JsonField kind = field.member("kind");
    const QString kindName = kind.string();
    if (kindName != QLatin1String("quaternion") && kindName != QLatin1String("euler"))
        kind.fail(FileError::tr("'%1' is neither quaternion nor euler").arg(kindName));
    mode.kind = kindName == QLatin1String("euler") ? RotationMode::Kind::Euler : RotationMode::Kind::Quaternion;
    const JsonField frame = field.member("frame");
    const QString frameName = frame.string();
    if (frameName != QLatin1String("intrinsic") && frameName != QLatin1String("extrinsic"))
        frame.fail(FileError::tr("'%1' is neither intrinsic nor extrinsic").arg(frameName));
    const JsonField order = field.member("order");
    const std::optional<EulerConvention> convention = EulerConvention::parse(
        order.string().toStdString(), frameName == QLatin1String("intrinsic") ? AngleFrame::Intrinsic : AngleFrame::Extrinsic);
    if (!convention)
        order.fail(FileError::tr("'%1' is not an order of three axes").arg(order.string()));
    mode.convention = *convention;
    return mode;
}

} // namespace gyre::model
