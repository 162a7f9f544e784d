// Fuzz target: a glTF 2.0 mesh (scene/gltf_import.h, through tinygltf), as .glb when the input
// starts with the binary container's magic, else as .gltf text. Bad input must end in InputError;
// anything else is a defect.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "common/input_error.h"
#include "fuzz_file.h"
#include "scene/gltf_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  try {
    relight::import_gltf(relight::fuzz::write_input(data, size, binary ? ".glb" : ".gltf"));
  } catch (const relight::InputError&) {
  }
  return 0;
}
