#include "core/number_text.h"

#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <system_error>

namespace gyre {

namespace {

// Enough to quote the text in a message without echoing a whole runaway field.
constexpr std::size_t kQuotedLength = 40;

std::string quoted(std::string_view text)
{
    if (text.size() <= kQuotedLength)
        return "'" + std::string(text) + "'";
    return "'" + std::string(text.substr(0, kQuotedLength)) + "…'";
}

} // namespace

std::string formatNumber(double value)
{
    // 24 characters hold the longest shortest-round-trip double, "-2.2250738585072014e-308".
    std::array<char, 32> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return std::string(buffer.data(), result.ptr);
}

std::string_view trimmed(std::string_view text)
{
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos)
        return {};
    const auto last = text.find_last_not_of(" \t");
    return text.substr(first, last - first + 1);
}

double parseFiniteNumber(std::string_view text)
{
    const std::string_view number = trimmed(text);
    if (number.empty())
        throw std::invalid_argument("empty field; expected a number");
    double value = 0.0;
    const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (error == std::errc::result_out_of_range)
        throw std::invalid_argument(quoted(number) + " is out of the range of a double");
    if (error != std::errc() || end != number.data() + number.size())
        throw std::invalid_argument(quoted(number) + " is not a number");
    // from_chars accepts "nan" and "inf"; a pose file has no use for them.
    if (!std::isfinite(value))
        throw std::invalid_argument(quoted(number) + " is not a finite number");
    return value;
}

} // namespace gyre
