#include "model/json_field.h"

#include "core/number_text.h"

#include <QJsonArray>
#include <QJsonObject>

#include <cmath>
#include <utility>

namespace gyre::model {

namespace {

// Enough to recognise a wrong string in a message without echoing a whole runaway field.
constexpr qsizetype kQuotedLength = 40;

std::string typeName(const QJsonValue& value)
{
    switch (value.type()) {
    case QJsonValue::Null:
        return "null";
    case QJsonValue::Bool:
        return "a boolean";
    case QJsonValue::Double:
        return "a number";
    case QJsonValue::String: {
        const QString text = value.toString();
        return "the string \"" +
               (text.size() > kQuotedLength ? text.left(kQuotedLength) + QStringLiteral("…") : text).toStdString() +
               "\"";
    }
    case QJsonValue::Array:
        return "an array";
    case QJsonValue::Object:
        return "an object";
    case QJsonValue::Undefined:
        break;
    }
    return "nothing";
}

std::string expectedName(QJsonValue::Type type)
{
    switch (type) {
    case QJsonValue::Bool:
        return "true or false";
    case QJsonValue::Double:
        return "a number";
    case QJsonValue::String:
        return "a string";
    case QJsonValue::Array:
        return "an array";
    case QJsonValue::Object:
        return "an object";
    default:
        return "null";
    }
}

} // namespace

JsonField::JsonField(QJsonValue value, QString path)
    : value_(std::move(value))
    , path_(std::move(path))
{
}

void JsonField::fail(std::string_view message) const
{
    const QString where = path_.isEmpty() ? QStringLiteral("the top level") : path_;
    throw FieldError(where.toStdString() + ": " + std::string(message));
}

void JsonField::requireType(QJsonValue::Type type) const
{
    if (value_.type() != type)
        fail("expected " + expectedName(type) + ", found " + typeName(value_));
}

JsonField JsonField::member(const char* key) const
{
    requireType(QJsonValue::Object);
    const QString name = QString::fromLatin1(key);
    const QString path = path_.isEmpty() ? name : path_ + QLatin1Char('.') + name;
    const QJsonObject object = value_.toObject();
    const auto found = object.constFind(name);
    if (found == object.constEnd())
        JsonField(QJsonValue(), path).fail("missing");
    return JsonField(*found, path);
}

bool JsonField::has(const char* key) const
{
    requireType(QJsonValue::Object);
    return value_.toObject().contains(QString::fromLatin1(key));
}

std::vector<JsonField> JsonField::elements() const
{
    requireType(QJsonValue::Array);
    const QJsonArray array = value_.toArray();
    std::vector<JsonField> fields;
    fields.reserve(static_cast<std::size_t>(array.size()));
    for (qsizetype i = 0; i < array.size(); ++i)
        fields.emplace_back(array[i], path_ + QLatin1Char('[') + QString::number(i) + QLatin1Char(']'));
    return fields;
}

double JsonField::number() const
{
    requireType(QJsonValue::Double);
    // Qt's parser refuses literals beyond a double's range, such as 1e999, but a scene being saved
    // is checked through this reader too, and it may hold one.
    const double value = value_.toDouble();
    if (!std::isfinite(value))
        fail(formatNumber(value) + " is not a finite number");
    return value;
}

qint64 JsonField::integer(qint64 min, qint64 max) const
{
    const double value = number();
    if (value != std::trunc(value))
        fail(formatNumber(value) + " is not a whole number");
    if (value < static_cast<double>(min) || value > static_cast<double>(max))
        fail(formatNumber(value) + " is outside " + std::to_string(min) + " to " + std::to_string(max));
    return value_.toInteger(static_cast<qint64>(value));
}

bool JsonField::boolean() const
{
    requireType(QJsonValue::Bool);
    return value_.toBool();
}

QString JsonField::string() const
{
    requireType(QJsonValue::String);
    return value_.toString();
}

QByteArray JsonField::base64() const
{
    const auto decoded = QByteArray::fromBase64Encoding(string().toLatin1(), QByteArray::AbortOnBase64DecodingErrors);
    if (!decoded)
        fail("not valid base64");
    return *decoded;
}

template <int Count>
Eigen::Matrix<double, Count, 1> JsonField::numbers() const
{
    const std::vector<JsonField> fields = elements();
    if (fields.size() != Count)
        fail("expected " + std::to_string(Count) + " numbers, found " + std::to_string(fields.size()));
    Eigen::Matrix<double, Count, 1> values;
    for (int i = 0; i < Count; ++i)
        values[i] = fields[static_cast<std::size_t>(i)].number();
    return values;
}

Eigen::Vector2d JsonField::vector2() const { return numbers<2>(); }
Eigen::Vector3d JsonField::vector3() const { return numbers<3>(); }
Eigen::Vector4d JsonField::vector4() const { return numbers<4>(); }

} // namespace gyre::model
