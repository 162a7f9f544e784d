// PNG is the display format: 8-bit sRGB, what tone mapping and false colour produce.
// Encoding and decoding use stb_image_write / stb_image from Debian's libstb.
#pragma once

#include <filesystem>

#include "image/image.h"

namespace relight {

// Writes an 8-bit RGB PNG atomically. Throws InputError "PATH: reason" on failure.
void write_png(const std::filesystem::path& path, const Image8& image);

// Reads a PNG (or any 8-bit format stb_image decodes) as RGB. Throws InputError
// "PATH: reason" when the file is missing or cannot be decoded.
Image8 read_png(const std::filesystem::path& path);

}  // namespace relight
