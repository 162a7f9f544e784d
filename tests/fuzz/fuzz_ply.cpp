// Fuzz target: a PLY mesh, ASCII or binary (scene/ply_import.h). Bad input must end in InputError;
// anything else is a defect.
#include <cstddef>
#include <cstdint>

#include "common/input_error.h"
#include "fuzz_file.h"
#include "scene/ply_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    relight::import_ply(relight::fuzz::write_input(data, size, ".ply"));
  } catch (const relight::InputError&) {
  }
  return 0;
}
