// Fuzz target: a photograph as `relight capture` reads it (image/photo.h): JPEG, PNG or TIFF
// through OpenCV's imgcodecs, and its EXIF exposure through libexif. The input is written with the
// extension its first bytes suggest (the decoders go by content). Bad input must end in InputError;
// anything else is a defect. Pictures declaring more than 2¹⁶ pixels are refused from their
// headers, as environment maps are in fuzz_envmap: decoding large pictures under AddressSanitizer
// (a 204-byte TIFF had OpenCV allocate 879 MB) held the target at 1,300 executions a second; the
// decoders' code is the same for every size.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "common/input_error.h"
#include "fuzz_file.h"
#include "image/photo.h"

namespace {
constexpr double kMaxPixels = 65536;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string extension = ".jpg";
  if (size >= 4 && std::memcmp(data, "\x89PNG", 4) == 0) extension = ".png";
  if (size >= 4 && (std::memcmp(data, "II*", 4) == 0 || std::memcmp(data, "MM\0*", 4) == 0)) {
    extension = ".tif";
  }
  const auto file = relight::fuzz::write_input(data, size, extension);
  relight::read_photo_exposure(file);
  try {
    relight::read_photo(file, kMaxPixels);
  } catch (const relight::InputError&) {
  }
  return 0;
}
