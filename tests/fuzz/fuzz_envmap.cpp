// Fuzz target: an environment map file (light/environment_map_io.h): OpenEXR when the input starts
// with its magic number, else Radiance RGBE .hdr. Bad input must end in InputError; anything else
// is a defect. Maps of more than 2¹⁴ pixels are refused from their headers: decoding large
// pictures, not finding defects, is what the target would spend its time on (60–1,000 executions a
// second; with 2¹⁸ still 80 % of it in clearing fresh pages for the pictures); the decoders' code
// is the same for every size.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "common/input_error.h"
#include "fuzz_file.h"
#include "light/environment_map_io.h"

namespace {
constexpr std::size_t kMaxPixels = std::size_t{1} << 14;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool exr = size >= 4 && std::memcmp(data, "\x76\x2f\x31\x01", 4) == 0;
  try {
    relight::read_environment_map(relight::fuzz::write_input(data, size, exr ? ".exr" : ".hdr"),
                                  kMaxPixels);
  } catch (const relight::InputError&) {
  }
  return 0;
}
