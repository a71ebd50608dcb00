#pragma once
// The byte streams of the scene wire (scene_wire.h): a Writer that appends little-endian numbers,
// strings and blocks, and a Reader that takes them back, checking every count against the bytes that
// are left before it allocates anything.

#include "io/scene_wire.h"

#include <QByteArray>
#include <QString>
#include <QtEndian>

#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

namespace gyre::io::wire {

class Writer {
public:
    template <class Value>
    void put(Value value)
    {
        static_assert(std::is_arithmetic_v<Value>);
        char bytes[sizeof(Value)];
        qToLittleEndian(value, bytes);
        bytes_.append(bytes, sizeof(Value));
    }

    void count(std::size_t n) { put<quint64>(n); }

    template <class Enum>
    void enumeration(Enum value)
    {
        put(static_cast<std::underlying_type_t<Enum>>(value));
    }

    void string(const QString& text)
    {
        const QByteArray utf8 = text.toUtf8();
        count(static_cast<std::size_t>(utf8.size()));
        bytes_.append(utf8);
    }

    // A count, then the values as one block.
    template <class Value>
    void block(const Value* values, std::size_t n)
    {
        count(n);
        if (n == 0)
            return;
        const qsizetype start = bytes_.size();
        bytes_.resize(start + static_cast<qsizetype>(n * sizeof(Value)));
        qToLittleEndian<Value>(values, static_cast<qsizetype>(n), bytes_.data() + start);
    }

    template <class Value>
    void block(const std::vector<Value>& values)
    {
        block(values.data(), values.size());
    }

    QByteArray take() { return std::move(bytes_); }

private:
    QByteArray bytes_;
};

class Reader {
public:
    explicit Reader(const QByteArray& bytes) : bytes_(bytes) {}

    template <class Value>
    Value get()
    {
        static_assert(std::is_arithmetic_v<Value>);
        require(sizeof(Value), "a number");
        const Value value = qFromLittleEndian<Value>(bytes_.constData() + at_);
        at_ += sizeof(Value);
        return value;
    }

    bool flag()
    {
        const auto value = get<quint8>();
        if (value > 1)
            throw WireError("a flag is " + std::to_string(value) + ", neither 0 nor 1");
        return value == 1;
    }

    // A count of items of at least `itemBytes` each, which the bytes left must be able to hold: a
    // count can never make the reader allocate more than the message's own size.
    std::size_t count(std::size_t itemBytes, const char* what)
    {
        const auto n = get<quint64>();
        if (n > left() / itemBytes)
            throw WireError(std::string(what) + ": a count of " + std::to_string(n) + " does not fit in the " +
                            std::to_string(left()) + " bytes left");
        return static_cast<std::size_t>(n);
    }

    QString string(const char* what)
    {
        const std::size_t n = count(1, what);
        const QString text = QString::fromUtf8(bytes_.constData() + at_, static_cast<qsizetype>(n));
        at_ += n;
        return text;
    }

    template <class Value>
    std::vector<Value> block(const char* what, std::size_t multipleOf = 1)
    {
        const std::size_t n = count(sizeof(Value), what);
        if (n % multipleOf != 0)
            throw WireError(std::string(what) + ": " + std::to_string(n) + " numbers are not whole items of " +
                            std::to_string(multipleOf));
        std::vector<Value> values(n);
        if (n > 0)
            qFromLittleEndian<Value>(bytes_.constData() + at_, static_cast<qsizetype>(n), values.data());
        at_ += n * sizeof(Value);
        return values;
    }

    void requireEnd() const
    {
        if (left() != 0)
            throw WireError(std::to_string(left()) + " bytes after the end of the message");
    }

private:
    std::size_t left() const { return static_cast<std::size_t>(bytes_.size()) - at_; }

    void require(std::size_t n, const char* what) const
    {
        if (n > left())
            throw WireError(std::string("the message ends inside ") + what);
    }

    const QByteArray& bytes_;
    std::size_t at_ = 0;
};

} // namespace gyre::io::wire
