// PNG through stb (see image_png.h). stbi_write_png itself does not check fwrite, so the
// PNG is encoded to memory and written by write_bytes_atomically, which does.
#include "image/image_png.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/input_error.h"
#include "image/image_bytes.h"

namespace relight {

namespace fs = std::filesystem;

namespace {

void append_bytes(void* context, void* data, int size) {
  auto* bytes = static_cast<std::vector<std::uint8_t>*>(context);
  const auto* begin = static_cast<const std::uint8_t*>(data);
  bytes->insert(bytes->end(), begin, begin + size);
}

struct StbFree {
  void operator()(unsigned char* pixels) const { stbi_image_free(pixels); }
};

}  // namespace

void write_png(const fs::path& path, const Image8& image) {
  if (!is_valid(image)) throw std::invalid_argument("write_png: byte count != 3 × width × height");
  std::vector<std::uint8_t> bytes;
  if (stbi_write_png_to_func(append_bytes, &bytes, image.width, image.height, 3, image.rgb.data(),
                             3 * image.width) == 0) {
    fail_input(path.string(), "cannot encode PNG");
  }
  write_bytes_atomically(path, bytes);
}

Image8 read_png(const fs::path& path) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) fail_input(path.string(), "no such file");
  int width = 0, height = 0, channels = 0;
  const std::unique_ptr<unsigned char, StbFree> pixels(
      stbi_load(path.c_str(), &width, &height, &channels, 3));
  if (!pixels) fail_input(path.string(), std::string("cannot decode: ") + stbi_failure_reason());
  const std::size_t count = 3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  return {width, height, std::vector<std::uint8_t>(pixels.get(), pixels.get() + count)};
}

}  // namespace relight
