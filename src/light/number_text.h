// Strict number reading for the photometric text formats (IES LM-63, EULUMDAT): a token
// is a number only if all of it is one, so "12x", "1.2.3", "nan" and "inf" are rejected
// instead of silently truncated, which is what lets the parsers report bad values with
// their line numbers.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace relight {

// A finite decimal number ("12", "-1.5", "+.5e3"); nullopt for anything else.
std::optional<double> parse_finite_number(std::string_view token);

// A finite number with an integral value ("37", "37.0"), within ±1e9.
std::optional<long long> parse_integer(std::string_view token);

// The token for messages: at most 40 characters, non-printable bytes shown as '?'.
std::string printable_token(std::string_view token);

}  // namespace relight
