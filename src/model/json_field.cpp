#include "model/json_field.h"

#include "model/input_error.h"

#include <QJsonArray>
#include <QJsonObject>

#include <cmath>
#include <utility>

namespace gyre::model {

namespace {

// Enough to recognise a wrong string in a message without echoing a whole runaway field.
constexpr qsizetype kQuotedLength = 40;

QString typeName(const QJsonValue& value)
{
    switch (value.type()) {
    case QJsonValue::Null:
        return QStringLiteral("null");
    case QJsonValue::Bool:
        return FileError::tr("a boolean");
    case QJsonValue::Double:
        return FileError::tr("a number");
    case QJsonValue::String: {
        const QString text = value.toString();
        return FileError::tr("the string \"%1\"")
            .arg(text.size() > kQuotedLength ? text.left(kQuotedLength) + QStringLiteral("…") : text);
    }
    case QJsonValue::Array:
        return FileError::tr("an array");
    case QJsonValue::Object:
        return FileError::tr("an object");
    case QJsonValue::Undefined:
        break;
    }
    return FileError::tr("nothing");
}

QString expectedName(QJsonValue::Type type)
{
    switch (type) {
    case QJsonValue::Bool:
        return FileError::tr("true or false");
    case QJsonValue::Double:
        return FileError::tr("a number");
    case QJsonValue::String:
        return FileError::tr("a string");
    case QJsonValue::Array:
        return FileError::tr("an array");
    case QJsonValue::Object:
        return FileError::tr("an object");
    default:
        return QStringLiteral("null");
    }
}

} // namespace

JsonField::JsonField(QJsonValue value, QString path)
    : value_(std::move(value))
    , path_(std::move(path))
{
}

void JsonField::fail(const QString& message) const
{
    const QString where = path_.isEmpty() ? FileError::tr("the top level") : path_;
    throw FieldError((where + QStringLiteral(": ") + message).toStdString());
}

void JsonField::requireType(QJsonValue::Type type) const
{
    if (value_.type() != type)
        fail(FileError::tr("expected %1, found %2").arg(expectedName(type), typeName(value_)));
}

JsonField JsonField::member(const char* key) const
{
    requireType(QJsonValue::Object);
    const QString name = QString::fromLatin1(key);
    const QString path = path_.isEmpty() ? name : path_ + QLatin1Char('.') + name;
    const QJsonObject object = value_.toObject();
    const auto found = object.constFind(name);
    if (found == object.constEnd())
        JsonField(QJsonValue(), path).fail(FileError::tr("missing"));
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
        fail(FileError::tr("%1 is not a finite number").arg(FileError::number(value)));
    return value;
}

qint64 JsonField::integer(qint64 min, qint64 max) const
{
    const double value = number();
    if (value != std::trunc(value))
        fail(FileError::tr("%1 is not a whole number").arg(FileError::number(value)));
    if (value < static_cast<double>(min) || value > static_cast<double>(max))
        fail(FileError::tr("%1 is outside %2 to %3").arg(FileError::number(value)).arg(min).arg(max));
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
        fail(FileError::tr("not valid base64"));
    return *decoded;
}

template <int Count>
Eigen::Matrix<double, Count, 1> JsonField::numbers() const
{
    const std::vector<JsonField> fields = elements();
    if (fields.size() != Count)
        fail(FileError::tr("expected %1 numbers, found %2").arg(Count).arg(fields.size()));
    Eigen::Matrix<double, Count, 1> values;
    for (int i = 0; i < Count; ++i)
        values[i] = fields[static_cast<std::size_t>(i)].number();
    return values;
}

Eigen::Vector2d JsonField::vector2() const { return numbers<2>(); }
Eigen::Vector3d JsonField::vector3() const { return numbers<3>(); }
Eigen::Vector4d JsonField::vector4() const { return numbers<4>(); }

QString unknownValueMessage(const QString& name, const QString& known)
{
    return FileError::tr("unknown value \"%1\"; expected one of %2").arg(name, known);
}

} // namespace gyre::model
