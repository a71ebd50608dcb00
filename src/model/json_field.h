#pragma once
// A value of a JSON document together with the path that leads to it, as in
// `objects[2].keyframes[5].time`, so that whatever is wrong with it can be said about that field.
// Every accessor checks the value's type (and numbers, that they are finite) and throws FieldError
// otherwise. The reader walks the format's own shape, never the document's, so nesting the format
// does not expect costs nothing.

#include "core/name_table.h"

#include <QByteArray>
#include <QJsonValue>
#include <QString>
#include <QStringList>

#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace gyre::model {

// A field that is not what the format allows; what() is `field: what is wrong`.
class FieldError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class JsonField {
public:
    JsonField(QJsonValue value, QString path);

    const QString& path() const { return path_; }
    bool isNull() const { return value_.isNull(); }

    // The member `key` of an object, which must be there.
    JsonField member(const char* key) const;
    // Whether this object has the member `key`.
    bool has(const char* key) const;
    // The elements of an array.
    std::vector<JsonField> elements() const;

    double number() const;
    // A whole number in [min, max].
    qint64 integer(qint64 min, qint64 max) const;
    bool boolean() const;
    QString string() const;
    // Base64 text, decoded.
    QByteArray base64() const;
    // Arrays of exactly N numbers.
    Eigen::Vector2d vector2() const;
    Eigen::Vector3d vector3() const;
    Eigen::Vector4d vector4() const;

    // check(), or a FieldError carrying its std::invalid_argument's message.
    template <class Check>
    auto checked(Check check) const -> decltype(check())
    {
        try {
            return check();
        } catch (const std::invalid_argument& problem) {
            fail(QString::fromUtf8(problem.what()));
        }
    }

    // Throws a FieldError naming this field: `path: message`.
    [[noreturn]] void fail(const QString& message) const;

private:
    // The elements of an array of exactly `count` numbers.
    template <int Count>
    Eigen::Matrix<double, Count, 1> numbers() const;
    void requireType(QJsonValue::Type type) const;

    QJsonValue value_;
    QString path_;
};

// `unknown value "name"; expected one of known`, translated.
QString unknownValueMessage(const QString& name, const QString& known);

// The value `field` names, one of `names`' strings; else a FieldError listing them.
template <class Enum, std::size_t N>
Enum namedValue(const JsonField& field, const NameTable<Enum, N>& names)
{
    const QString name = field.string();
    if (const std::optional<Enum> value = valueNamed(names, name.toStdString()))
        return *value;
    QStringList known;
    for (const auto& entry : names)
        known.append(QString::fromLatin1(entry.second));
    field.fail(unknownValueMessage(name, known.join(QStringLiteral(", "))));
}

} // namespace gyre::model
