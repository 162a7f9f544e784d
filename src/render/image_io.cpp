// Output image dispatch on the file extension (see image_io.h).
#include "render/image_io.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>

#include "common/input_error.h"
#include "image/image_exr.h"
#include "image/image_png.h"
#include "render/tone_map.h"

namespace relight {

ImageFormat image_format(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".exr") return ImageFormat::kExr;
  if (extension == ".png") return ImageFormat::kPng;
  fail_input(path.string(), "unknown image format '" + path.extension().string() +
                                "' (use .exr for physical values or .png for display)");
}

DisplayReport write_image(const std::filesystem::path& path, const Image& hdr,
                          const DisplayOptions& options) {
  const ImageFormat format = image_format(path);
  if (!is_valid(hdr)) throw std::invalid_argument("write_image: pixel count != width × height");
  if (format == ImageFormat::kExr) {
    write_exr(path, hdr);
    return {format, std::nullopt, std::nullopt};
  }
  if (options.false_color) {
    const FalseColorImage result = render_false_color(hdr, *options.false_color);
    write_png(path, result.image);
    return {format, std::nullopt, result.scale};
  }
  const ToneMapped result = tone_map(hdr, options.exposure_ev);
  write_png(path, result.image);
  return {format, result.ev100, std::nullopt};
}

}  // namespace relight
