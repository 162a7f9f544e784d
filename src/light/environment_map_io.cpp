// Environment map files: OpenEXR via read_exr, Radiance .hdr via stbi_loadf (the compiled stb
// in Debian's libstb.so); see environment_map_io.h.
#include "light/environment_map_io.h"

#include <stb_image.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

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

// Walks the run-length scanlines from `start`: each is 2, 2, W (big-endian 16 bits), then per
// component runs until W values: a byte c > 128 repeats the next byte c − 128 times, else c
// literal bytes follow. Debian's stb (2022) loops forever on a run of length 0 and reads zeros
// past the end of the file, so a run of 0, one longer than what is left of the scanline, or
// the end of the file inside the runs is refused (make fuzz found a 93-byte file hanging
// relight; EnvironmentMapIo.ARunOfZero...). A scanline without the 2, 2 mark ends the walk: stb
// reads the rest as flat pixels, whose size was checked.
void check_hdr_runs(const fs::path& path, std::ifstream& in, std::streamoff start, int width,
                    int height) {
  in.clear();
  in.seekg(start);
  std::vector<unsigned char> data{std::istreambuf_iterator<char>(in), {}};
  std::size_t at = 0;
  const auto fail_at = [&](int row, const std::string& what) {
    fail_input(path.string(),
               "bad run-length data in scanline " + std::to_string(row) + ": " + what);
  };
  for (int row = 0; row < height; ++row) {
    if (at + 4 > data.size()) fail_at(row, "the file ends");
    if (data[at] != 2 || data[at + 1] != 2 || (data[at + 2] & 0x80) != 0) return;
    if ((data[at + 2] << 8 | data[at + 3]) != width) fail_at(row, "its length is not the width");
    at += 4;
    for (int component = 0; component < 4; ++component) {
      for (int left = width; left > 0;) {
        if (at >= data.size()) fail_at(row, "the file ends");
        const int c = data[at++];
        const int count = c > 128 ? c - 128 : c;
        if (count == 0 || count > left) {
          fail_at(row, "a run of " + std::to_string(count) + " where " + std::to_string(left) +
                           " values are left");
        }
        at += c > 128 ? 1 : static_cast<std::size_t>(count);
        if (at > data.size()) fail_at(row, "the file ends");
        left -= count;
      }
    }
  }
}

// A Radiance RGBE file (Ward, "Real Pixels", Graphics Gems II, 1991) is header lines up to an
// empty one, the resolution "-Y H +X W", then H scanlines: flat, 4 bytes a pixel, or — when
// 8 ≤ W < 32768 and a scanline starts with the bytes 2, 2 — run-length encoded: 4 bytes, then
// each of the 4 components in runs of at most 127 bytes, each run at least 2 bytes. stb decodes
// the bytes a flat file lacks as zeros: a truncated file would read as black, and a file of a
// few bytes declaring 2²⁴ × 2²³ pixels would ask for gigabytes. So the pixel data must hold at
// least those minima, and declare at most `max_pixels`; refused before decoding otherwise. Pinned
// by EnvironmentMapIo.*Truncated*.
void check_hdr_holds_its_pixels(const fs::path& path, std::size_t max_pixels) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  while (std::getline(in, line) && !line.empty()) {
  }
  if (!std::getline(in, line)) return;  // no resolution line: stb says what is wrong
  int height = 0, width = 0;
  if (std::sscanf(line.c_str(), "-Y %d +X %d", &height, &width) != 2 || height <= 0 || width <= 0) {
    return;
  }
  const std::streamoff start = in.tellg();
  char first[2] = {};
  in.read(first, 2);
  const bool run_length =
      width >= 8 && width < 32768 && in.gcount() == 2 && first[0] == 2 && first[1] == 2;
  const auto w = static_cast<std::uintmax_t>(width), h = static_cast<std::uintmax_t>(height);
  const std::uintmax_t needed =
      run_length ? h * (4 + std::uintmax_t{8} * ((w + 126) / 127)) : h * w * 4;
  std::error_code error;
  const std::uintmax_t size = fs::file_size(path, error);
  if (error || start < 0) return;
  const std::uintmax_t held = size - static_cast<std::uintmax_t>(start);
  if (held < needed) {
    fail_input(path.string(), "declares " + std::to_string(width) + " × " + std::to_string(height) +
                                  " pixels but holds " + std::to_string(held) +
                                  " bytes of them (at least " + std::to_string(needed) +
                                  " needed): truncated");
  }
  if (w * h > max_pixels) {
    fail_input(path.string(), "declares " + std::to_string(width) + " × " + std::to_string(height) +
                                  " pixels, more than " + std::to_string(max_pixels));
  }
  if (run_length) check_hdr_runs(path, in, start, width, height);
}

EquirectMap read_hdr(const fs::path& path, std::size_t max_pixels) {
  if (!stbi_is_hdr(path.c_str())) fail_input(path.string(), "not a Radiance HDR (RGBE) file");
  check_hdr_holds_its_pixels(path, max_pixels);
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

EquirectMap read_exr_map(const fs::path& path, std::size_t max_pixels) {
  Image image = read_exr(path, max_pixels);
  EquirectMap map;
  map.width = image.width;
  map.height = image.height;
  map.texels = std::move(image.pixels);
  return map;
}

}  // namespace

EquirectMap read_environment_map(const fs::path& path, std::size_t max_pixels) {
  const std::string ext = lower_extension(path);
  std::error_code error;
  if (!fs::is_regular_file(path, error)) fail_input(path.string(), "no such file");
  EquirectMap map;
  if (ext == ".exr") {
    map = read_exr_map(path, max_pixels);
  } else if (ext == ".hdr") {
    map = read_hdr(path, max_pixels);
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
