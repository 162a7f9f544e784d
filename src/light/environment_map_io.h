// Reading equirectangular environment maps ("type": "map"): OpenEXR through read_exr (any
// compression, including the DWAB files of Debian's blender-data) and Radiance RGBE .hdr through
// stb_image's stbi_loadf (Debian libstb). The image becomes an EquirectMap (light/environment.h) in
// the math/equirect.h orientation, values unchanged (cd/m² per channel before the spec's scale).
#pragma once

#include <filesystem>

#include "image/image_exr.h"
#include "light/environment.h"
#include "scene/environment_spec.h"

namespace relight {

// Reads a .exr or .hdr file (chosen by extension, case-insensitive). The image must be twice
// as wide as tall (a latitude–longitude panorama). Negative values (lossy DWA compression
// leaves a few small ones) read as 0. Throws InputError "FILE: reason" when the file is
// missing, of another type, damaged, not 2:1, or holds a non-finite value, or when it declares
// more than `max_pixels` (refused before decoding; a smaller bound keeps fuzz_envmap fast).
EquirectMap read_environment_map(const std::filesystem::path& path,
                                 std::size_t max_pixels = kExrMaxPixels);

// make_environment with the map file of a map spec read by read_environment_map.
Environment load_environment(const EnvironmentSpec& spec);

}  // namespace relight
