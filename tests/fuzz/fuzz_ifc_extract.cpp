// Fuzz target: the IFC reader's output as `relight import` takes it (import/ifc_model.h
// parse_ifc_extract), then made a scene: missing fields, wrong types, indices out of range and
// empty models must end in InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/input_error.h"
#include "fuzz_file.h"
#include "import/ifc_model.h"
#include "import/imported_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto folder = relight::fuzz::write_input(data, 0, ".ifc").parent_path();
    const relight::BuildingModel model = relight::parse_ifc_extract(
        std::string(reinterpret_cast<const char*>(data), size), folder / "model.ifc");
    relight::write_imported_scene(model, {}, folder / "model.ifc", folder / "scene.json");
  } catch (const relight::InputError&) {
  }
  return 0;
}
