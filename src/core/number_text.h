#pragma once
// Doubles as text, exactly: written in the shortest form that reads back to the same bits, and read
// without locale, so that a file written and read again holds the very same numbers.

#include <string>
#include <string_view>

namespace gyre {

// The shortest decimal text that reads back as exactly `value` (std::to_chars), e.g. "0.1", "-0",
// "1e+300". Non-finite values give "nan", "inf" or "-inf", which parseFiniteNumber rejects.
std::string formatNumber(double value);

// The finite double that `text` spells, ignoring spaces and tabs around it: decimal or scientific
// notation with an optional leading '-' (std::from_chars). Throws std::invalid_argument with a
// message that quotes the text and says what is wrong: empty, not a number, not finite (nan, inf),
// or out of the range of a double.
double parseFiniteNumber(std::string_view text);

// `text` without the spaces and tabs at its ends.
std::string_view trimmed(std::string_view text);

} // namespace gyre
