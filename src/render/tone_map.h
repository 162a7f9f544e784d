// Tone mapping: physical luminance (cd/m²) → 8-bit sRGB, the way a camera would.
//
// Exposure follows the physically based camera of Lagarde & de Rousiers, "Moving
// Frostbite to Physically Based Rendering 3.0" (SIGGRAPH 2014 course notes, section on
// the physically based camera and exposure), as also used by Filament ("Physically
// Based Rendering in Filament", section "Physically based camera"). With
// EV100 = log2(N²/t · 100/S) and saturation-based sensitivity (ISO 12232, lens
// transmittance q = 0.65) the luminance that saturates the sensor is
//     L_max = 78 / (q · S) · N²/t = 1.2 · 2^EV100  cd/m²,
// and a pixel's linear display value is x = L / L_max. Higher EV100 means a darker image.
//
// Automatic exposure puts the log-average luminance L̄ = exp(mean ln Y) (Reinhard et al.,
// "Photographic Tone Reproduction for Digital Images", SIGGRAPH 2002, Eq. 1) at the key
// a = 0.18 (their "middle grey", Eq. 2): EV100 = log2(L̄ / (1.2 · a)). A reflected-light
// meter (calibration K = 12.5, Frostbite's computeEV100FromAvgLuminance) would read
// log2(1.2 · a · 100 / 12.5) = 0.79 EV higher; 0.18 was chosen because it matches where
// cameras' output curves put middle grey, so automatic images look like photographs.
// Pixels with Y ≤ 0 or non-finite are left out of the average (no surface, or no light).
//
// Highlights roll off instead of clipping: x is kept unchanged below the shoulder
// s = 0.6 and above it becomes s + (1 − s) · u / (1 + u), u = (x − s) / (1 − s) (a
// Reinhard x/(1+x) curve fitted to the line with matching value and slope at s). So
// L_max maps to 0.8, 4 L_max to 0.958, 16 L_max to 0.99, and only infinity to 1.0.
// It acts per channel, so very bright coloured light desaturates towards white as on
// film.
//
// Finally the sRGB OETF (IEC 61966-2-1): 12.92 x for x ≤ 0.0031308, else
// 1.055 x^(1/2.4) − 0.055; rounded to 8 bits. Negative or NaN values display as black.
#pragma once

#include <cstdint>
#include <optional>

#include "image/image.h"

namespace relight {

inline constexpr double kAutoExposureKey = 0.18;
inline constexpr double kShoulderStart = 0.6;

// L_max = 1.2 · 2^EV100 (cd/m²): the luminance that maps to display value 1.0 before
// the highlight roll-off.
double saturation_luminance(double ev100);
// 1 / L_max: multiply luminance by this to get the linear display value.
double exposure_scale(double ev100);

// exp(mean ln Y) over pixels with finite Y > 0; empty when there are none.
std::optional<double> log_average_luminance(const Image& hdr);
// EV100 that maps the log-average luminance to kAutoExposureKey (0 for a black image).
double auto_exposure_ev100(const Image& hdr);

double highlight_rolloff(double x);
// round(255 · clamp(v, 0, 1)); NaN → 0.
std::uint8_t quantize_8bit(double display);

struct ToneMapped {
  Image8 image;
  double ev100 = 0;  // the exposure actually used (the automatic one when none was given)
};

// Exposure (ev100, automatic when empty), roll-off, sRGB OETF and 8-bit quantisation.
ToneMapped tone_map(const Image& hdr, std::optional<double> ev100);

}  // namespace relight
