// Constructors and checks for the two image types (see image.h).
#include "image/image.h"

namespace relight {

namespace {

std::size_t pixel_count(int width, int height) {
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

}  // namespace

Image make_image(int width, int height, Rgb fill) {
  return {width, height, std::vector<Rgb>(pixel_count(width, height), fill)};
}

Image8 make_image8(int width, int height, Rgb8 fill) {
  Image8 image{width, height, {}};
  image.rgb.reserve(3 * pixel_count(width, height));
  for (std::size_t i = 0; i < pixel_count(width, height); ++i) {
    image.rgb.insert(image.rgb.end(), {fill.r, fill.g, fill.b});
  }
  return image;
}

bool is_valid(const Image& image) {
  return image.width > 0 && image.height > 0 &&
         image.pixels.size() == pixel_count(image.width, image.height);
}

bool is_valid(const Image8& image) {
  return image.width > 0 && image.height > 0 &&
         image.rgb.size() == 3 * pixel_count(image.width, image.height);
}

}  // namespace relight
