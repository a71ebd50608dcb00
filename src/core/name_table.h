#pragma once
// The names by which an enumeration is written in files and on command lines, both ways.

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <utility>

namespace gyre {

template <class Enum, std::size_t N>
using NameTable = std::array<std::pair<Enum, std::string_view>, N>;

template <class Enum, std::size_t N>
std::optional<Enum> valueNamed(const NameTable<Enum, N>& table, std::string_view name)
{
    for (const auto& [value, text] : table)
        if (text == name)
            return value;
    return std::nullopt;
}

template <class Enum, std::size_t N>
std::string_view nameOf(const NameTable<Enum, N>& table, Enum value)
{
    for (const auto& [candidate, text] : table)
        if (candidate == value)
            return text;
    return {};
}

} // namespace gyre
