// OpenEXR keeps the physical values (cd/m², lux) that PNG cannot: renders are written
// unchanged, and environment maps (including Blender's DWAB-compressed studio lights) are read
// back. Uses the OpenEXR 3 C++ API from Debian (tinyexr cannot read DWAB).
#pragma once

#include <cstddef>
#include <filesystem>

#include "image/image.h"

namespace relight {

// Largest finite half-float value; files holding anything larger are written in float.
inline constexpr double kHalfMax = 65504.0;

// Writes R, G, B channels, ZIP-compressed (lossless), atomically. Channels are 16-bit
// half floats (relative precision 2^-11 ≈ 4.9e-4) unless a finite value exceeds kHalfMax
// in magnitude — direct sunlight is ~1e5 lx, a luminaire's lamp ~1e7 cd/m² — in which case
// they are 32-bit floats so that no physical value becomes infinite. NaN stays NaN.
// Throws InputError "PATH: reason" when the file cannot be written. kFloat writes 32-bit floats
// whatever the values (a captured environment map).
enum class ExrChannels { kAuto, kFloat };
void write_exr(const std::filesystem::path& path, const Image& image,
               ExrChannels channels = ExrChannels::kAuto);

// Reads the first part of any scanline or tiled OpenEXR file whose channels include R, G
// or B (missing ones read as 0; alpha and other channels are ignored), or a luminance
// (Y) / luminance-chroma (Y, RY, BY) file, in any compression including DWAA/DWAB. The
// data window becomes the image; the display window is ignored. Throws InputError
// "PATH: reason" when the file is missing, not OpenEXR, damaged or has no colour channel,
// or when its data window holds more than `max_pixels` (refused from the header, before
// decoding).
inline constexpr std::size_t kExrMaxPixels = std::size_t{1} << 30;
Image read_exr(const std::filesystem::path& path, std::size_t max_pixels = kExrMaxPixels);

}  // namespace relight
