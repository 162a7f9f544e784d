// False colour: each pixel's photometric quantity (Y of linear Rec.709: illuminance in lux or
// luminance in cd/m²) shown as a colour from a fixed ramp, with a legend that reads back in
// physical units. This is how lighting designers check levels against targets (e.g. 500 lx on a
// desk), which a tone-mapped picture cannot show.
//
// The ramp is this project's own: seven control points, equally spaced in scale position
// t ∈ [0, 1], from deep blue through blue, cyan, green, yellow and red to white: the
// cold-to-hot order that lighting software has made familiar, ending in white so the
// brightest areas read as the hottest and never as "no surface" grey. Colours
// between control points are linear interpolations of the 8-bit sRGB-encoded values.
// Values below MIN take the first colour, above MAX the last. Pixels with no surface
// (non-finite Y; the renderer writes NaN there) are drawn in neutral grey, which the
// ramp never produces.
#pragma once

#include <array>

#include "image/image.h"
#include "render/false_color_scale.h"

namespace relight {

inline constexpr std::array<Rgb8, 7> kFalseColorRamp = {{
    {24, 32, 128},    // deep blue (MIN)
    {0, 96, 230},     // blue
    {0, 200, 230},    // cyan
    {40, 190, 60},    // green (geometric mean of MIN and MAX on a log scale)
    {240, 225, 30},   // yellow
    {235, 60, 25},    // red
    {255, 255, 255},  // white (MAX)
}};
inline constexpr Rgb8 kNoSurfaceColor = {128, 128, 128};

// Ramp colour at scale position t (clamped to [0, 1]); kNoSurfaceColor for NaN.
Rgb8 ramp_color(double t);

// The false-colour picture alone, same size as hdr.
Image8 false_color_pixels(const Image& hdr, const FalseColorScale& scale);

struct FalseColorImage {
  Image8 image;           // picture with the legend appended on the right
  FalseColorScale scale;  // the range and scale actually used
};

// resolve_scale + false_color_pixels + append_legend (false_color_legend.h).
FalseColorImage render_false_color(const Image& hdr, const FalseColor& request);

}  // namespace relight
