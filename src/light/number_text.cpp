// Strict number reading shared by the IES and EULUMDAT parsers (see number_text.h).
#include "light/number_text.h"

#include <charconv>
#include <cmath>
#include <string>

namespace relight {

std::optional<double> parse_finite_number(std::string_view token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty() || token.front() == '+') return std::nullopt;
  double value = 0;
  const char* const end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<long long> parse_integer(std::string_view token) {
  const auto value = parse_finite_number(token);
  if (!value || std::abs(*value) > 1e9 || std::trunc(*value) != *value) return std::nullopt;
  return static_cast<long long>(*value);
}

std::string printable_token(std::string_view token) {
  std::string out;
  for (const char ch : token.substr(0, 40)) {
    const auto u = static_cast<unsigned char>(ch);
    out += (u >= 0x20 && u < 0x7f) ? ch : '?';
  }
  if (token.size() > 40) out += "...";
  return out;
}

}  // namespace relight
