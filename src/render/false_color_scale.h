// The value scale of a false-colour image: which range of lux or cd/m² the colour ramp
// spans, linear or logarithmic, and where the legend's tick labels go. Lighting designers
// read false colour as a measurement, so the ends are round numbers and the labels carry
// the unit.
//
// Rules (each part that the user leaves out is automatic):
//  * Data range: the 1st and 99th percentiles of Y over pixels with finite Y > 0, so a
//    few lamp pixels or dark corners do not squash the scale.
//  * Logarithmic when asked, or (automatic) when MIN > 0 and MAX / MIN > 20; linear
//    otherwise. Illuminance in a room spans decades near windows and luminaires, which a
//    linear scale would show as one colour.
//  * Rounding of automatic ends: logarithmic → MIN down / MAX up to the next 1, 2, 5 × 10^k;
//    linear → to multiples of the tick step (below).
//  * Ticks, logarithmic: the densest of {1, 2, 5} × 10^k, {1, 3} × 10^k, 10^k, every 2nd,
//    3rd, 5th, 10th… decade that gives at most 8 ticks in [MIN, MAX]; if that gives fewer
//    than 4 (a range under about a decade) the linear rule is used instead.
//  * Ticks, linear: multiples of the smallest step in {1, 2, 2.5, 5} × 10^k that gives at
//    most 8 ticks (7 intervals) in [MIN, MAX].
//  * Degenerate data (one value v, or nothing lit): [0, 2v], or [0, 1].
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "image/image.h"

namespace relight {

enum class Quantity { kIlluminance, kLuminance };
enum class ScaleKind { kAuto, kLinear, kLogarithmic };

// What the user asked for (CLI: --false-color QUANTITY, --range MIN:MAX, --scale).
struct FalseColor {
  Quantity quantity = Quantity::kIlluminance;
  std::optional<double> min, max;  // empty: automatic
  ScaleKind scale = ScaleKind::kAuto;
};

// The scale actually drawn.
struct FalseColorScale {
  double min = 0, max = 1;
  bool logarithmic = false;
};

// "lx" or "cd/m2" (ASCII: the legend font has no superscripts).
std::string_view unit_label(Quantity quantity);

// Parses the CLI's --range argument "MIN:MAX"; either side may be empty ("MIN:" or
// ":MAX") to leave it automatic. Values must be finite and ≥ 0, and MIN < MAX. Throws
// InputError "--range: reason".
struct RangeArgument {
  std::optional<double> min, max;
};
RangeArgument parse_range(std::string_view text);

// Applies the rules above to the pixels' Y. Throws InputError "--range: reason" when a
// given range is unusable (MIN ≥ MAX, or MIN ≤ 0 on a logarithmic scale).
FalseColorScale resolve_scale(const Image& hdr, const FalseColor& request);

// Position of value on the scale, clamped to [0, 1] (0 at MIN, 1 at MAX, log or linear);
// NaN for a non-finite value.
double scale_position(const FalseColorScale& scale, double value);

// Tick values in [MIN, MAX], ascending.
std::vector<double> scale_ticks(const FalseColorScale& scale);

// Short label for a tick value: "0", "0.5", "250", "20000", "1.5e6".
std::string format_tick(double value);

// Nice numbers: the largest 1, 2, 5 × 10^k ≤ value and the smallest ≥ value (value > 0).
double nice_floor_125(double value);
double nice_ceil_125(double value);

}  // namespace relight
