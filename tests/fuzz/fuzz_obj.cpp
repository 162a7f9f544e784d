// Fuzz target: a Wavefront OBJ mesh (scene/obj_import.h, through tinyobjloader).
// Bad input must end in InputError; anything else is a defect.
#include <cstddef>
#include <cstdint>

#include "common/input_error.h"
#include "fuzz_file.h"
#include "scene/obj_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    relight::import_obj(relight::fuzz::write_input(data, size, ".obj"));
  } catch (const relight::InputError&) {
  }
  return 0;
}
