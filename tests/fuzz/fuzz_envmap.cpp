// Fuzz target (issue 16): an environment map file (light/environment_map_io.h): OpenEXR when the
// input starts with its magic number, else Radiance RGBE .hdr. Bad input must end in
// InputError; anything else is a defect.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "common/input_error.h"
#include "fuzz_file.h"
#include "light/environment_map_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool exr = size >= 4 && std::memcmp(data, "\x76\x2f\x31\x01", 4) == 0;
  try {
    relight::read_environment_map(relight::fuzz::write_input(data, size, exr ? ".exr" : ".hdr"));
  } catch (const relight::InputError&) {
  }
  return 0;
}
