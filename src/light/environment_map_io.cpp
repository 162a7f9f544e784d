// Environment map files: OpenEXR via read_exr, Radiance .hdr via stbi_loadf (the compiled stb
// in Debian's libstb.so); see environment_map_io.h.
#include "light/environment_map_io.h"

#include <stb_image.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <string>

#include "common/input_error.h"
#include "image/image_exr.h"

namespace relight {

namespace fs = std::filesystem;

namespace {

struct StbFloatFree {
  void operator()(float* pixels) const { stbi_image_free(pixels); }
};

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

EquirectMap read_hdr(const fs::path& path) {
  if (!stbi_is_hdr(path.c_str())) fail_input(path.string(), "not a Radiance HDR (RGBE) file");
  int width = 0, height = 0, channels = 0;
  const std::unique_ptr<float, StbFloatFree> pixels(
      stbi_loadf(path.c_str(), &width, &height, &channels, 3));
  if (!pixels) {
    fail_input(path.string(), std::string("cannot decode Radiance HDR: ") + stbi_failure_reason());
  }
  EquirectMap map;
  map.width = width;
  map.height = height;
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  map.texels.resize(count);
  const float* p = pixels.get();
  for (std::size_t k = 0; k < count; ++k) map.texels[k] = {p[3 * k], p[3 * k + 1], p[3 * k + 2]};
  return map;
}

EquirectMap read_exr_map(const fs::path& path) {
  Image image = read_exr(path);
  EquirectMap map;
  map.width = image.width;
  map.height = image.height;
  map.texels = std::move(image.pixels);
  return map;
}

}  // namespace

EquirectMap read_environment_map(const fs::path& path) {
  const std::string ext = lower_extension(path);
  std::error_code error;
  if (!fs::is_regular_file(path, error)) fail_input(path.string(), "no such file");
  EquirectMap map;
  if (ext == ".exr") {
    map = read_exr_map(path);
  } else if (ext == ".hdr") {
    map = read_hdr(path);
  } else {
    fail_input(path.string(),
               "unsupported environment map type \"" + ext + "\" (expected .exr or .hdr)");
  }
  if (map.width < 2 || map.height < 1 || map.width != 2 * map.height) {
    fail_input(path.string(), "expected an equirectangular panorama twice as wide as tall, got " +
                                  std::to_string(map.width) + "×" + std::to_string(map.height));
  }
  for (std::size_t k = 0; k < map.texels.size(); ++k) {
    Rgb& t = map.texels[k];
    if (!std::isfinite(t.r) || !std::isfinite(t.g) || !std::isfinite(t.b)) {
      fail_input(path.string(), "texel (" + std::to_string(k % map.width) + ", " +
                                    std::to_string(k / map.width) + ") is not finite");
    }
    t = {std::max(t.r, 0.0), std::max(t.g, 0.0), std::max(t.b, 0.0)};
  }
  return map;
}

Environment load_environment(const EnvironmentSpec& spec) {
  if (spec.type != EnvironmentType::kMap) return make_environment(spec);
  return make_environment(spec,
                          std::make_shared<const EquirectMap>(read_environment_map(spec.file)));
}

}  // namespace relight
