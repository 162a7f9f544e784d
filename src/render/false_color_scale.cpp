// False-colour value scale: range, linear/log choice, ticks (rules in false_color_scale.h).
#include "render/false_color_scale.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

#include "common/input_error.h"

namespace relight {

namespace {

constexpr double kLogRatio = 20;  // auto: logarithmic above this MAX / MIN
constexpr int kMaxTicks = 8;      // at most 8 labels…
constexpr int kMinLogTicks = 4;   // …and a log set needs at least 4 to be used
constexpr double kLowPercentile = 0.01, kHighPercentile = 0.99;
constexpr double kTolerance = 1e-9;  // relative slack for values on a range end

[[noreturn]] void fail_range(const std::string& reason) {
  fail_input("--range", reason);
}

// 'text' (built by appending: GCC 12 warns falsely on "'" + std::string, PR 105329).
std::string quoted(std::string_view text) {
  std::string out(1, '\'');
  out += text;
  out += '\'';
  return out;
}

// Value at fraction p of the sorted values (nearest rank).
double percentile(std::vector<double>& values, double p) {
  const auto rank =
      static_cast<std::ptrdiff_t>(std::lround(p * static_cast<double>(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + rank, values.end());
  return values[static_cast<std::size_t>(rank)];
}

double decade(int exponent) {
  return std::pow(10.0, exponent);
}

// Intervals of width step needed to cover [lo, hi] from multiples of step.
long long intervals(double lo, double hi, double step) {
  return static_cast<long long>(std::ceil(hi / step - kTolerance)) -
         static_cast<long long>(std::floor(lo / step + kTolerance));
}

// Smallest step in {1, 2, 2.5, 5} × 10^k covering [lo, hi] in at most kMaxTicks - 1
// intervals between multiples of the step.
double linear_step(double lo, double hi) {
  const double span = hi - lo;
  int exponent = static_cast<int>(std::floor(std::log10(span / (kMaxTicks - 1)))) - 1;
  for (;; ++exponent) {
    for (const double mantissa : {1.0, 2.0, 2.5, 5.0}) {
      const double step = mantissa * decade(exponent);
      if (intervals(lo, hi, step) <= kMaxTicks - 1) return step;
    }
  }
}

std::vector<double> linear_ticks(double lo, double hi) {
  const double step = linear_step(lo, hi);
  std::vector<double> ticks;
  const auto first = static_cast<long long>(std::ceil(lo / step - kTolerance));
  const auto last = static_cast<long long>(std::floor(hi / step + kTolerance));
  for (long long k = first; k <= last; ++k) ticks.push_back(k == 0 ? 0.0 : k * step);
  return ticks;
}

bool in_range(double value, double lo, double hi) {
  return value >= lo * (1 - kTolerance) && value <= hi * (1 + kTolerance);
}

// Ticks m × 10^e in [lo, hi] for each mantissa m and each exponent e divisible by
// every_decades.
std::vector<double> log_ticks(double lo, double hi, std::initializer_list<double> mantissas,
                              int every_decades) {
  std::vector<double> ticks;
  const int first = static_cast<int>(std::floor(std::log10(lo))) - 1;
  const int last = static_cast<int>(std::ceil(std::log10(hi))) + 1;
  for (int e = first; e <= last; ++e) {
    if (e % every_decades != 0) continue;
    for (const double m : mantissas) {
      const double value = m * decade(e);
      if (in_range(value, lo, hi)) ticks.push_back(value);
    }
  }
  return ticks;
}

double parse_bound(std::string_view text, std::string_view full) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    fail_range(quoted(text) + " in " + quoted(full) + " is not a number");
  }
  if (value < 0) fail_range("values must be >= 0, got " + std::string(text));
  return value;
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  return text;
}

}  // namespace

std::string_view unit_label(Quantity quantity) {
  return quantity == Quantity::kIlluminance ? "lx" : "cd/m2";
}

RangeArgument parse_range(std::string_view text) {
  const std::size_t colon = text.find(':');
  if (colon == std::string_view::npos || text.find(':', colon + 1) != std::string_view::npos) {
    fail_range("expected MIN:MAX, got " + quoted(text));
  }
  const std::string_view min_text = trim(text.substr(0, colon));
  const std::string_view max_text = trim(text.substr(colon + 1));
  if (min_text.empty() && max_text.empty()) fail_range("give MIN, MAX or both in MIN:MAX");
  RangeArgument range;
  if (!min_text.empty()) range.min = parse_bound(min_text, text);
  if (!max_text.empty()) range.max = parse_bound(max_text, text);
  if (range.min && range.max && !(*range.min < *range.max)) {
    fail_range("MIN must be below MAX, got " + quoted(text));
  }
  return range;
}

double nice_floor_125(double value) {
  const int e = static_cast<int>(std::floor(std::log10(value)));
  const double mantissa = value / decade(e);
  for (const double m : {5.0, 2.0, 1.0}) {
    if (mantissa >= m * (1 - kTolerance)) return m * decade(e);
  }
  return decade(e);  // mantissa just below 1 through rounding
}

double nice_ceil_125(double value) {
  const int e = static_cast<int>(std::floor(std::log10(value)));
  const double mantissa = value / decade(e);
  for (const double m : {1.0, 2.0, 5.0}) {
    if (mantissa <= m * (1 + kTolerance)) return m * decade(e);
  }
  return decade(e + 1);
}

FalseColorScale resolve_scale(const Image& hdr, const FalseColor& request) {
  for (const std::optional<double>& bound : {request.min, request.max}) {
    if (bound && !(std::isfinite(*bound) && *bound >= 0))
      fail_range("values must be finite and >= 0");
  }
  if (request.min && request.max && !(*request.min < *request.max)) {
    fail_range("MIN must be below MAX");
  }
  std::vector<double> lit;
  for (const Rgb& p : hdr.pixels) {
    const double y = luminance(p);
    if (std::isfinite(y) && y > 0) lit.push_back(y);
  }
  const double data_lo = lit.empty() ? 0 : percentile(lit, kLowPercentile);
  const double data_hi = lit.empty() ? 0 : percentile(lit, kHighPercentile);

  double lo = request.min.value_or(data_lo);
  double hi = request.max.value_or(data_hi);
  if (!(hi > lo)) {  // degenerate: one value, nothing lit, or data outside a given bound
    if (!request.max) {
      hi = request.min ? (lo > 0 ? 10 * lo : 1) : (hi > 0 ? 2 * hi : 1);
      if (!request.min) lo = 0;
    } else {
      lo = 0;
    }
  }
  bool logarithmic = request.scale == ScaleKind::kLogarithmic ||
                     (request.scale == ScaleKind::kAuto && lo > 0 && hi / lo > kLogRatio);
  if (logarithmic) {
    if (lo <= 0) {
      if (request.min) fail_range("a logarithmic scale needs MIN > 0");
      lo = hi / 100;
    }
    if (!request.min) lo = nice_floor_125(lo);
    if (!request.max) hi = nice_ceil_125(hi);
  } else {
    const double step = linear_step(lo, hi);
    if (!request.min) lo = std::floor(lo / step + kTolerance) * step;
    if (!request.max) hi = std::ceil(hi / step - kTolerance) * step;
  }
  return {lo, hi, logarithmic};
}

double scale_position(const FalseColorScale& scale, double value) {
  if (!std::isfinite(value)) return std::numeric_limits<double>::quiet_NaN();
  double t = 0;
  if (scale.logarithmic) {
    t = value > 0 ? std::log(value / scale.min) / std::log(scale.max / scale.min) : 0;
  } else {
    t = (value - scale.min) / (scale.max - scale.min);
  }
  return std::clamp(t, 0.0, 1.0);
}

std::vector<double> scale_ticks(const FalseColorScale& scale) {
  if (!scale.logarithmic) return linear_ticks(scale.min, scale.max);
  std::vector<double> best = log_ticks(scale.min, scale.max, {1, 2, 5}, 1);
  if (static_cast<int>(best.size()) > kMaxTicks) best = log_ticks(scale.min, scale.max, {1, 3}, 1);
  for (const int every_decades : {1, 2, 3, 5, 10, 20, 50, 100}) {
    if (static_cast<int>(best.size()) <= kMaxTicks) break;
    best = log_ticks(scale.min, scale.max, {1}, every_decades);
  }
  if (static_cast<int>(best.size()) < kMinLogTicks) return linear_ticks(scale.min, scale.max);
  return best;
}

std::string format_tick(double value) {
  if (value == 0) return "0";
  char text[32];
  const double magnitude = std::abs(value);
  if (magnitude >= 1e-3 && magnitude < 1e6) {
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
  }
  const int e = static_cast<int>(std::floor(std::log10(magnitude)));
  std::snprintf(text, sizeof text, "%.3ge%d", value / decade(e), e);
  return text;
}

}  // namespace relight
