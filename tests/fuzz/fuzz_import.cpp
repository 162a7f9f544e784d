// Fuzz target: `relight import` of an OBJ model (import/mesh_model.h, import/imported_scene.h):
// the mesh read, its glass split into windows, its faces oriented, its room floors found and
// gridded, the scene and its meshes written. Bad input must end in InputError.
#include <cstddef>
#include <cstdint>

#include "common/input_error.h"
#include "fuzz_file.h"
#include "import/imported_scene.h"
#include "import/mesh_model.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto model_file = relight::fuzz::write_input(data, size, ".obj");
    const relight::BuildingModel model = relight::read_mesh_model(model_file, {"*glass*"});
    relight::write_imported_scene(model, {}, model_file, model_file.parent_path() / "scene.json");
  } catch (const relight::InputError&) {
  }
  return 0;
}
