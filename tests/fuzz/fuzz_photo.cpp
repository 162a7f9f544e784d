// Fuzz target (issue 16): a photograph as `relight capture` reads it (image/photo.h): JPEG, PNG
// or TIFF through OpenCV's imgcodecs, and its EXIF exposure through libexif. The input is
// written with the extension its first bytes suggest (the decoders go by content). Bad input
// must end in InputError; anything else is a defect.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "common/input_error.h"
#include "fuzz_file.h"
#include "image/photo.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string extension = ".jpg";
  if (size >= 4 && std::memcmp(data, "\x89PNG", 4) == 0) extension = ".png";
  if (size >= 4 && (std::memcmp(data, "II*", 4) == 0 || std::memcmp(data, "MM\0*", 4) == 0)) {
    extension = ".tif";
  }
  const auto file = relight::fuzz::write_input(data, size, extension);
  relight::read_photo_exposure(file);
  try {
    relight::read_photo(file);
  } catch (const relight::InputError&) {
  }
  return 0;
}
